import { describe, expect, it } from 'vitest';
import {
  canSplitEdge,
  canSplitEdgeTriangulated,
  canSplitFace,
  splitEdge,
  splitEdgeTriangulated,
  splitFace,
} from '../../src/core/edits/index.js';
import { TopologyError } from '../../src/core/errors.js';
import { cube, singleTriangle, strip, tetrahedron } from '../../src/core/shapes.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { checkedEdit, counts, degrees, edgeBetween, meshOf, triangleQuadPillow } from './helpers.js';

describe('splitEdge', () => {
  it('puts a vertex in the middle of a tetrahedron edge; the two triangles beside it become quads', () => {
    const mesh = meshOf(tetrahedron());
    const [a, b] = [mesh.heVertex[0], mesh.heVertex[1]];
    const { vertex, created, removed } = checkedEdit(mesh, (m) => splitEdge(m, 0));
    expect(counts(mesh)).toEqual([5, 7, 4]);
    expect(degrees(mesh)).toEqual({ 3: 2, 4: 2 });
    expect(mesh.position(vertex)).toEqual(mesh.position(a).map((x, i) => (x + mesh.position(b)[i]) / 2));
    expect(mesh.vertexDegree(vertex)).toBe(2);
    expect(created.vertices).toEqual(Int32Array.of(4));
    expect(created.edges).toEqual(Int32Array.of(6));
    expect(removed).toEqual({});
  });

  it('places the vertex at t along the edge and blends every vertex attribute the same way', () => {
    const mesh = meshOf(tetrahedron());
    const colour = mesh.vertexAttributes.add('colour', 'float32', 3);
    colour.data.set([1, 0, 0], 3 * mesh.heVertex[0]);
    colour.data.set([0, 0, 1], 3 * mesh.heVertex[1]);
    const [a, b] = [mesh.position(mesh.heVertex[0]), mesh.position(mesh.heVertex[1])];
    const { vertex } = checkedEdit(mesh, (m) => splitEdge(m, 0, { t: 0.25 }));
    expect(mesh.position(vertex)).toEqual(a.map((x, i) => 0.75 * x + 0.25 * b[i]));
    expect(Array.from(colour.data.subarray(3 * vertex, 3 * vertex + 3))).toEqual([0.75, 0, 0.25]);
  });

  it('blends the corner values (texture coordinates) of the faces beside the edge', () => {
    const mesh = meshOf(tetrahedron());
    const uv = mesh.halfedgeAttributes.add('uv', 'float32', 2);
    for (const h of mesh.halfedges()) uv.data.set([mesh.heVertex[h], 10 * mesh.heFace[h]], 2 * h);
    const [h, t] = [0, 1];
    const [afterH, afterT] = [mesh.heNext[h], mesh.heNext[t]];
    const expected = (a: number, b: number, s: number) => [0, 1].map((k) => (1 - s) * uv.data[2 * a + k] + s * uv.data[2 * b + k]);
    // the corner of the new vertex in each face: a quarter of the way from a to b
    const inFace0 = expected(h, afterH, 0.25);
    const inFace1 = expected(afterT, t, 0.25);
    const { created } = checkedEdit(mesh, (m) => splitEdge(m, 0, { t: 0.25 }));
    const g = 2 * created.edges![0];
    expect(Array.from(uv.data.subarray(2 * g, 2 * g + 2))).toEqual(inFace0.map(Math.fround));
    expect(Array.from(uv.data.subarray(2 * t, 2 * t + 2))).toEqual(inFace1.map(Math.fround));
  });

  it('gives a vertex on a boundary edge its boundary halfedge', () => {
    const mesh = meshOf(singleTriangle());
    const { vertex } = checkedEdit(mesh, (m) => splitEdge(m, 1));
    expect(mesh.isBoundaryVertex(vertex)).toBe(true);
    expect(degrees(mesh)).toEqual({ 4: 1 });
  });

  it('refuses t outside (0, 1)', () => {
    const mesh = meshOf(tetrahedron());
    expect(canSplitEdge(mesh, 2, 1)).toBe('t = 1 is not strictly between 0 and 1: the new vertex would not lie inside e2');
    expect(() => splitEdge(mesh, 2, { t: 0 })).toThrow(TopologyError);
  });
});

