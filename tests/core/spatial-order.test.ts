import { describe, expect, it } from 'vitest';
import { buildMesh, grid, HalfedgeMesh, mergeSoups, meshStats, torus, uvSphere, validate } from '../../src/index.js';
import { collapseEdge } from '../../src/core/edits/index.js';
import { spatialOrder } from '../../src/core/spatial-order.js';
import { meshArrays } from '../../src/core/mesh-arrays.js';
import type { CompactionMaps } from '../../src/core/mesh.js';

/** For every live halfedge of `before`: each pointer, renumbered, is the pointer of its new id. */
function expectSameMeshRenumbered(before: HalfedgeMesh, after: HalfedgeMesh, maps: CompactionMaps): void {
  const halfedge = (h: number) => (h < 0 ? h : 2 * maps.edges[h >> 1] + (h & 1));
  for (let h = 0; h < before.halfedgeSlots; h++) {
    if (before.eDeleted[h >> 1]) continue;
    const g = halfedge(h);
    expect(after.heNext[g]).toBe(halfedge(before.heNext[h]));
    expect(after.hePrev[g]).toBe(halfedge(before.hePrev[h]));
    expect(after.heVertex[g]).toBe(maps.vertices[before.heVertex[h]]);
    expect(after.heFace[g]).toBe(before.heFace[h] < 0 ? -1 : maps.faces[before.heFace[h]]);
  }
  for (let v = 0; v < before.vertexSlots; v++) {
    if (before.vDeleted[v]) continue;
    expect(after.position(maps.vertices[v])).toEqual(before.position(v));
    expect(after.vHalfedge[maps.vertices[v]]).toBe(halfedge(before.vHalfedge[v]));
  }
  for (let f = 0; f < before.faceSlots; f++) if (!before.fDeleted[f]) expect(after.fHalfedge[maps.faces[f]]).toBe(halfedge(before.fHalfedge[f]));
}

/** The live ids of a map, in order of their new ids: each new id exactly once. */
function expectPermutation(map: Int32Array, live: number): void {
  expect(Array.from(map.filter((id) => id >= 0)).sort((a, b) => a - b)).toEqual(Array.from({ length: live }, (_, i) => i));
}

describe('spatialOrder', () => {
  it('renumbers every element and pointer, attributes included, dropping deleted slots', () => {
    const { mesh } = buildMesh(mergeSoups([uvSphere(6, 8), torus(6, 4)]));
    mesh.vertexAttributes.add('weight', 'float32', 1).data.set(Array.from({ length: mesh.vertexSlots }, (_, v) => v));
    // a collapse leaves deleted slots behind: a vertex, three edges, two faces
    const f = mesh.heFace[0];
    collapseEdge(mesh, 0);
    expect(validate(mesh)).toEqual([]);
    const before = mesh.clone();
    const weight = Float32Array.from(mesh.vertexAttributes.get('weight')!.data);
    const maps = spatialOrder(mesh);
    expect(validate(mesh)).toEqual([]);
    expect(mesh.isCompact).toBe(true);
    expect(maps.faces[f]).toBe(-1);
    expectPermutation(maps.vertices, mesh.nVertices);
    expectPermutation(maps.edges, mesh.nEdges);
    expectPermutation(maps.faces, mesh.nFaces);
    expectSameMeshRenumbered(before, mesh, maps);
    for (let v = 0; v < before.vertexSlots; v++) if (!before.vDeleted[v]) expect(mesh.vertexAttributes.get('weight')!.data[maps.vertices[v]]).toBe(weight[v]);
    const { vertices, edges, faces, genus, components } = meshStats(mesh);
    const was = meshStats(before);
    expect({ vertices, edges, faces, genus, components }).toEqual({ vertices: was.vertices, edges: was.edges, faces: was.faces, genus: was.genus, components: was.components });
  });

  it('puts the vertices of a grid along a Z-order curve, and each edge after its lower end', () => {
    // a 4 × 4 grid of vertices, numbered row by row
    const { mesh } = buildMesh(grid(3, 3, true));
    const maps = spatialOrder(mesh);
    // the Z-order of the cells (x, y) of a 4 × 4 grid: 2 × 2 blocks, each in the order 00 10 01 11
    const zOrder = [
      [0, 0], [1, 0], [0, 1], [1, 1], [2, 0], [3, 0], [2, 1], [3, 1],
      [0, 2], [1, 2], [0, 3], [1, 3], [2, 2], [3, 2], [2, 3], [3, 3],
    ];
    const rowByRow = (x: number, y: number) => 4 * y + x;
    expect(zOrder.map(([x, y]) => maps.vertices[rowByRow(x, y)])).toEqual(zOrder.map((_, i) => i));
    for (let e = 1; e < mesh.edgeSlots; e++) {
      const lower = (g: number) => Math.min(mesh.heVertex[2 * g], mesh.heVertex[2 * g + 1]);
      expect(lower(e)).toBeGreaterThanOrEqual(lower(e - 1));
    }
  });

  it('keeps a mesh with every vertex in one place (one cell) or non-finite coordinates whole', () => {
    const { mesh } = buildMesh(uvSphere(3, 4));
    for (let v = 0; v < mesh.vertexSlots; v++) mesh.setPosition(v, v === 2 ? NaN : 1, 1, 1);
    const before = mesh.clone();
    const maps = spatialOrder(mesh);
    expectPermutation(maps.vertices, mesh.nVertices);
    expect(validate(mesh)).toEqual([]);
    expect(Number.isNaN(mesh.position(maps.vertices[2])[0])).toBe(true);
    expect(mesh.nFaces).toBe(before.nFaces);
  });
});

