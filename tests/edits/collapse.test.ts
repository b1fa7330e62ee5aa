import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { loopHalfedges } from '../../src/core/circulators.js';
import { canCollapseEdge, collapseEdge, triangulateMesh } from '../../src/core/edits/index.js';
import { TopologyError } from '../../src/core/errors.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { disk, singleTriangle, strip, tetrahedron, torus, uvSphere } from '../../src/core/shapes.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';
import { bipyramid, checkedEdit, counts, degrees, edgeBetween, meshOf, triangleQuadPillow } from './helpers.js';

const SEED = 777;

/** Relabels edge e's halfedges: 2e becomes 2e + 1 and the other way round (a renumbering only). */
function swapHalfedges(mesh: HalfedgeMesh, e: number): void {
  const [x, y] = [2 * e, 2 * e + 1];
  const swap = (h: number) => (h === x ? y : h === y ? x : h);
  for (const array of [mesh.heNext, mesh.hePrev]) {
    for (let h = 0; h < mesh.halfedgeSlots; h++) array[h] = swap(array[h]);
  }
  for (const array of [mesh.heNext, mesh.hePrev, mesh.heVertex, mesh.heFace]) [array[x], array[y]] = [array[y], array[x]];
  for (let v = 0; v < mesh.vertexSlots; v++) mesh.vHalfedge[v] = swap(mesh.vHalfedge[v]);
  for (let f = 0; f < mesh.faceSlots; f++) mesh.fHalfedge[f] = swap(mesh.fHalfedge[f]);
}

/** Collapses edges picked by `pick` until none can be collapsed; returns how many were. */
function collapseAll(mesh: HalfedgeMesh, pick: (n: number) => number): number {
  let collapsed = 0;
  for (;;) {
    const candidates = [...mesh.edges()].filter((e) => canCollapseEdge(mesh, e) === null);
    if (candidates.length === 0) return collapsed;
    collapseEdge(mesh, candidates[pick(candidates.length)], { record: false });
    collapsed++;
  }
}

