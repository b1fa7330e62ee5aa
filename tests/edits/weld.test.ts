import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { canMakeBoundary, canWeldEdges, makeBoundary, weldEdges } from '../../src/core/edits/index.js';
import { annulus, cube, fan, grid, tetrahedron } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { checkedEdit, edgeBetween, meshOf, square } from './helpers.js';
import { boundaryEdges, corners, expectRefused, loopId, nth, propertyShapes, step, topology } from './topology.js';

const SEED = 1618;

/** The original assignment's weld case: quad (0, 4, 5, 1) and, apart from it, triangle (2, 6, 3). */
function quadBesideTriangle() {
  return soupFromArrays(
    [-1, 1.1, 0, 1, 1, 0, 1.1, 1, 0, 2.2, 0, 0, -1.3, -0.7, 0, 1.1, -1, 0, 1.4, -1, 0],
    [
      [0, 4, 5, 1],
      [2, 6, 3],
    ],
  );
}

describe('weldEdges', () => {
  it('joins a quad and a triangle side by side, ends at their midpoints (the original assignment’s case)', () => {
    const mesh = meshOf(quadBesideTriangle());
    const e1 = edgeBetween(mesh, 1, 5);
    const e2 = edgeBetween(mesh, 2, 6);
    const { edge, removed } = checkedEdit(mesh, (m) => weldEdges(m, e1, e2));
    expect(edge).toBe(e1);
    expect(mesh.isBoundaryEdge(edge)).toBe(false);
    expect(topology(mesh)).toEqual({ V: 5, E: 6, F: 2, chi: 1, loops: 1, components: 1 });
    expect(removed).toEqual({ vertices: Int32Array.of(2, 6), edges: Int32Array.of(e2) });
    expect(mesh.position(1)).toEqual([1.05, 1, 0]);
    expect(mesh.position(5)).toEqual([1.25, -1, 0]);
    expect(corners(mesh, 0)).toEqual([0, 4, 5, 1]);
    expect(corners(mesh, 1)).toEqual([1, 5, 3]);
  });

  it('averages every vertex attribute of the merged ends, and the welded halfedge takes the corner values it replaces', () => {
    const mesh = meshOf(quadBesideTriangle());
    mesh.vertexAttributes.add('heat', 'float64', 1).data.set([0, 10, 20, 30, 40, 50, 60]);
    const uv = mesh.halfedgeAttributes.add('uv', 'float64', 1);
    uv.data.set(Array.from({ length: mesh.halfedgeSlots }, (_, h) => h));
    const e1 = edgeBetween(mesh, 1, 5);
    const e2 = edgeBetween(mesh, 2, 6);
    const t2 = mesh.heFace[2 * e2] === -1 ? 2 * e2 + 1 : 2 * e2;
    const h1 = mesh.heFace[2 * e1] === -1 ? 2 * e1 : 2 * e1 + 1;
    checkedEdit(mesh, (m) => weldEdges(m, e1, e2));
    const heat = mesh.vertexAttributes.get('heat')!.data;
    expect([heat[1], heat[5]]).toEqual([15, 55]);
    expect(uv.data[h1]).toBe(t2);
  });

  it('rolls a strip of three quads into the annulus of three quads: χ 1 → 0, one boundary loop → two', () => {
    // grid(3, 1) of quads: bottom 0…3, top 4…7; weld the left side 0–4 to the right side 3–7
    const mesh = meshOf(grid(3, 1, true));
    const { edge } = checkedEdit(mesh, (m) => weldEdges(m, edgeBetween(m, 0, 4), edgeBetween(m, 3, 7)));
    expect(topology(mesh)).toEqual({ V: 6, E: 9, F: 3, chi: 0, loops: 2, components: 1 });
    expect(topology(mesh)).toEqual(topology(meshOf(annulus(3))));
    expect([mesh.heVertex[2 * edge], mesh.heVertex[2 * edge + 1]].sort()).toEqual([0, 4]);
  });

  it('zips two edges that meet at a vertex: the vertex moves inside, χ unchanged', () => {
    // fan(4): centre 0, rim 1…5; the edges 0–1 and 0–5 both lie on the hole and meet at 0
    const mesh = meshOf(fan(4, 1.5 * Math.PI));
    const [e1, e2] = [edgeBetween(mesh, 0, 1), edgeBetween(mesh, 0, 5)];
    const { removed } = checkedEdit(mesh, (m) => weldEdges(m, e1, e2));
    expect(topology(mesh)).toEqual({ V: 5, E: 8, F: 4, chi: 1, loops: 1, components: 1 });
    expect(removed).toEqual({ vertices: Int32Array.of(5), edges: Int32Array.of(e2) });
    expect(mesh.isBoundaryVertex(0)).toBe(false);
    expect(mesh.vertexDegree(0)).toBe(4);
  });

  it('welds the hole a face left back into an annulus of one face fewer (makeBoundary, then weldEdges)', () => {
    // annulus(4): quads (2i, 2i + 1, 2i + 3, 2i + 2), inner ring even, outer ring odd
    const mesh = meshOf(annulus(4));
    checkedEdit(mesh, (m) => makeBoundary(m, 0));
    expect(topology(mesh)).toEqual({ V: 8, E: 10, F: 3, chi: 1, loops: 1, components: 1 });
    // the strip's free ends are the spokes 0–1 and 2–3
    checkedEdit(mesh, (m) => weldEdges(m, edgeBetween(m, 0, 1), edgeBetween(m, 2, 3)));
    expect(topology(mesh)).toEqual({ V: 6, E: 9, F: 3, chi: 0, loops: 2, components: 1 });
  });

  it('refuses an edge with faces on both sides, and the same edge twice', () => {
    const mesh = meshOf(square());
    const diagonal = edgeBetween(mesh, 0, 2);
    const side = edgeBetween(mesh, 0, 1);
    expectRefused(
      mesh,
      canWeldEdges(mesh, side, diagonal),
      `e${diagonal} is not on the boundary: only boundary edges can be welded (it has faces on both sides)`,
      'weldEdges',
      (m) => weldEdges(m, side, diagonal),
    );
    expectRefused(
      mesh,
      canWeldEdges(mesh, side, side),
      `e${side} is given twice: a weld joins two different edges`,
      'weldEdges',
      (m) => weldEdges(m, side, side),
    );
    expect(canWeldEdges(mesh, side, 99)).toBe('e99 is not an edge of this mesh (ids run 0…4)');
  });

  it('refuses zipping a hole of three sides shut: the merged ends are joined already', () => {
    const mesh = meshOf(tetrahedron());
    checkedEdit(mesh, (m) => makeBoundary(m, 3)); // the hole runs round 1, 2, 3
    const [e1, e2] = [edgeBetween(mesh, 1, 3), edgeBetween(mesh, 3, 2)];
    expectRefused(
      mesh,
      canWeldEdges(mesh, e1, e2),
      /^v[12] and v[12] would merge, but e\d+ joins them: it would become a loop$/,
      'weldEdges',
      (m) => weldEdges(m, e1, e2),
    );
  });

  it('refuses zipping a hole of four sides shut: the merged vertex would be joined twice to the fourth corner', () => {
    const mesh = meshOf(cube());
    checkedEdit(mesh, (m) => makeBoundary(m, 1)); // the hole runs round 4, 5, 6, 7
    const [e1, e2] = [edgeBetween(mesh, 4, 5), edgeBetween(mesh, 5, 6)];
    expectRefused(
      mesh,
      canWeldEdges(mesh, e1, e2),
      /^welding would join v[46] \(merged with v[46]\) to v7 by two edges, e\d+ and e\d+: a second edge between two vertices is not allowed$/,
      'weldEdges',
      (m) => weldEdges(m, e1, e2),
    );
  });

  it('refuses two edges of one face: the face would pass through the merged vertex twice', () => {
    const mesh = meshOf(
      soupFromArrays(
        [0, 0, 0, 1, 0, 0, 1.5, 1, 0, 0.5, 2, 0, -0.5, 1, 0],
        [[0, 1, 2, 3, 4]],
      ),
    );
    const [e1, e2] = [edgeBetween(mesh, 0, 1), edgeBetween(mesh, 3, 4)];
    expectRefused(
      mesh,
      canWeldEdges(mesh, e1, e2),
      'v1 and v3 would merge, but they are both corners of f0: it would pass through the merged vertex twice',
      'weldEdges',
      (m) => weldEdges(m, e1, e2),
    );
  });

  it('refuses a weld that would join two vertices by two edges (a strip of two quads rolled up)', () => {
    // grid(2, 1) of quads: bottom 0, 1, 2, top 3, 4, 5; v3 and v5 would merge, both joined to v4
    const mesh = meshOf(grid(2, 1, true));
    const [e1, e2] = [edgeBetween(mesh, 0, 3), edgeBetween(mesh, 2, 5)];
    expectRefused(
      mesh,
      canWeldEdges(mesh, e1, e2),
      /^welding would join v\d \(merged with v\d\) to v[14] by two edges, e\d+ and e\d+: a second edge between two vertices is not allowed$/,
      'weldEdges',
      (m) => weldEdges(m, e1, e2),
    );
  });
});

