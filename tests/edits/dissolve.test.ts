import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  canDissolveEdge,
  canDissolveVertex,
  canMergeFaces,
  dissolveEdge,
  dissolveVertex,
  halfedgeFromTo,
  makeBoundary,
  mergeFaces,
} from '../../src/core/edits/index.js';
import { cube, fan, grid, singleTriangle, strip, tetrahedron } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { checkedEdit, degrees, edgeBetween, meshOf, square, triangleQuadPillow } from './helpers.js';
import { corners, expectRefused, holeChiChange, nth, propertyShapes, step, topology } from './topology.js';

const SEED = 4242;

/** The original assignment's first dissolve-vertex case: a square of four triangles around its centre, v4. */
function squareAroundCentre() {
  return soupFromArrays(
    [-0.5, 0, -0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0, 0.5, 0, 0, 0],
    [
      [3, 2, 4],
      [0, 1, 4],
      [2, 0, 4],
      [1, 3, 4],
    ],
  );
}

/** Two quads on the same four corners, back to back: a closed pillow where every vertex has degree 2. */
function quadPillow() {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0],
    [
      [0, 1, 2, 3],
      [3, 2, 1, 0],
    ],
  );
}

describe('dissolveVertex', () => {
  it('merges the four triangles around the centre of a square into the square (the original assignment’s case)', () => {
    const mesh = meshOf(squareAroundCentre());
    const { face, removed } = checkedEdit(mesh, (m) => dissolveVertex(m, 4));
    expect(topology(mesh)).toEqual({ V: 4, E: 4, F: 1, chi: 1, loops: 1, components: 1 });
    expect(corners(mesh, face)).toEqual([0, 1, 3, 2]);
    expect(removed.vertices).toEqual(Int32Array.of(4));
    expect(removed.edges).toHaveLength(4);
    expect(removed.faces).toHaveLength(3);
  });

  it('merges the three quads at a cube corner into a hexagon, χ unchanged', () => {
    const mesh = meshOf(cube());
    const { face } = checkedEdit(mesh, (m) => dissolveVertex(m, 0));
    expect(topology(mesh)).toEqual({ V: 7, E: 9, F: 4, chi: 2, loops: 0, components: 1 });
    expect(degrees(mesh)).toEqual({ 4: 3, 6: 1 });
    expect(corners(mesh, face)).toEqual([1, 5, 4, 7, 3, 2]);
  });

  it('leaves two triangles on the same three corners when a tetrahedron loses a vertex, and refuses to go further', () => {
    const mesh = meshOf(tetrahedron());
    checkedEdit(mesh, (m) => dissolveVertex(m, 0));
    expect(topology(mesh)).toEqual({ V: 3, E: 3, F: 2, chi: 2, loops: 0, components: 1 });
    expectRefused(
      mesh,
      canDissolveVertex(mesh, 1),
      /^the faces around v1 have only 2 other sides: the merged face would have 2 sides, and a face needs at least 3$/,
      'dissolveVertex',
      (m) => dissolveVertex(m, 1),
    );
  });

  it('merges the faces below a boundary vertex and closes them with a new edge between its boundary neighbours', () => {
    // grid(2, 1): bottom 0, 1, 2, top 3, 4, 5; v1 has faces (0, 1, 4), (1, 2, 5), (1, 5, 4)
    const mesh = meshOf(grid(2, 1));
    const { face, created, removed } = checkedEdit(mesh, (m) => dissolveVertex(m, 1));
    expect(topology(mesh)).toEqual({ V: 5, E: 6, F: 2, chi: 1, loops: 1, components: 1 });
    expect(corners(mesh, face)).toEqual([0, 2, 5, 4]);
    expect(created.edges).toHaveLength(1);
    const n = created.edges![0];
    // the hole ran 2 → 1 → 0 (a = v2, b = v0): n = b → a in the face, its twin a → b on the hole
    expect([mesh.heVertex[2 * n], mesh.heVertex[2 * n + 1]]).toEqual([0, 2]);
    expect(mesh.heFace[2 * n + 1]).toBe(-1);
    expect(mesh.vHalfedge[2]).toBe(2 * n + 1);
    expect(removed.edges).toHaveLength(4);
    expect(degrees(mesh)).toEqual({ 3: 1, 4: 1 });
  });

  it('merges an open fan into one face across its centre', () => {
    const mesh = meshOf(fan(3));
    const { face } = checkedEdit(mesh, (m) => dissolveVertex(m, 0));
    expect(topology(mesh)).toEqual({ V: 4, E: 4, F: 1, chi: 1, loops: 1, components: 1 });
    expect(corners(mesh, face)).toEqual([1, 2, 3, 4]);
  });

  it('refuses a boundary vertex with one face: nothing to merge (the original assignment’s test refuses a lone quad’s corner)', () => {
    const quad = meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], [[0, 1, 3, 2]]));
    expectRefused(
      quad,
      canDissolveVertex(quad, 0),
      'v0 is on the boundary with one face, f0: there are no faces to merge (dissolving it would only cut the corner off)',
      'dissolveVertex',
      (m) => dissolveVertex(m, 0),
    );
    const mesh = meshOf(square());
    expect(canDissolveVertex(mesh, 1)).toBe('v1 is on the boundary with one face, f0: there are no faces to merge (dissolving it would only cut the corner off)');
  });

  it('refuses a boundary vertex whose neighbours along the boundary are joined already (a hole of three sides)', () => {
    // an open tetrahedron: three triangles around v0, the hole where f3 = (1, 3, 2) was
    const mesh = meshOf(tetrahedron());
    checkedEdit(mesh, (m) => makeBoundary(m, 3));
    expectRefused(
      mesh,
      canDissolveVertex(mesh, 1),
      /^v[23] and v[23], v1's neighbours along the boundary, are already joined by e\d+: the edge closing the merged face would be a second edge between them$/,
      'dissolveVertex',
      (m) => dissolveVertex(m, 1),
    );
    // its apex is inside: its three faces merge into the triangle over the hole
    checkedEdit(mesh, (m) => dissolveVertex(m, 0));
    expect(topology(mesh)).toEqual({ V: 3, E: 3, F: 1, chi: 1, loops: 1, components: 1 });
  });

  it('refuses faces that share a corner away from the vertex: the merged face would pass through it twice', () => {
    const mesh = meshOf(quadPillow());
    expectRefused(
      mesh,
      canDissolveVertex(mesh, 0),
      'v2 is a corner of f1 and f0 away from v0: the merged face would pass through v2 twice',
      'dissolveVertex',
      (m) => dissolveVertex(m, 0),
    );
  });

  it('refuses an isolated vertex, a deleted one and an id out of range', () => {
    const mesh = meshOf(square());
    const v = mesh.addVertex(5, 5, 5);
    expectRefused(mesh, canDissolveVertex(mesh, v), `v${v} has no edges: there are no faces around it to merge`, 'dissolveVertex', (m) => dissolveVertex(m, v));
    expect(canDissolveVertex(mesh, 99)).toBe(`v99 is not a vertex of this mesh (ids run 0…${v})`);
    mesh.deleteVertex(v);
    expect(canDissolveVertex(mesh, v)).toBe(`v${v} is deleted`);
  });

  it('keeps the face of the vertex’s handle with its attributes', () => {
    const mesh = meshOf(cube());
    const heat = mesh.faceAttributes.add('heat', 'float64', 1);
    heat.data.set([1, 2, 3, 4, 5, 6]);
    const kept = mesh.heFace[mesh.vHalfedge[0]];
    const { face } = checkedEdit(mesh, (m) => dissolveVertex(m, 0));
    expect(face).toBe(kept);
    expect(heat.data[face]).toBe(kept + 1);
  });

  it('gives the closing edge the attributes of a–v and its halfedges the corner values of those they replace', () => {
    const mesh = meshOf(grid(2, 1));
    mesh.halfedgeAttributes.add('uv', 'float64', 1).data.set(Array.from({ length: mesh.halfedgeSlots }, (_, h) => 100 + h));
    mesh.edgeAttributes.add('crease', 'float64', 1).data.set(Array.from({ length: mesh.edgeSlots }, (_, e) => 10 + e));
    const bv = halfedgeFromTo(mesh, 0, 1); // b → v, b's corner in the last face
    const av = halfedgeFromTo(mesh, 2, 1); // a → v, on the hole
    const { created } = checkedEdit(mesh, (m) => dissolveVertex(m, 1));
    const n = created.edges![0];
    const uv = mesh.halfedgeAttributes.get('uv')!.data;
    expect([uv[2 * n], uv[2 * n + 1]]).toEqual([100 + bv, 100 + av]);
    expect(mesh.edgeAttributes.get('crease')!.data[n]).toBe(10 + (av >> 1));
  });
});

