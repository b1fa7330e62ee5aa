import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { faceHalfedges, loopHalfedges } from '../../src/core/circulators.js';
import { bevelEdge, bevelVertex, canBevelEdge, canBevelVertex, splitEdge } from '../../src/core/edits/index.js';
import { faceArea, signedVolume } from '../../src/core/geometry.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { cube, torus } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { euler, expectRefused, fixtures } from './fixtures.js';
import { checkedEdit, counts, degrees, edgeBetween, meshOf, square } from './helpers.js';

const SEED = 5150;

const cornerPositions = (mesh: HalfedgeMesh, f: number) => [...faceHalfedges(mesh, f)].map((h) => mesh.position(mesh.heVertex[h]));
const sorted = (points: number[][]) => [...points].sort((p, q) => p[0] - q[0] || p[1] - q[1] || p[2] - q[2]);

/** Two triangles on the same three corners: every vertex has 2 edges. */
const twoTrianglePillow = () =>
  soupFromArrays(
    [0, 0, 0, 1, 0, 0, 0, 1, 0],
    [
      [0, 1, 2],
      [0, 2, 1],
    ],
  );

describe('bevelVertex', () => {
  it('replaces a cube corner by a triangle of zero area by default', () => {
    const mesh = meshOf(cube());
    const { face, created } = checkedEdit(mesh, (m) => bevelVertex(m, 6));
    expect(counts(mesh)).toEqual([10, 15, 7]);
    expect(euler(mesh)).toBe(2);
    expect(degrees(mesh)).toEqual({ 3: 1, 4: 3, 5: 3 });
    expect(mesh.faceDegree(face)).toBe(3);
    expect(created.faces).toEqual(Int32Array.of(face));
    expect(cornerPositions(mesh, face)).toEqual([
      [1, 1, 1],
      [1, 1, 1],
      [1, 1, 1],
    ]);
    expect(faceArea(mesh, face)).toBe(0);
  });

  it('cuts a cube corner off half way along its edges', () => {
    const mesh = meshOf(cube());
    const { face } = checkedEdit(mesh, (m) => bevelVertex(m, 6, { amount: 0.5 }));
    expect(sorted(cornerPositions(mesh, face))).toEqual([
      [0.5, 1, 1],
      [1, 0.5, 1],
      [1, 1, 0.5],
    ]);
    expect(signedVolume(mesh)).toBeCloseTo(1 - 1 / 48, 14);
  });

  it('bevels a boundary vertex: the new face borders the hole along one side', () => {
    // the assignment's boundary case: a square of two triangles, a corner of degree 3
    const mesh = meshOf(square());
    const { face } = checkedEdit(mesh, (m) => bevelVertex(m, 0, { amount: 0.25 }));
    expect(counts(mesh)).toEqual([6, 8, 3]);
    expect(degrees(mesh)).toEqual({ 3: 1, 4: 2 });
    expect(mesh.isBoundaryFace(face)).toBe(true);
    expect([...loopHalfedges(mesh, mesh.vHalfedge[1])]).toHaveLength(5);
    expect(sorted(cornerPositions(mesh, face))).toEqual([
      [0, 0.25, 0],
      [0.25, 0, 0],
      [0.25, 0.25, 0],
    ]);
  });

  it('keeps each face around its old corner value at both of its new corners', () => {
    const mesh = meshOf(cube());
    const uv = mesh.halfedgeAttributes.add('uv', 'float64', 2);
    for (let h = 0; h < mesh.halfedgeSlots; h++) uv.data.set([h, -h], 2 * h);
    const { face } = checkedEdit(mesh, (m) => bevelVertex(m, 6));
    const data = mesh.halfedgeAttributes.get('uv')!.data;
    const value = (h: number) => [data[2 * h], data[2 * h + 1]];
    for (const g of faceHalfedges(mesh, face)) {
      const spoke = mesh.heNext[g ^ 1]; // the wedge face's old corner, now at g's origin
      expect(value(g ^ 1)).toEqual(value(spoke));
      expect(value(g)).toEqual(value(spoke));
      expect(spoke).toBeLessThan(24); // an old halfedge, with its old value
    }
  });

  it('refuses a vertex of degree 2 and leaves the mesh as it was', () => {
    const mesh = meshOf(square());
    const why = 'v1 has only 2 edges: the face replacing it would have 2 sides, and a face needs at least 3';
    expect(canBevelVertex(mesh, 1)).toBe(why);
    expectRefused(mesh, () => bevelVertex(mesh, 1), `bevelVertex: ${why}`);
    expect(canBevelVertex(meshOf(twoTrianglePillow()), 0)).toBe(why.replaceAll('v1', 'v0'));
  });

  it('refuses a missing vertex and an amount outside 0 … 1', () => {
    const mesh = meshOf(cube());
    expect(canBevelVertex(mesh, 8)).toBe('v8 is not a vertex of this mesh (ids run 0…7)');
    expect(canBevelVertex(mesh, 2, 1.5)).toBe('amount = 1.5 is not between 0 and 1: it is the fraction of the way the new corners move from v2 along its edges');
    expectRefused(mesh, () => bevelVertex(mesh, 2, { amount: -1 }), 'bevelVertex: amount = -1 is not between 0 and 1: it is the fraction of the way the new corners move from v2 along its edges');
    mesh.deleteVertex(3);
    expect(canBevelVertex(mesh, 3)).toBe('v3 is deleted');
  });
});

