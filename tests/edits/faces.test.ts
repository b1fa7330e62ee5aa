import { describe, expect, it } from 'vitest';
import {
  canCollapseEdge,
  canMergeFaces,
  canPokeFace,
  canSplitEdge,
  collapseEdge,
  canTriangulateFace,
  mergeFaces,
  pokeFace,
  splitEdge,
  triangulateFace,
  triangulateMesh,
  triangulatePolygon,
} from '../../src/core/edits/index.js';
import { TopologyError } from '../../src/core/errors.js';
import { faceArea, faceNormal, signedVolume } from '../../src/core/geometry.js';
import { cube, tetrahedron, torus } from '../../src/core/shapes.js';
import { type PolygonSoup, soupFromArrays } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { checkedEdit, counts, degrees, edgeBetween, meshOf, square, triangleQuadPillow } from './helpers.js';

/** Twice the signed area of each triangle of a 2D triangulation. */
function doubleAreas(coords: number[], triangles: Uint32Array): number[] {
  const areas: number[] = [];
  for (let i = 0; i < triangles.length; i += 3) {
    const [a, b, c] = [triangles[i], triangles[i + 1], triangles[i + 2]];
    areas.push(
      (coords[2 * b] - coords[2 * a]) * (coords[2 * c + 1] - coords[2 * a + 1]) -
        (coords[2 * b + 1] - coords[2 * a + 1]) * (coords[2 * c] - coords[2 * a]),
    );
  }
  return areas;
}

describe('pokeFace', () => {
  it('turns a cube face into four triangles around a vertex at its centre', () => {
    const mesh = meshOf(cube());
    const { vertex, created } = checkedEdit(mesh, (m) => pokeFace(m, 1));
    expect(counts(mesh)).toEqual([9, 16, 9]);
    expect(degrees(mesh)).toEqual({ 3: 4, 4: 5 });
    expect(mesh.position(vertex)).toEqual([0.5, 0.5, 1]);
    expect(created.edges).toHaveLength(4);
    expect(created.faces).toHaveLength(3);
    expect(signedVolume(mesh)).toBeCloseTo(1, 14);
  });

  it('averages every vertex attribute over the corners', () => {
    const mesh = meshOf(tetrahedron());
    const label = mesh.vertexAttributes.add('heat', 'float64', 1);
    label.data.set([3, 6, 9, 12]);
    const corners = [0, 1, 2].map((i) => mesh.heVertex[[mesh.fHalfedge[0], mesh.heNext[mesh.fHalfedge[0]], mesh.hePrev[mesh.fHalfedge[0]]][i]]);
    const { vertex } = checkedEdit(mesh, (m) => pokeFace(m, 0));
    expect(label.data[vertex]).toBeCloseTo(corners.reduce((s, v) => s + label.data[v], 0) / 3, 12);
  });

  it('refuses a deleted face', () => {
    const mesh = meshOf(cube());
    mesh.deleteFace(2);
    expect(canPokeFace(mesh, 2)).toBe('f2 is deleted');
    expect(() => pokeFace(mesh, 2)).toThrow(TopologyError);
  });
});