describe('dissolveEdge', () => {
  it('merges the two triangles of a square into one quad (the original assignment’s case)', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 2);
    const { face } = checkedEdit(mesh, (m) => dissolveEdge(m, e));
    expect(topology(mesh)).toEqual({ V: 4, E: 4, F: 1, chi: 1, loops: 1, components: 1 });
    expect(corners(mesh, face)).toEqual([0, 1, 2, 3]);
  });

  it('makes exactly the change mergeFaces makes on an interior edge (mergeFaces is its old name)', () => {
    for (const e of [0, 3, 7]) {
      const a = meshOf(cube());
      const b = meshOf(cube());
      const merged = mergeFaces(a, e);
      const dissolved = dissolveEdge(b, e);
      expect(dissolved.face).toBe(merged.face);
      expect(dissolved.changes).toEqual(merged.changes);
      expect(dissolved.record).toEqual(merged.record);
      expect(canMergeFaces(a, e)).toBe(canDissolveEdge(b, e));
    }
  });

  it('lets the face of a boundary edge join the hole: the face goes, its other edges become boundary', () => {
    // grid(2, 2): f0 = (0, 1, 4) lies along the bottom on e(0, 1); v4 is the middle of the grid
    const mesh = meshOf(grid(2, 2));
    const e = edgeBetween(mesh, 0, 1);
    const { face, removed } = checkedEdit(mesh, (m) => dissolveEdge(m, e));
    expect(face).toBe(-1);
    expect(topology(mesh)).toEqual({ V: 9, E: 15, F: 7, chi: 1, loops: 1, components: 1 });
    expect(removed.faces).toEqual(Int32Array.of(0));
    expect(removed.edges).toEqual(Int32Array.of(e));
    expect(removed.vertices).toBeUndefined();
    for (const [u, v] of [
      [1, 4],
      [4, 0],
    ]) {
      expect(mesh.isBoundaryEdge(edgeBetween(mesh, u, v))).toBe(true);
    }
    expect(mesh.isBoundaryVertex(4)).toBe(true);
  });

  it('takes the corner a face alone had, with both its edges, when that face joins the hole', () => {
    const mesh = meshOf(square());
    const { removed } = checkedEdit(mesh, (m) => dissolveEdge(m, edgeBetween(m, 0, 1)));
    expect(topology(mesh)).toEqual({ V: 3, E: 3, F: 1, chi: 1, loops: 1, components: 1 });
    expect(removed.vertices).toEqual(Int32Array.of(1));
  });

  it('refuses a boundary edge of a lone face (the original assignment’s test refuses a lone quad’s edge)', () => {
    const mesh = meshOf(singleTriangle());
    expectRefused(
      mesh,
      canDissolveEdge(mesh, 0),
      'e0 is on the boundary, so f0 would join the hole, but every edge of f0 is on the boundary (f0 is a piece of one face): making it a hole would leave nothing of it',
      'dissolveEdge',
      (m) => dissolveEdge(m, 0),
    );
  });

  it('refuses a boundary edge whose face touches the boundary at a corner too (a pinch)', () => {
    // strip(2): f0 = (0, 2, 3) lies along the bottom on e(0, 2), and v3 is on the top boundary
    const mesh = meshOf(strip(2));
    const e = edgeBetween(mesh, 0, 2);
    expectRefused(
      mesh,
      canDissolveEdge(mesh, e),
      `e${e} is on the boundary, so f0 would join the hole, but v3 is already on the boundary, but neither edge of f0 at v3 is: f0's hole and the hole through v3 would meet at v3 alone (a pinch)`,
      'dissolveEdge',
      (m) => dissolveEdge(m, e),
    );
  });

  it('refuses two faces that share another corner, as mergeFaces does', () => {
    const mesh = meshOf(triangleQuadPillow());
    const e = edgeBetween(mesh, 0, 2);
    expectRefused(
      mesh,
      canDissolveEdge(mesh, e),
      /^f[02] and f[02] also share v1: the merged face would pass through v1 twice$/,
      'dissolveEdge',
      (m) => dissolveEdge(m, e),
    );
  });

  it('refuses a deleted edge and one out of range', () => {
    const mesh = meshOf(square());
    expect(canDissolveEdge(mesh, 99)).toBe('e99 is not an edge of this mesh (ids run 0…4)');
    mesh.deleteEdge(4);
    expect(canDissolveEdge(mesh, 4)).toBe('e4 is deleted');
  });
});