describe('bevelEdge', () => {
  it('replaces a cube edge by a quad of zero area by default', () => {
    const mesh = meshOf(cube());
    const e = edgeBetween(mesh, 5, 6);
    const { face } = checkedEdit(mesh, (m) => bevelEdge(m, e));
    expect(counts(mesh)).toEqual([10, 15, 7]);
    expect(euler(mesh)).toBe(2);
    expect(degrees(mesh)).toEqual({ 4: 5, 5: 2 });
    expect(mesh.faceDegree(face)).toBe(4);
    expect(faceArea(mesh, face)).toBe(0);
    // e stays, as the new face's side toward the face on its 2e side
    expect(mesh.heFace[2 * e + 1]).toBe(face);
  });

  it('chamfers a cube edge half way along the edges at its ends', () => {
    const mesh = meshOf(cube());
    const { face } = checkedEdit(mesh, (m) => bevelEdge(m, edgeBetween(m, 5, 6), { amount: 0.5 }));
    expect(sorted(cornerPositions(mesh, face))).toEqual([
      [0.5, 0, 1],
      [0.5, 1, 1],
      [1, 0, 0.5],
      [1, 1, 0.5],
    ]);
    expect(signedVolume(mesh)).toBeCloseTo(0.875, 14);
  });

  it("bevels the assignment's square diagonal, whose ends are on the boundary: the new face borders the hole twice", () => {
    const mesh = meshOf(square());
    const { face } = checkedEdit(mesh, (m) => bevelEdge(m, edgeBetween(m, 0, 2), { amount: 0.25 }));
    expect(counts(mesh)).toEqual([6, 8, 3]);
    expect(degrees(mesh)).toEqual({ 3: 2, 4: 1 });
    const sides = [...faceHalfedges(mesh, face)];
    expect(sides.filter((h) => mesh.heFace[h ^ 1] === -1)).toHaveLength(2);
    expect([...loopHalfedges(mesh, mesh.vHalfedge[1])]).toHaveLength(6);
    expect(sorted(cornerPositions(mesh, face))).toEqual([
      [0, 0.25, 0],
      [0.25, 0, 0],
      [0.75, 1, 0],
      [1, 0.75, 0],
    ]);
  });

  it('bevels an edge whose end has degree 2 (a split point): the new face is a triangle', () => {
    const mesh = meshOf(cube());
    const { vertex } = splitEdge(mesh, edgeBetween(mesh, 5, 6));
    const { face } = checkedEdit(mesh, (m) => bevelEdge(m, edgeBetween(m, vertex, 6)));
    expect(mesh.faceDegree(face)).toBe(3);
    expect([counts(mesh), euler(mesh)]).toEqual([[10, 15, 7], 2]);
  });

  it('keeps a torus a torus', () => {
    const mesh = meshOf(torus(5, 4));
    const { face } = checkedEdit(mesh, (m) => bevelEdge(m, 3, { amount: 0.2 }));
    expect(mesh.faceDegree(face)).toBe(6);
    expect(counts(mesh)).toEqual([24, 45, 21]);
    expect(meshStats(mesh).genus).toBe(1);
  });

  it('refuses a boundary edge, as the assignment does, and leaves the mesh as it was', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 1);
    const why = `e${e} is on the boundary: a bevel replaces an edge between two faces, and e${e} has the hole on one side`;
    expect(canBevelEdge(mesh, e)).toBe(why);
    expectRefused(mesh, () => bevelEdge(mesh, e), `bevelEdge: ${why}`);
  });

  it('refuses an edge whose ends have 4 edges between them: the new face would have 2 sides', () => {
    const mesh = meshOf(twoTrianglePillow());
    const why = 'the ends of e0 (v0, v1) have 2 and 2 edges: the face replacing it would have 2 sides, and a face needs at least 3';
    expect(canBevelEdge(mesh, 0)).toBe(why);
    expectRefused(mesh, () => bevelEdge(mesh, 0), `bevelEdge: ${why}`);
  });

  it('refuses a missing edge and an amount outside 0 … 1', () => {
    const mesh = meshOf(cube());
    expect(canBevelEdge(mesh, 12)).toBe('e12 is not an edge of this mesh (ids run 0…11)');
    expect(canBevelEdge(mesh, 0, Number.NaN)).toMatch(/^amount = NaN is not between 0 and 1: it is the fraction of the way the new corners move from v\d and v\d along its edges$/);
  });
});

