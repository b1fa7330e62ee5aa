import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { canMakeBoundary, makeBoundary } from '../../src/core/edits/index.js';
import { annulus, cube, grid, singleTriangle, tetrahedron } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { checkedEdit, edgeBetween, meshOf } from './helpers.js';
import { corners, expectRefused, holeChiChange, nth, propertyShapes, step, topology } from './topology.js';

const SEED = 2718;

/** The original assignment's first make-boundary case: quads (0, 4, 5, 1), (1, 5, 6, 2) and triangle (2, 6, 3) in a row. */
function quadQuadTriangle() {
  return soupFromArrays(
    [-1, 1.1, 0, 1, 1, 0, 1.1, 1, 0, 2.2, 0, 0, -1.3, -0.7, 0, 1.1, -1, 0, 1.4, -1, 0],
    [
      [0, 4, 5, 1],
      [2, 6, 3],
      [1, 5, 6, 2],
    ],
  );
}

/** The original assignment's second case: quad (0, 3, 4, 1) and triangle (1, 4, 2). */
function quadTriangle() {
  return soupFromArrays(
    [-1, 1.1, 0, 1.05, 1, 0, 2.2, 0, 0, -1.3, -0.7, 0, 1.25, -1, 0],
    [
      [0, 3, 4, 1],
      [1, 4, 2],
    ],
  );
}

describe('makeBoundary', () => {
  it('cuts a face out of a cube: χ drops by 1 and one boundary loop of 4 sides appears', () => {
    const mesh = meshOf(cube());
    const { halfedge, removed } = checkedEdit(mesh, (m) => makeBoundary(m, 1));
    expect(topology(mesh)).toEqual({ V: 8, E: 12, F: 5, chi: 1, loops: 1, components: 1 });
    expect(removed).toEqual({ faces: Int32Array.of(1) });
    expect(mesh.heFace[halfedge]).toBe(-1);
    expect(mesh.loopLength(halfedge)).toBe(4);
    for (const v of [4, 5, 6, 7]) expect(mesh.isBoundaryVertex(v)).toBe(true);
  });

  it('cuts a hole in the middle of an open grid: a second boundary loop', () => {
    // grid(3, 3) of quads: face 4 is the middle one, its corners all inside the grid
    const mesh = meshOf(grid(3, 3, true));
    checkedEdit(mesh, (m) => makeBoundary(m, 4));
    expect(topology(mesh)).toEqual({ V: 16, E: 24, F: 8, chi: 0, loops: 2, components: 1 });
  });

  it('merges a face with the hole along both its free sides, and the row falls in two (the original assignment’s case)', () => {
    const mesh = meshOf(quadQuadTriangle());
    const between = [edgeBetween(mesh, 5, 6), edgeBetween(mesh, 1, 2)];
    const { halfedge, removed } = checkedEdit(mesh, (m) => makeBoundary(m, 2));
    expect(topology(mesh)).toEqual({ V: 7, E: 7, F: 2, chi: 2, loops: 2, components: 2 });
    expect([...removed.edges!].sort()).toEqual(between.sort());
    expect(corners(mesh, 0)).toEqual([0, 4, 5, 1]);
    expect(corners(mesh, 1)).toEqual([2, 6, 3]);
    // the hole handed back is one of the two loops: round the quad or round the triangle
    expect(mesh.heFace[halfedge]).toBe(-1);
    expect([3, 4]).toContain(mesh.loopLength(halfedge));
  });

  it('deletes a corner left with no edge (the original assignment’s second case)', () => {
    const mesh = meshOf(quadTriangle());
    const { removed } = checkedEdit(mesh, (m) => makeBoundary(m, 1));
    expect(topology(mesh)).toEqual({ V: 4, E: 4, F: 1, chi: 1, loops: 1, components: 1 });
    expect(removed.vertices).toEqual(Int32Array.of(2));
    expect(removed.edges).toHaveLength(2);
    expect(corners(mesh, 0)).toEqual([0, 3, 4, 1]);
  });

  it('joins the two holes of an annulus through one of its quads', () => {
    const mesh = meshOf(annulus(4));
    checkedEdit(mesh, (m) => makeBoundary(m, 0));
    expect(topology(mesh)).toEqual({ V: 8, E: 10, F: 3, chi: 1, loops: 1, components: 1 });
  });

  it('opens a tetrahedron, then a second face beside the hole: χ 2 → 1 → 1', () => {
    const mesh = meshOf(tetrahedron());
    checkedEdit(mesh, (m) => makeBoundary(m, 3));
    expect(topology(mesh)).toEqual({ V: 4, E: 6, F: 3, chi: 1, loops: 1, components: 1 });
    // f0 = (0, 1, 2) shares e(1, 2) with the hole: that edge goes, and the hole runs round 0, 1, 3, 2
    checkedEdit(mesh, (m) => makeBoundary(m, 0));
    expect(topology(mesh)).toEqual({ V: 4, E: 5, F: 2, chi: 1, loops: 1, components: 1 });
  });

  it('refuses a face that touches the boundary at a corner alone (a pinch), leaving the mesh as it was', () => {
    // grid(3, 3) of triangles: f3 = (1, 6, 5) has v1 on the bottom boundary but no edge along it
    const mesh = meshOf(grid(3, 3));
    expectRefused(
      mesh,
      canMakeBoundary(mesh, 3),
      "v1 is already on the boundary, but neither edge of f3 at v1 is: f3's hole and the hole through v1 would meet at v1 alone (a pinch)",
      'makeBoundary',
      (m) => makeBoundary(m, 3),
    );
  });

  it('refuses a lone face: nothing would be left', () => {
    const mesh = meshOf(singleTriangle());
    expectRefused(
      mesh,
      canMakeBoundary(mesh, 0),
      'every edge of f0 is on the boundary (f0 is a piece of one face): making it a hole would leave nothing of it',
      'makeBoundary',
      (m) => makeBoundary(m, 0),
    );
  });

  it('refuses a deleted face and one out of range', () => {
    const mesh = meshOf(cube());
    expect(canMakeBoundary(mesh, 6)).toBe('f6 is not a face of this mesh (ids run 0…5)');
    checkedEdit(mesh, (m) => makeBoundary(m, 2));
    expect(canMakeBoundary(mesh, 2)).toBe('f2 is deleted');
  });
});

describe('makeBoundary on random faces', () => {
  it(`keeps closed, open and many-piece meshes valid, χ changing by what the face had along holes (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.constantFrom(...Object.keys(propertyShapes)), fc.array(fc.nat(), { minLength: 1, maxLength: 10 }), (shape, picks) => {
        const mesh = meshOf(propertyShapes[shape]());
        for (const k of picks) {
          const f = nth(mesh.faces(), k);
          if (f === -1) break;
          const chi = topology(mesh).chi;
          const change = holeChiChange(mesh, f);
          const result = step(mesh, canMakeBoundary(mesh, f), 'makeBoundary', (m) => makeBoundary(m, f));
          if (!result) continue;
          expect(topology(mesh).chi).toBe(chi + change);
          expect(mesh.heFace[result.halfedge]).toBe(-1);
          expect(mesh.isEdgeDeleted(result.halfedge >> 1)).toBe(false);
        }
      }),
      { seed: SEED, numRuns: 60 },
    );
  });
});