describe('dissolves on random elements', () => {
  /** Each a vertex (true) or an edge (false), and which live one (modulo their number). */
  const picksOfVerticesAndEdges = fc.array(fc.tuple(fc.boolean(), fc.nat()), { minLength: 1, maxLength: 12 });

  it(`keep closed, open and many-piece meshes valid, χ unchanged but where a boundary edge's face joins the hole (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.constantFrom(...Object.keys(propertyShapes)), picksOfVerticesAndEdges, (shape, picks) => {
        const mesh = meshOf(propertyShapes[shape]());
        for (const [onVertex, k] of picks) {
          const chi = topology(mesh).chi;
          if (onVertex) {
            const v = nth(mesh.vertices(), k);
            if (v === -1) continue;
            step(mesh, canDissolveVertex(mesh, v), 'dissolveVertex', (m) => dissolveVertex(m, v));
            expect(topology(mesh).chi).toBe(chi);
          } else {
            const e = nth(mesh.edges(), k);
            if (e === -1) continue;
            const f = mesh.heFace[2 * e] === -1 ? mesh.heFace[2 * e + 1] : mesh.heFace[2 * e + 1] === -1 ? mesh.heFace[2 * e] : -1;
            const change = f === -1 ? 0 : holeChiChange(mesh, f);
            const result = step(mesh, canDissolveEdge(mesh, e), 'dissolveEdge', (m) => dissolveEdge(m, e));
            expect(topology(mesh).chi).toBe(result ? chi + change : chi);
          }
        }
      }),
      { seed: SEED, numRuns: 60 },
    );
  });
});