describe('splitEdgeTriangulated', () => {
  it('splits a tetrahedron edge and both triangles beside it: four triangles where there were two', () => {
    const mesh = meshOf(tetrahedron());
    const { vertex, created } = checkedEdit(mesh, (m) => splitEdgeTriangulated(m, 3));
    expect(counts(mesh)).toEqual([5, 9, 6]);
    expect(degrees(mesh)).toEqual({ 3: 6 });
    expect(mesh.vertexDegree(vertex)).toBe(4);
    expect(created.edges).toHaveLength(3);
    expect(created.faces).toHaveLength(2);
  });

  it('splits only the one triangle beside a boundary edge', () => {
    const mesh = meshOf(strip(2));
    const e = edgeBetween(mesh, 0, 2);
    const { vertex } = checkedEdit(mesh, (m) => splitEdgeTriangulated(m, e));
    expect(counts(mesh)).toEqual([7, 11, 5]);
    expect(degrees(mesh)).toEqual({ 3: 5 });
    expect(mesh.vertexDegree(vertex)).toBe(3);
    expect(mesh.isBoundaryVertex(vertex)).toBe(true);
  });

  it('refuses two triangles on the same three corners: the new vertex would be joined to the third twice', () => {
    // a pillow: the triangles (0 1 2) and (1 0 2) share all three edges
    const mesh = meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2], [1, 0, 2]]));
    const e = edgeBetween(mesh, 0, 1);
    expect(canSplitEdgeTriangulated(mesh, e)).toBe(`the triangles beside e${e} (f0, f1) have the same third corner v2: the new vertex would be joined to it twice`);
    expect(() => splitEdgeTriangulated(mesh, e)).toThrow(TopologyError);
    // the plain split still applies: it joins nothing
    checkedEdit(mesh, (m) => splitEdge(m, e));
  });

  it('refuses an edge beside a quad', () => {
    const mesh = meshOf(cube());
    expect(canSplitEdgeTriangulated(mesh, 0)).toMatch(/^f\d beside e0 has 4 sides: the triangulated split needs triangles \(use splitEdge\)$/);
  });
});

describe('splitFace', () => {
  it('cuts a cube face into two triangles along a diagonal', () => {
    const mesh = meshOf(cube());
    // face 0 is (0, 3, 2, 1)
    const { edge, created } = checkedEdit(mesh, (m) => splitFace(m, 0, 0, 2));
    expect(counts(mesh)).toEqual([8, 13, 7]);
    expect(degrees(mesh)).toEqual({ 3: 2, 4: 5 });
    expect([mesh.heVertex[2 * edge], mesh.heVertex[2 * edge + 1]]).toEqual([2, 0]);
    expect(mesh.heFace[2 * edge]).toBe(0);
    expect(created.faces).toEqual(Int32Array.of(6));
  });

  it('splits a hexagon three times into a fan of triangles around corner 0, each step valid', () => {
    const corners = [0, 1, 2, 3, 4, 5].flatMap((i) => [Math.cos((i * Math.PI) / 3), Math.sin((i * Math.PI) / 3), 0]);
    const mesh = meshOf(soupFromArrays(corners, [[0, 1, 2, 3, 4, 5]]));
    let f = 0;
    for (const v of [2, 3, 4]) {
      // f keeps the side from 0 round to v (a triangle now); the new face holds the rest
      checkedEdit(mesh, (m) => splitFace(m, f, 0, v));
      f = mesh.faceSlots - 1;
    }
    expect(counts(mesh)).toEqual([6, 9, 4]);
    expect(degrees(mesh)).toEqual({ 3: 4 });
    expect(mesh.vertexDegree(0)).toBe(5);
  });

  it('refuses neighbouring corners, the same corner, a vertex not on the face, and corners already joined', () => {
    const mesh = meshOf(cube());
    expect(canSplitFace(mesh, 0, 0, 3)).toMatch(/^v0 and v3 are neighbours on f0: the new edge would lie on e\d+$/);
    expect(canSplitFace(mesh, 0, 2, 2)).toBe('a face is split between two different corners, not v2 twice');
    expect(canSplitFace(mesh, 0, 0, 6)).toBe('v6 is not a corner of f0');
    const pillow = meshOf(triangleQuadPillow());
    expect(canSplitFace(pillow, 2, 0, 1)).toMatch(/^v0 and v1 are already joined by e\d+: a second edge between them is not allowed$/);
    expect(() => splitFace(pillow, 2, 0, 1)).toThrow(TopologyError);
  });
});
