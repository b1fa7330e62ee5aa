import { describe, expect, it } from 'vitest';
import {
  AttributeSet,
  buildMesh,
  cube,
  HalfedgeMesh,
  mergeSoups,
  meshStats,
  tetrahedron,
  torus,
  validate,
} from '../../src/index.js';
import { Scratch } from '../../src/core/permute.js';

/** Deletes every element of the connected component that contains face f. */
function deleteComponent(mesh: HalfedgeMesh, f: number): void {
  const faces = new Set([f]);
  const queue = [f];
  while (queue.length) {
    const g = queue.pop()!;
    let h = mesh.fHalfedge[g];
    do {
      const across = mesh.heFace[h ^ 1];
      if (across !== -1 && !faces.has(across)) {
        faces.add(across);
        queue.push(across);
      }
      h = mesh.heNext[h];
    } while (h !== mesh.fHalfedge[g]);
  }
  const vertices = new Set<number>();
  const edges = new Set<number>();
  for (const g of faces) {
    let h = mesh.fHalfedge[g];
    do {
      vertices.add(mesh.heVertex[h]);
      edges.add(h >> 1);
      h = mesh.heNext[h];
    } while (h !== mesh.fHalfedge[g]);
  }
  faces.forEach((g) => mesh.deleteFace(g));
  edges.forEach((e) => mesh.deleteEdge(e));
  vertices.forEach((v) => mesh.deleteVertex(v));
}

describe('HalfedgeMesh storage', () => {
  it('grows its capacity as elements are added, keeping what it had', () => {
    const { mesh } = buildMesh(tetrahedron());
    const before = mesh.heNext.slice();
    for (let i = 0; i < 100; i++) mesh.addVertex(i, 2 * i, 3 * i);
    for (let i = 0; i < 50; i++) mesh.addEdge();
    for (let i = 0; i < 30; i++) mesh.addFace();
    expect(mesh.vertexSlots).toBe(104);
    expect(mesh.edgeSlots).toBe(56);
    expect(mesh.faceSlots).toBe(34);
    expect(mesh.heNext.length).toBeGreaterThanOrEqual(112);
    expect(Array.from(mesh.heNext.subarray(0, 12))).toEqual(Array.from(before));
    expect(mesh.position(103)).toEqual([99, 198, 297]);
  });

  it('compacts away a deleted component, renumbering in order, and stays valid', () => {
    const { mesh } = buildMesh(mergeSoups([tetrahedron(), cube(), torus(4, 3)]));
    deleteComponent(mesh, 4); // the cube's first face
    expect(validate(mesh)).toEqual([]);
    expect(mesh.nFaces).toBe(4 + 12);
    expect(mesh.isCompact).toBe(false);
    const torusPosition = mesh.position(12);
    const maps = mesh.compact();
    expect(mesh.isCompact).toBe(true);
    expect(validate(mesh)).toEqual([]);
    expect(Array.from(maps.faces.subarray(0, 11))).toEqual([0, 1, 2, 3, -1, -1, -1, -1, -1, -1, 4]);
    expect(maps.vertices[12]).toBe(4);
    expect(mesh.position(4)).toEqual(torusPosition);
    const stats = meshStats(mesh);
    expect([stats.vertices, stats.faces, stats.components, stats.genus]).toEqual([4 + 12, 4 + 12, 2, 1]);
    expect(mesh.heNext.length).toBe(mesh.halfedgeSlots);
  });

  it('trims the spare room growth left, keeping every element', () => {
    const { mesh } = buildMesh(tetrahedron());
    mesh.addVertex(1, 2, 3);
    expect(mesh.vHalfedge.length).toBeGreaterThan(5);
    mesh.trim();
    expect([mesh.vHalfedge.length, mesh.positions.length, mesh.vDeleted.length]).toEqual([5, 15, 5]);
    expect(mesh.position(4)).toEqual([1, 2, 3]);
    expect(validate(mesh)).toEqual([]);
  });

  it('clones deeply: editing the copy leaves the original alone', () => {
    const { mesh } = buildMesh(cube());
    mesh.vertexAttributes.add('weight', 'float32', 1).data.fill(7);
    const copy = mesh.clone();
    copy.setPosition(0, 5, 5, 5);
    copy.heNext[0] = 3;
    copy.vertexAttributes.get('weight')!.data[0] = 1;
    expect(mesh.position(0)).toEqual([0, 0, 0]);
    expect(validate(mesh)).toEqual([]);
    expect(mesh.vertexAttributes.get('weight')!.data[0]).toBe(7);
  });
});

describe('AttributeSet', () => {
  it('blends linear attributes, copies discrete ones, and rounds integer colours', () => {
    const set = new AttributeSet(4);
    const uv = set.add('uv', 'float32', 2);
    const colour = set.add('color', 'uint8', 3, 'linear');
    const label = set.add('label', 'int32', 1);
    uv.data.set([0, 0, 1, 1]);
    colour.data.set([0, 0, 0, 255, 255, 255]);
    label.data.set([10, 20]);
    set.blend(2, [0, 1], [0.25, 0.75]);
    expect(Array.from(uv.data.subarray(4, 6))).toEqual([0.75, 0.75]);
    expect(Array.from(colour.data.subarray(6, 9))).toEqual([191, 191, 191]);
    expect(label.data[2]).toBe(10);
  });

  it('refuses an attribute of the same name but another shape', () => {
    const set = new AttributeSet(1);
    set.add('color', 'uint8', 3);
    expect(set.add('color', 'uint8', 3)).toBe(set.get('color'));
    expect(() => set.add('color', 'float32', 3)).toThrow(/already exists as uint8 × 3/);
  });

  it('follows compaction and growth', () => {
    const set = new AttributeSet(3);
    const a = set.add('a', 'float64', 1);
    a.data.set([1, 2, 3]);
    const scratch = new Scratch();
    set.permute(Int32Array.from([1, -1, 0]), 2, scratch);
    expect(Array.from(set.get('a')!.data)).toEqual([3, 1]);
    // nothing dropped: the same array, renumbered in place
    const data = set.get('a')!.data;
    set.permute(Int32Array.from([1, 0]), 2, scratch);
    expect(set.get('a')!.data).toBe(data);
    expect(Array.from(data)).toEqual([1, 3]);
    set.resize(5, 2);
    expect(Array.from(set.get('a')!.data)).toEqual([1, 3, 0, 0, 0]);
  });
});

describe('mergeSoups', () => {
  it('shifts the vertex ids of each soup and keeps attributes all of them share', () => {
    const a = tetrahedron();
    const b = cube();
    a.vertexAttributes = [{ name: 'id', itemSize: 1, data: new Int32Array([1, 2, 3, 4]) }];
    b.vertexAttributes = [{ name: 'id', itemSize: 1, data: new Int32Array(8).fill(9) }];
    const merged = mergeSoups([a, b]);
    expect(merged.faceStarts.length).toBe(11);
    expect(Array.from(merged.faceIndices.subarray(12, 16))).toEqual([4, 7, 6, 5]);
    expect(Array.from(merged.vertexAttributes![0]!.data)).toEqual([1, 2, 3, 4, 9, 9, 9, 9, 9, 9, 9, 9]);
    expect(mergeSoups([a, cube()]).vertexAttributes).toBeUndefined();
  });
});
