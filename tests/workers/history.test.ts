import { describe, expect, it } from 'vitest';
import { buildMesh, type HalfedgeMesh, serializeMesh, smooth, subdivide, torus, uvSphere, validate } from '../../src/index.js';
import { History } from '../../src/workers/history.js';
import { meshContents } from '../core/contents.js';
import { applyEdit } from '../../src/workers/operations.js';
import { sphereWithFaces } from '../../bench/cases/build.js';

/** Every array of a mesh, as plain arrays, to compare two meshes exactly. */
const arrays = meshContents;

const meshBytes = (mesh: HalfedgeMesh) => {
  const s = serializeMesh(mesh);
  return [s.heNext, s.hePrev, s.heVertex, s.heFace, s.vHalfedge, s.fHalfedge, s.vDeleted, s.eDeleted, s.fDeleted, ...Object.values(s.attributes).flat().map((a) => a.data)].reduce((n, a) => n + a.byteLength, 0);
};

describe('History', () => {
  it('keeps a few bytes for each local edit, and gives every mesh back exactly', () => {
    const history = new History<null>();
    let mesh = buildMesh(uvSphere(40, 60)).mesh;
    history.push('open', mesh, null);
    const expected = [arrays(mesh)];
    const edits = [
      { kind: 'poke-face', face: 10 },
      { kind: 'flip-edge', edge: 500 },
      { kind: 'split-edge', edge: 77 },
      { kind: 'collapse-edge', edge: 901 },
      { kind: 'poke-face', face: 1234 },
    ] as const;
    for (const edit of edits) {
      mesh = mesh.clone();
      applyEdit(mesh, edit);
      history.push(edit.kind, mesh, null);
      expected.push(arrays(mesh));
    }
    // one whole mesh, five small differences (and the current mesh, kept whole)
    expect(history.bytes()).toBeLessThan(2.1 * meshBytes(mesh));
    for (const index of [0, 3, 1, 5, 2, 4]) {
      history.moveTo(index);
      expect(arrays(history.mesh()!), `entry ${index}`).toEqual(expected[index]);
      expect(validate(history.mesh()!)).toEqual([]);
    }
  });

  it('shares the connectivity of a smoothed mesh with the mesh before it', () => {
    const history = new History<null>();
    const before = buildMesh(torus(20, 10)).mesh;
    history.push('open', before, null);
    const after = before.clone();
    smooth(after, { method: 'laplacian', iterations: 2 });
    history.push('smooth', after, null);
    expect(after.heNext).toBe(before.heNext);
    expect(after.positions).not.toBe(before.positions);
    const positions = after.positions.byteLength;
    // the mesh and the new positions (which the difference shares)
    expect(history.bytes()).toBe(meshBytes(before) + positions);
    history.moveTo(0);
    expect(arrays(history.mesh()!)).toEqual(arrays(before));
  });

  it('keeps the whole mesh of an operation that changes everything', () => {
    const history = new History<null>();
    const before = buildMesh(torus(20, 10)).mesh;
    history.push('open', before, null);
    const after = before.clone();
    subdivide(after, 'catmull-clark');
    history.push('subdivide', after, null);
    expect(history.bytes()).toBe(meshBytes(before) + meshBytes(after));
    history.moveTo(0);
    expect(arrays(history.mesh()!)).toEqual(arrays(before));
    history.moveTo(1);
    expect(history.mesh()).toBe(after);
  });

  it('holds a million-triangle mesh and five edits in not much more than two meshes', () => {
    const history = new History<null>();
    let mesh = buildMesh(sphereWithFaces(1_000_000)).mesh;
    const one = meshBytes(mesh);
    history.push('open', mesh, null);
    for (let i = 0; i < 5; i++) {
      mesh = mesh.clone();
      applyEdit(mesh, { kind: 'poke-face', face: 1000 * i });
      history.push(`poke ${i}`, mesh, null);
    }
    // five full copies would be six meshes' worth
    expect(history.bytes()).toBeLessThan(2.05 * one);
  });
});