describe('mergeFaces', () => {
  it('erases the diagonal of a square: two triangles become one quad', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 2);
    const { face, removed } = checkedEdit(mesh, (m) => mergeFaces(m, e));
    expect(counts(mesh)).toEqual([4, 4, 1]);
    expect(degrees(mesh)).toEqual({ 4: 1 });
    expect(face).toBe(mesh.heFace[0]);
    expect(removed.edges).toEqual(Int32Array.of(e));
  });

  it('merges two cube faces into a hexagon that folds over an edge', () => {
    const mesh = meshOf(cube());
    checkedEdit(mesh, (m) => mergeFaces(m, 0));
    expect(degrees(mesh)).toEqual({ 4: 4, 6: 1 });
    expect(meshStats(mesh).eulerCharacteristic).toBe(2);
  });

  it('refuses a boundary edge', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 1);
    expect(canMergeFaces(mesh, e)).toBe(`e${e} is on the boundary: there is no second face to merge f0 with`);
  });

  it('refuses two faces that share a second edge (it would leave a dangling edge)', () => {
    const mesh = meshOf(triangleQuadPillow());
    const e = edgeBetween(mesh, 0, 2);
    expect(canMergeFaces(mesh, e)).toMatch(/^f[02] and f[02] also share v1: the merged face would pass through v1 twice/);
    expect(() => mergeFaces(mesh, e)).toThrow(TopologyError);
  });

  // the sequences that once led, every predicate saying yes, to meshes validate() rejects: each
  // went through a merge of two faces that share a corner, a face that passes through it twice
  const sequences: Array<[string, () => PolygonSoup, Array<[string, number]>]> = [
    ['cube', cube, [['collapse', 1], ['merge', 7], ['merge', 5], ['collapse', 10], ['split', 11]]],
    ['cube', cube, [['collapse', 7], ['merge', 10], ['merge', 8], ['collapse', 6], ['collapse', 5]]],
    ['tetrahedron', tetrahedron, [['split', 1], ['split', 3], ['collapse', 2], ['merge', 4], ['collapse', 5], ['collapse', 1], ['collapse', 0]]],
  ];
  for (const [name, shape, steps] of sequences) {
    it(`keeps the ${name} valid through ${steps.map(([op, e]) => `${op} e${e}`).join(', ')}, refusing the merge that would break it`, () => {
      const mesh = meshOf(shape());
      let refused = '';
      for (const [op, e] of steps) {
        const why = op === 'merge' ? canMergeFaces(mesh, e) : op === 'collapse' ? canCollapseEdge(mesh, e) : canSplitEdge(mesh, e);
        if (why) {
          refused = `${op} e${e}: ${why}`;
          break;
        }
        if (op === 'merge') checkedEdit(mesh, (m) => mergeFaces(m, e));
        else if (op === 'collapse') checkedEdit(mesh, (m) => collapseEdge(m, e));
        else checkedEdit(mesh, (m) => splitEdge(m, e));
      }
      expect(refused).toMatch(/^merge e\d+: f\d+ and f\d+ also share v\d+: the merged face would pass through v\d+ twice$/);
    });
  }
});

describe('triangulatePolygon', () => {
  it('cuts a U-shaped octagon into six counter-clockwise triangles', () => {
    const u = [0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3];
    const triangles = triangulatePolygon(u, [])!;
    expect(triangles).toHaveLength(18);
    const areas = doubleAreas(u, triangles);
    expect(areas.every((a) => a > 0)).toBe(true);
    expect(areas.reduce((s, a) => s + a, 0) / 2).toBeCloseTo(7, 12);
  });

  it('uses corners that lie on a straight side, with no triangle of zero area', () => {
    // a square with a corner in the middle of each side
    const square8 = [0, 0, 1, 0, 2, 0, 2, 1, 2, 2, 1, 2, 0, 2, 0, 1];
    const triangles = triangulatePolygon(square8, [])!;
    expect(new Set(triangles).size).toBe(8);
    expect(triangles).toHaveLength(18);
    expect(doubleAreas(square8, triangles).every((a) => a > 0)).toBe(true);
  });

  it('triangulates a square with a square hole (the hole clockwise)', () => {
    const ring = [0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 1, 3, 3, 3, 3, 1];
    const triangles = triangulatePolygon(ring, [4])!;
    expect(triangles).toHaveLength(24);
    expect(doubleAreas(ring, triangles).reduce((s, a) => s + a, 0) / 2).toBeCloseTo(12, 12);
  });

  it('gives null for fewer than three corners, or corners all on one line', () => {
    expect(triangulatePolygon([0, 0, 1, 1], [])).toBeNull();
    expect(triangulatePolygon([0, 0, 1, 0, 2, 0, 3, 0], [])).toBeNull();
  });
});