describe('weldEdges on random pairs of boundary edges', () => {
  it(`keeps meshes valid, χ − 1 (0 for a zip), one loop fewer (two loops joined) or more (one split) (seed ${SEED})`, () => {
    fc.assert(
      fc.property(
        fc.constantFrom(...Object.keys(propertyShapes)),
        fc.array(fc.tuple(fc.nat(3), fc.nat(), fc.nat()), { minLength: 1, maxLength: 16 }),
        (shape, picks) => {
          const mesh = meshOf(propertyShapes[shape]());
          for (const [kind, i, j] of picks) {
            // one step in four opens a hole, so that closed meshes have edges to weld too
            if (kind === 0) {
              const f = nth(mesh.faces(), i);
              if (f !== -1) step(mesh, canMakeBoundary(mesh, f), 'makeBoundary', (m) => makeBoundary(m, f));
              continue;
            }
            const edges = boundaryEdges(mesh);
            if (edges.length < 2) continue;
            const e1 = edges[i % edges.length];
            const e2 = edges[j % edges.length];
            const h1 = mesh.heFace[2 * e1] === -1 ? 2 * e1 : 2 * e1 + 1;
            const h2 = mesh.heFace[2 * e2] === -1 ? 2 * e2 : 2 * e2 + 1;
            const zip = mesh.heNext[h1] === h2 || mesh.heNext[h2] === h1;
            const sameLoop = loopId(mesh, h1) === loopId(mesh, h2);
            const before = topology(mesh);
            const result = step(mesh, canWeldEdges(mesh, e1, e2), 'weldEdges', (m) => weldEdges(m, e1, e2));
            if (!result) continue;
            const after = topology(mesh);
            expect(result.edge).toBe(e1);
            expect(mesh.isBoundaryEdge(e1)).toBe(false);
            expect(after.chi).toBe(zip ? before.chi : before.chi - 1);
            expect(after.loops).toBe(zip ? before.loops : sameLoop ? before.loops + 1 : before.loops - 1);
          }
        },
      ),
      { seed: SEED, numRuns: 80 },
    );
  });
});