describe('renumber', () => {
  it('takes any permutation, and the inverse permutation gives the mesh back', () => {
    const { mesh } = buildMesh(torus(5, 4));
    const before = mesh.clone();
    const reversed = (n: number) => Int32Array.from({ length: n }, (_, i) => n - 1 - i);
    const maps = { vertices: reversed(mesh.vertexSlots), edges: reversed(mesh.edgeSlots), faces: reversed(mesh.faceSlots) };
    const arrays = meshArrays.map((spec) => mesh[spec.name]);
    mesh.renumber(maps);
    expect(validate(mesh)).toEqual([]);
    // with no slot to spare, every array is renumbered where it is
    meshArrays.forEach((spec, i) => expect(mesh[spec.name]).toBe(arrays[i]));
    expectSameMeshRenumbered(before, mesh, maps);
    mesh.renumber(maps); // reversing is its own inverse
    for (const spec of meshArrays) expect(mesh[spec.name]).toEqual(before[spec.name]);
    expect(mesh.positions).toEqual(before.positions);
  });

  it('refuses maps that are not a renumbering, changing nothing', () => {
    const { mesh } = buildMesh(torus(5, 4));
    const before = mesh.clone();
    const identity = (n: number) => Int32Array.from({ length: n }, (_, i) => i);
    const maps = () => ({ vertices: identity(mesh.vertexSlots), edges: identity(mesh.edgeSlots), faces: identity(mesh.faceSlots) });
    const twice = maps();
    twice.edges[3] = 2;
    expect(() => mesh.renumber(twice)).toThrow("renumber: e3's new id 2 is taken twice");
    const outside = maps();
    outside.faces[0] = mesh.faceSlots;
    expect(() => mesh.renumber(outside)).toThrow(`renumber: f0's new id ${mesh.faceSlots} is not in 0…${mesh.faceSlots - 1}`);
    expect(() => mesh.renumber({ ...maps(), vertices: identity(3) })).toThrow(`renumber: the map of v ids has 3 entries for ${mesh.vertexSlots} slots`);
    for (const spec of meshArrays) expect(mesh[spec.name]).toEqual(before[spec.name]);
    const gone = mesh.heVertex[1]; // collapsing e0 deletes the origin of its second halfedge
    collapseEdge(mesh, 0);
    expect(mesh.isVertexDeleted(gone)).toBe(true);
    expect(() => mesh.renumber(maps())).toThrow(`renumber: v${gone} is deleted, so its new id must be -1, not ${gone}`);
    expect(validate(mesh)).toEqual([]);
  });
});