describe('collapseEdge', () => {
  it('merges an interior edge of a disk: one vertex, three edges and two triangles fewer', () => {
    const mesh = meshOf(disk(2));
    const e = edgeBetween(mesh, 0, 1);
    const [a, b] = [mesh.position(0), mesh.position(1)];
    const [kept, gone] = [mesh.heVertex[2 * e], mesh.heVertex[2 * e + 1]];
    const { vertex, removed } = checkedEdit(mesh, (m) => collapseEdge(m, e));
    expect(counts(mesh)).toEqual([18, 39, 22]);
    expect(vertex).toBe(kept);
    expect(mesh.position(vertex)).toEqual(a.map((x, i) => (x + b[i]) / 2));
    expect(removed.vertices).toEqual(Int32Array.of(gone));
    expect(removed.edges).toHaveLength(3);
    expect(removed.faces).toHaveLength(2);
  });

  it('collapses a boundary ear edge stored with its boundary halfedge first', () => {
    // the builder always puts the boundary halfedge second (2e + 1); edits do not, so relabel one
    // edge of a strip's end triangle: 2e runs along the hole, and the triangle's next side from
    // the vanishing end is on the boundary too (an "ear")
    const mesh = meshOf(strip(3));
    const ear = [...mesh.edges()].find((e) => {
      const inner = 2 * e;
      return mesh.heFace[inner + 1] === -1 && mesh.heNext[inner + 1] === (mesh.hePrev[inner] ^ 1);
    })!;
    swapHalfedges(mesh, ear);
    expect(mesh.heFace[2 * ear]).toBe(-1);
    expect(validate(mesh)).toEqual([]);
    const { vertex } = checkedEdit(mesh, (m) => collapseEdge(m, ear));
    // the survivor's handle is live and leaves it, so its one-ring can be walked
    expect(mesh.isHalfedgeDeleted(mesh.vHalfedge[vertex])).toBe(false);
    expect(mesh.heVertex[mesh.vHalfedge[vertex]]).toBe(vertex);
  });

  it('skips the change list when told not to record, for bulk use', () => {
    const recorded = meshOf(disk(2));
    const quiet = recorded.clone();
    const e = edgeBetween(recorded, 0, 1);
    const loud = collapseEdge(recorded, e);
    const { changes, created, removed } = collapseEdge(quiet, e, { record: false });
    expect(loud.changes.length).toBeGreaterThan(0);
    expect(changes).toEqual([]);
    expect([created, removed]).toEqual([loud.created, loud.removed]);
    expect(quiet.heNext).toEqual(recorded.heNext);
  });

  it('puts the surviving vertex where it is told', () => {
    const mesh = meshOf(disk(2));
    const { vertex } = checkedEdit(mesh, (m) => collapseEdge(m, edgeBetween(m, 0, 1), { position: [0.1, 0.2, 0.3] }));
    expect(mesh.position(vertex)).toEqual([0.1, 0.2, 0.3]);
  });

  it('shortens the boundary by one when a boundary edge collapses', () => {
    const mesh = meshOf(disk(2));
    const e = edgeBetween(mesh, 7, 8);
    expect(canCollapseEdge(mesh, e)).toBeNull();
    const { vertex } = checkedEdit(mesh, (m) => collapseEdge(m, e));
    expect(mesh.isBoundaryVertex(vertex)).toBe(true);
    expect([...loopHalfedges(mesh, mesh.vHalfedge[vertex])]).toHaveLength(11);
  });

  it('refuses an interior edge between two boundary vertices', () => {
    const mesh = meshOf(strip(3));
    const e = edgeBetween(mesh, 2, 3);
    expect(canCollapseEdge(mesh, e)).toBe(
      `e${e} joins two boundary vertices (v${mesh.heVertex[2 * e]}, v${mesh.heVertex[2 * e + 1]}) but is not on the boundary itself: collapsing it would pinch the surface at one vertex`,
    );
  });

  it('refuses a lone triangle: its other two edges would dangle', () => {
    const mesh = meshOf(singleTriangle());
    expect(canCollapseEdge(mesh, 0)).toBe('the other two edges of f0 are both on the boundary: collapsing e0 would leave them as one dangling edge');
  });

  it('refuses when the ends share a neighbour that is not across one of their triangles (link condition)', () => {
    const mesh = meshOf(bipyramid());
    const e = edgeBetween(mesh, 0, 1);
    expect(canCollapseEdge(mesh, e)).toMatch(/^v[01] and v[01] \(the ends of e\d+\) are both joined to v2, which is not across a triangle of e\d+: collapsing would join them twice \(the link condition fails\)$/);
    expect(() => collapseEdge(mesh, e)).toThrow(TopologyError);
  });

  it('collapses a bipyramid edge from pole to equator into a tetrahedron', () => {
    const mesh = meshOf(bipyramid());
    checkedEdit(mesh, (m) => collapseEdge(m, edgeBetween(m, 0, 3)));
    expect(counts(mesh)).toEqual([4, 6, 4]);
  });

  it('refuses when a face other than those beside the edge has both ends as corners', () => {
    const mesh = meshOf(triangleQuadPillow());
    const e = edgeBetween(mesh, 0, 1);
    expect(canCollapseEdge(mesh, e)).toMatch(/^f2 has both v[01] and v[01] as corners but not along e\d+: collapsing would make it pass through one vertex twice$/);
  });

  it('refuses every edge of a tetrahedron', () => {
    const mesh = meshOf(tetrahedron());
    for (const e of mesh.edges()) {
      expect(canCollapseEdge(mesh, e)).toMatch(new RegExp(`^e${e} is an edge of a tetrahedron \\(f\\d, f\\d, f\\d, f\\d\\): collapsing it would flatten it`));
    }
  });

  it('shrinks an edge between quads, which lose one side each', () => {
    const mesh = meshOf(torus(5, 4));
    checkedEdit(mesh, (m) => collapseEdge(m, 0));
    expect(degrees(mesh)).toEqual({ 3: 2, 4: 18 });
    expect(meshStats(mesh).genus).toBe(1);
  });

  it(`collapses a sphere, edge after edge in random order, down to a tetrahedron and no further (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.infiniteStream(fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true })), (stream) => {
        const mesh = meshOf(uvSphere(5, 6));
        const random = stream[Symbol.iterator]();
        collapseAll(mesh, (n) => Math.floor(random.next().value * n));
        expect(validate(mesh)).toEqual([]);
        expect(counts(mesh)).toEqual([4, 6, 4]);
      }),
      { seed: SEED, numRuns: 20 },
    );
  });

  it(`keeps a torus a valid torus down to an irreducible triangulation (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.infiniteStream(fc.double({ min: 0, max: 1, maxExcluded: true, noNaN: true })), (stream) => {
        const mesh = meshOf(torus(6, 5));
        triangulateMesh(mesh, { record: false });
        const random = stream[Symbol.iterator]();
        collapseAll(mesh, (n) => Math.floor(random.next().value * n));
        expect(validate(mesh)).toEqual([]);
        const stats = meshStats(mesh);
        expect([stats.genus, stats.closed, stats.components]).toEqual([1, true, 1]);
        // the smallest triangulation of a torus has 7 vertices; irreducible ones have at most 10
        expect(mesh.nVertices).toBeGreaterThanOrEqual(7);
        expect(mesh.nVertices).toBeLessThanOrEqual(10);
      }),
      { seed: SEED, numRuns: 10 },
    );
  });

  it(`reports exactly its changes on each of a run of random collapses (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.array(fc.nat(), { minLength: 1, maxLength: 30 }), (picks) => {
        const mesh = meshOf(disk(3));
        for (const pick of picks) {
          const e = pick % mesh.edgeSlots;
          const why = canCollapseEdge(mesh, e);
          if (why) expect(() => collapseEdge(mesh, e)).toThrow(why);
          else checkedEdit(mesh, (m) => collapseEdge(m, e));
        }
        expect(meshStats(mesh).boundaryLoops).toBe(1);
      }),
      { seed: SEED, numRuns: 40 },
    );
  });
});
