import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { faceHalfedges, loopHalfedges, vertexOutgoingHalfedges } from '../../src/core/circulators.js';
import {
  bevelEdge,
  bevelVertex,
  canBevelEdge,
  canBevelVertex,
  canCollapseFace,
  canExtrudeFace,
  collapseFace,
  extrudeFace,
  splitEdge,
} from '../../src/core/edits/index.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { cube, disk, grid, tetrahedron, torus } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { euler, expectRefused, fixtures } from './fixtures.js';
import { bipyramid, checkedEdit, counts, degrees, meshOf, triangleQuadPillow } from './helpers.js';

const SEED = 2718;

/** Number of triangles across the sides of face f. */
function trianglesBeside(mesh: HalfedgeMesh, f: number): number {
  return [...faceHalfedges(mesh, f)].filter((h) => mesh.heFace[h ^ 1] !== -1 && mesh.loopLength(h ^ 1) === 3).length;
}

/**
 * A square f0 = (0, 1, 2, 3) closed by a roof of triangles over its two halves, which meet along
 * an edge 0–2: two corners of f0 joined by an edge that is not a side.
 */
const squareUnderARidge = () =>
  soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.3, 0.7, 1, 0.7, 0.3, 1],
    [
      [0, 1, 2, 3],
      [0, 3, 4],
      [3, 2, 4],
      [2, 0, 4],
      [2, 1, 5],
      [1, 0, 5],
      [0, 2, 5],
    ],
  );

/** The same square, under a roof whose middle is a quad f5 through corners 0 and 2 (but no edge 0–2). */
const squareUnderAQuad = () =>
  soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.1, 0.9, 1, 0.9, 0.1, 1],
    [
      [0, 1, 2, 3],
      [0, 3, 4],
      [3, 2, 4],
      [2, 1, 5],
      [1, 0, 5],
      [0, 4, 2, 5],
    ],
  );