describe('triangulateFace', () => {
  it('triangulates a non-convex L-shaped face on a tilted plane without folding any triangle', () => {
    const flat = [
      [0, 0],
      [2, 0],
      [2, 1],
      [1, 1],
      [1, 2],
      [0, 2],
    ];
    // the plane z = 0.3 x + 0.5 y
    const positions = flat.flatMap(([x, y]) => [x, y, 0.3 * x + 0.5 * y]);
    const mesh = meshOf(soupFromArrays(positions, [[0, 1, 2, 3, 4, 5]]));
    const normal = faceNormal(mesh, 0);
    const area = faceArea(mesh, 0);
    const { created } = checkedEdit(mesh, (m) => triangulateFace(m, 0));
    expect(degrees(mesh)).toEqual({ 3: 4 });
    expect(created.edges).toHaveLength(3);
    let total = 0;
    for (const f of mesh.faces()) {
      const n = faceNormal(mesh, f);
      expect(n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2]).toBeCloseTo(1, 12);
      total += faceArea(mesh, f);
    }
    expect(total).toBeCloseTo(area, 12);
  });

  it('triangulates the quad a plain edge split leaves, straight angle and all', () => {
    const mesh = meshOf(tetrahedron());
    splitEdge(mesh, 0);
    const quad = mesh.heFace[0];
    checkedEdit(mesh, (m) => triangulateFace(m, quad));
    expect(degrees(mesh)).toEqual({ 3: 4, 4: 1 });
    for (const f of mesh.faces()) if (mesh.faceDegree(f) === 3) expect(faceArea(mesh, f)).toBeGreaterThan(0.1);
  });

  // in a tetrahedron every two corners are joined: the quad left by erasing one edge has one
  // diagonal that is an edge already, and ear clipping from corner 0 chose it
  it('chooses the diagonal no edge holds yet: the quad of a tetrahedron with one edge erased', () => {
    const mesh = meshOf(tetrahedron());
    const erased = [mesh.heVertex[2], mesh.heVertex[3]];
    checkedEdit(mesh, (m) => mergeFaces(m, 1));
    checkedEdit(mesh, (m) => triangulateFace(m, 0));
    expect(meshStats(mesh)).toMatchObject({ vertices: 4, edges: 6, faces: 4, boundaryLoops: 0, eulerCharacteristic: 2 });
    expect(edgeBetween(mesh, erased[0]!, erased[1]!)).not.toBe(-1);
  });

  it('leaves a triangle as it is', () => {
    const mesh = meshOf(tetrahedron());
    expect(checkedEdit(mesh, (m) => triangulateFace(m, 0)).changes).toEqual([]);
  });

  it('refuses a face of zero area', () => {
    const mesh = meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0], [[0, 1, 2, 3]]));
    expect(canTriangulateFace(mesh, 0)).toBe('f0 has zero area: it has no plane to be triangulated in');
    expect(() => triangulateFace(mesh, 0)).toThrow(TopologyError);
  });
});

describe('triangulateMesh', () => {
  it('turns a cube into 12 triangles enclosing the same volume', () => {
    const mesh = meshOf(cube());
    const { skipped } = checkedEdit(mesh, (m) => triangulateMesh(m));
    expect(counts(mesh)).toEqual([8, 18, 12]);
    expect(skipped).toHaveLength(0);
    expect(signedVolume(mesh)).toBeCloseTo(1, 14);
  });

  it('keeps a torus a torus', () => {
    const mesh = meshOf(torus(8, 6));
    checkedEdit(mesh, (m) => triangulateMesh(m));
    const stats = meshStats(mesh);
    expect([stats.faces, stats.genus, stats.closed]).toEqual([96, 1, true]);
  });

  it('skips and lists the faces it cannot triangulate', () => {
    const mesh = meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 1, 1, 0, 0, 1, 0], [[0, 1, 2, 3], [1, 0, 5, 4]]));
    const { skipped } = triangulateMesh(mesh);
    expect(skipped).toEqual(Int32Array.of(0));
    expect(degrees(mesh)).toEqual({ 3: 2, 4: 1 });
  });
});