describe('bevels on random meshes', () => {
  it(`bevel random vertices and edges of closed, open and several-part meshes, keeping them valid and χ unchanged (seed ${SEED})`, () => {
    fc.assert(
      fc.property(
        fc.nat(fixtures.length - 1),
        fc.array(
          fc.record({ edge: fc.boolean(), pick: fc.nat(), amount: fc.oneof(fc.constant(0), fc.double({ min: 0, max: 1, noNaN: true })) }),
          { minLength: 1, maxLength: 8 },
        ),
        (which, steps) => {
          const mesh = meshOf(fixtures[which][1]());
          const chi = euler(mesh);
          for (const { edge, pick, amount } of steps) {
            const before = counts(mesh);
            if (edge) {
              const e = pick % mesh.edgeSlots;
              const why = canBevelEdge(mesh, e, amount);
              if (why) {
                expectRefused(mesh, () => bevelEdge(mesh, e, { amount }), `bevelEdge: ${why}`);
                continue;
              }
              const sum = mesh.vertexDegree(mesh.heVertex[2 * e]) + mesh.vertexDegree(mesh.heVertex[2 * e + 1]);
              const { face } = checkedEdit(mesh, (m) => bevelEdge(m, e, { amount }));
              expect(counts(mesh)).toEqual([before[0] + sum - 4, before[1] + sum - 3, before[2] + 1]);
              expect(mesh.faceDegree(face)).toBe(sum - 2);
              if (amount === 0) expect(faceArea(mesh, face)).toBe(0);
            } else {
              const v = pick % mesh.vertexSlots;
              const why = canBevelVertex(mesh, v, amount);
              if (why) {
                expectRefused(mesh, () => bevelVertex(mesh, v, { amount }), `bevelVertex: ${why}`);
                continue;
              }
              const d = mesh.vertexDegree(v);
              const { face } = checkedEdit(mesh, (m) => bevelVertex(m, v, { amount }));
              expect(counts(mesh)).toEqual([before[0] + d - 1, before[1] + d, before[2] + 1]);
              expect(mesh.faceDegree(face)).toBe(d);
              if (amount === 0) expect(faceArea(mesh, face)).toBe(0);
            }
          }
          expect(euler(mesh)).toBe(chi);
        },
      ),
      { seed: SEED, numRuns: 80 },
    );
  });
});