describe('collapseFace', () => {
  it("shrinks a face of the assignment's 4 × 4 grid to its centre: the four quads beside it become triangles", () => {
    const mesh = meshOf(grid(4, 4, true));
    const { vertex, removed } = checkedEdit(mesh, (m) => collapseFace(m, 10)); // the cell from (0.5, 0.5) to (0.75, 0.75)
    expect(counts(mesh)).toEqual([22, 36, 15]);
    expect(degrees(mesh)).toEqual({ 3: 4, 4: 11 });
    expect(euler(mesh)).toBe(1);
    expect(mesh.position(vertex)).toEqual([0.625, 0.625, 0]);
    expect([removed.vertices?.length, removed.edges?.length, removed.faces?.length]).toEqual([3, 4, 1]);
  });

  it('turns a cube into a square pyramid', () => {
    const mesh = meshOf(cube());
    const { vertex } = checkedEdit(mesh, (m) => collapseFace(m, 1));
    expect(counts(mesh)).toEqual([5, 8, 5]);
    expect(degrees(mesh)).toEqual({ 3: 4, 4: 1 });
    expect(mesh.position(vertex)).toEqual([0.5, 0.5, 1]);
    expect(mesh.vertexDegree(vertex)).toBe(4);
  });

  it('collapses a triangle of a disk: the triangles beside it go, each leaving one edge of its two', () => {
    const mesh = meshOf(disk(2));
    const f = [...mesh.faces()].find((g) => !mesh.isBoundaryFace(g) && trianglesBeside(mesh, g) === 3)!;
    checkedEdit(mesh, (m) => collapseFace(m, f));
    expect(counts(mesh)).toEqual([17, 36, 20]);
    expect(euler(mesh)).toBe(1);
  });

  it('collapses a corner cell of a grid onto the boundary: the hole loses both sides it had there', () => {
    const mesh = meshOf(grid(3, 3, true));
    const { vertex } = checkedEdit(mesh, (m) => collapseFace(m, 0));
    expect(counts(mesh)).toEqual([13, 20, 8]);
    expect(mesh.isBoundaryVertex(vertex)).toBe(true);
    expect([...loopHalfedges(mesh, mesh.vHalfedge[vertex])]).toHaveLength(10);
    mesh.position(vertex).forEach((x, c) => expect(x).toBeCloseTo([1 / 6, 1 / 6, 0][c], 15));
  });

  it('collapses a face beside a split edge: the face across loses both halves of it', () => {
    const mesh = meshOf(cube());
    const e = [...faceHalfedges(mesh, 1)][0] >> 1;
    const neighbour = mesh.heFace[2 * e] === 1 ? mesh.heFace[2 * e + 1] : mesh.heFace[2 * e];
    const uv = mesh.halfedgeAttributes.add('uv', 'float64', 1);
    for (let h = 0; h < mesh.halfedgeSlots; h++) uv.data[h] = h;
    splitEdge(mesh, e);
    const twins = [...faceHalfedges(mesh, neighbour)].filter((h) => mesh.heFace[h ^ 1] === 1);
    const kept = mesh.heNext[twins.find((h) => !twins.includes(mesh.heNext[h]))!];
    const average = [kept, ...twins].reduce((sum, h) => sum + mesh.halfedgeAttributes.get('uv')!.data[h], 0) / 3;
    expect(twins).toHaveLength(2);
    checkedEdit(mesh, (m) => collapseFace(m, 1));
    expect(counts(mesh)).toEqual([5, 8, 5]);
    expect(degrees(mesh)).toEqual({ 3: 4, 4: 1 });
    expect(mesh.faceDegree(neighbour)).toBe(3);
    expect(mesh.halfedgeAttributes.get('uv')!.data[kept]).toBeCloseTo(average, 12);
  });

  it('keeps a torus a torus', () => {
    const mesh = meshOf(torus(5, 4));
    checkedEdit(mesh, (m) => collapseFace(m, 6));
    expect(counts(mesh)).toEqual([17, 36, 19]);
    expect(meshStats(mesh).genus).toBe(1);
  });

  it('averages the corners: vertex attributes at the new vertex, and the two corners of a face that loses a side', () => {
    const mesh = meshOf(cube());
    const heat = mesh.vertexAttributes.add('heat', 'float64', 1);
    heat.data.set([0, 1, 2, 3, 4, 5, 6, 7]);
    const uv = mesh.halfedgeAttributes.add('uv', 'float64', 1);
    for (let h = 0; h < mesh.halfedgeSlots; h++) uv.data[h] = h;
    // the corners each face beside f1 has at f1's corners, before
    const expected = [...faceHalfedges(mesh, 1)].map((h) => (h ^ 1) + mesh.heNext[h ^ 1]);
    const { vertex } = checkedEdit(mesh, (m) => collapseFace(m, 1));
    expect(mesh.vertexAttributes.get('heat')!.data[vertex]).toBe((4 + 5 + 6 + 7) / 4);
    const data = mesh.halfedgeAttributes.get('uv')!.data;
    const atM = [...vertexOutgoingHalfedges(mesh, vertex)].map((h) => data[h] * 2).sort((a, b) => a - b);
    expect(atM).toEqual(expected.sort((a, b) => a - b));
  });

  it('refuses a tetrahedron face: the triangles around it meet at one vertex', () => {
    const mesh = meshOf(tetrahedron());
    for (const f of mesh.faces()) {
      const apex = [0, 1, 2, 3].find((v) => ![...faceHalfedges(mesh, f)].some((h) => mesh.heVertex[h] === v));
      const why = `the triangles on every side of f${f} meet at v${apex}: collapsing f${f} would leave only an edge to v${apex}, with no face`;
      expect(canCollapseFace(mesh, f)).toBe(why);
      expectRefused(mesh, () => collapseFace(mesh, f), `collapseFace: ${why}`);
    }
  });

  it('refuses a face of a triangular bipyramid: two triangles on the same three corners would be left', () => {
    const mesh = meshOf(bipyramid());
    expect(canCollapseFace(mesh, 0)).toMatch(
      /^collapsing f0 would flatten what is left around it into two triangles \(f\d, f\d\) on the same three corners \(v[24], v[24] and the new vertex\)$/,
    );
    expectRefused(mesh, () => collapseFace(mesh, 0), `collapseFace: ${canCollapseFace(mesh, 0)}`);
  });

  it('refuses a face on its own', () => {
    const mesh = meshOf(grid(1, 1, true));
    const why = 'f0 is a part of the mesh on its own (no edge leads away from its corners): collapsing it would leave a lone vertex';
    expect(canCollapseFace(mesh, 0)).toBe(why);
    expectRefused(mesh, () => collapseFace(mesh, 0), `collapseFace: ${why}`);
  });

  it('refuses a face with a neighbour along two sides that would be left with fewer than 3', () => {
    const mesh = meshOf(triangleQuadPillow());
    expect(canCollapseFace(mesh, 2)).toBe('f0 borders f2 along 2 sides and has 3: collapsing f2 would leave it 1');
    expectRefused(mesh, () => collapseFace(mesh, 2), `collapseFace: ${canCollapseFace(mesh, 2)}`);
  });

  it('refuses a face two of whose corners are joined by another edge: it would become a loop', () => {
    const mesh = meshOf(squareUnderARidge());
    expect(canCollapseFace(mesh, 0)).toMatch(/^v[02] and v[02], corners of f0, are also joined by e\d+: collapsing f0 would turn e\d+ into a loop$/);
    expectRefused(mesh, () => collapseFace(mesh, 0), `collapseFace: ${canCollapseFace(mesh, 0)}`);
  });

  it('refuses a face that another face touches at two corners: it would pass through the new vertex twice', () => {
    const mesh = meshOf(squareUnderAQuad());
    expect(canCollapseFace(mesh, 0)).toMatch(/^f5 meets f0 at two places \(at v[02] and v[02]\): collapsing f0 would make f5 pass through the new vertex twice$/);
    expectRefused(mesh, () => collapseFace(mesh, 0), `collapseFace: ${canCollapseFace(mesh, 0)}`);
  });

  it('refuses a face whose corners share a neighbour not across a triangle (the link condition)', () => {
    const mesh = meshOf(grid(3, 1, true));
    // the middle cell of a strip of three: its corners are not joined to the same vertex, but its
    // top and bottom sides are both on the boundary
    const pinch = canCollapseFace(mesh, 1);
    expect(pinch).toMatch(/^the boundary meets f1 at two places \(at v\d and v\d\): collapsing f1 would pinch the surface at the new vertex$/);
    expectRefused(mesh, () => collapseFace(mesh, 1), `collapseFace: ${pinch}`);
    // a ring of three quads: both inner corners of a cell are joined to the third inner vertex
    const ring = meshOf(
      soupFromArrays(
        [1, 0, 0, 2, 0, 0, -0.5, 0.87, 0, -1, 1.73, 0, -0.5, -0.87, 0, -1, -1.73, 0],
        [
          [0, 1, 3, 2],
          [2, 3, 5, 4],
          [4, 5, 1, 0],
        ],
      ),
    );
    const why = canCollapseFace(ring, 0);
    expect(why).toMatch(/^v[45] is joined to v\d and v\d, corners of f0, but not across a triangle beside f0: collapsing f0 would join it to the new vertex twice \(the link condition fails\)$/);
    expectRefused(ring, () => collapseFace(ring, 0), `collapseFace: ${why}`);
  });

  it('refuses a face that is not there', () => {
    const mesh = meshOf(cube());
    expect(canCollapseFace(mesh, 6)).toBe('f6 is not a face of this mesh (ids run 0…5)');
    mesh.deleteFace(2);
    expect(canCollapseFace(mesh, 2)).toBe('f2 is deleted');
  });

  it(`collapses random faces of closed, open and several-part meshes, keeping them valid and χ unchanged (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.nat(fixtures.length - 1), fc.array(fc.nat(), { minLength: 1, maxLength: 8 }), (which, picks) => {
        const mesh = meshOf(fixtures[which][1]());
        const chi = euler(mesh);
        for (const pick of picks) {
          const f = pick % mesh.faceSlots;
          const why = canCollapseFace(mesh, f);
          if (why) {
            expectRefused(mesh, () => collapseFace(mesh, f), `collapseFace: ${why}`);
            continue;
          }
          const [before, k, t] = [counts(mesh), mesh.faceDegree(f), trianglesBeside(mesh, f)];
          checkedEdit(mesh, (m) => collapseFace(m, f));
          expect(counts(mesh)).toEqual([before[0] - (k - 1), before[1] - k - t, before[2] - 1 - t]);
        }
        expect(euler(mesh)).toBe(chi);
      }),
      { seed: SEED, numRuns: 80 },
    );
  });

  it(`keeps meshes valid through random runs of extrusions, bevels and face collapses, χ unchanged (seed ${SEED})`, () => {
    const step = fc.record({ op: fc.nat(3), pick: fc.nat(), amount: fc.oneof(fc.constant(0), fc.double({ min: 0, max: 1, noNaN: true })) });
    fc.assert(
      fc.property(fc.nat(fixtures.length - 1), fc.array(step, { minLength: 1, maxLength: 12 }), (which, steps) => {
        const mesh = meshOf(fixtures[which][1]());
        const chi = euler(mesh);
        for (const { op, pick, amount } of steps) {
          if (op === 0) {
            const f = pick % mesh.faceSlots;
            if (!canExtrudeFace(mesh, f, { inset: amount })) checkedEdit(mesh, (m) => extrudeFace(m, f, { inset: amount }));
          } else if (op === 1) {
            const v = pick % mesh.vertexSlots;
            if (!canBevelVertex(mesh, v, amount)) checkedEdit(mesh, (m) => bevelVertex(m, v, { amount }));
          } else if (op === 2) {
            const e = pick % mesh.edgeSlots;
            if (!canBevelEdge(mesh, e, amount)) checkedEdit(mesh, (m) => bevelEdge(m, e, { amount }));
          } else {
            const f = pick % mesh.faceSlots;
            const why = canCollapseFace(mesh, f);
            if (why) expectRefused(mesh, () => collapseFace(mesh, f), `collapseFace: ${why}`);
            else checkedEdit(mesh, (m) => collapseFace(m, f));
          }
        }
        expect(euler(mesh)).toBe(chi);
      }),
      { seed: SEED, numRuns: 80 },
    );
  });
});
