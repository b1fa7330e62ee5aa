import { describe, expect, it } from 'vitest';
import { buildMesh, meshByteLength, positionsChange, smooth, subdivide, torus, uvSphere, validate } from '../../src/index.js';
import { History } from '../../src/workers/history.js';
import { applyEdit } from '../../src/workers/operations.js';
import { sphereWithFaces } from '../../bench/cases/sphere.js';
import { meshContents } from '../core/contents.js';


describe('History', () => {
  it('keeps each local edit as its change record, and gives every mesh back exactly', () => {
    const history = new History<null>();
    const mesh = buildMesh(uvSphere(40, 60)).mesh;
    history.pushMesh('open', mesh, null);
    const expected = [meshContents(mesh)];
    const edits = [
      { kind: 'poke-face', face: 10 },
      { kind: 'flip-edge', edge: 500 },
      { kind: 'split-edge', edge: 77 },
      { kind: 'collapse-edge', edge: 901 },
      { kind: 'poke-face', face: 1234 },
    ] as const;
    for (const edit of edits) {
      // in place, on the history's own current mesh
      const { record } = applyEdit(history.mesh()!, edit);
      history.pushChange(edit.kind, record!, null);
      expected.push(meshContents(history.mesh()!));
    }
    expect(history.mesh()).toBe(mesh);
    // one whole mesh and five records of a few hundred bytes each
    expect(history.bytes()).toBeLessThan(meshByteLength(mesh) + 5 * 2000);
    for (const index of [0, 3, 1, 5, 2, 4, 0, 5]) {
      history.moveTo(index);
      expect(meshContents(history.mesh()!), `entry ${index}`).toEqual(expected[index]);
      expect(validate(history.mesh()!)).toEqual([]);
    }
  });

  it('keeps a smoothing run as the positions it moved', () => {
    const history = new History<null>();
    const mesh = buildMesh(torus(20, 10)).mesh;
    history.pushMesh('open', mesh, null);
    const before = meshContents(mesh);
    const opened = history.bytes();
    const positions = mesh.positions.slice(0, 3 * mesh.vertexSlots);
    smooth(mesh, { method: 'laplacian', iterations: 2 });
    history.pushChange('smooth', positionsChange(mesh, positions), null);
    const after = meshContents(mesh);
    // old and new positions, nothing else
    expect(history.bytes()).toBe(opened + 2 * positions.byteLength);
    history.moveTo(0);
    expect(meshContents(history.mesh()!)).toEqual(before);
    history.moveTo(1);
    expect(meshContents(history.mesh()!)).toEqual(after);
  });

  it('keeps the whole mesh of an operation that changes everything, and the mesh before it where it was', () => {
    const history = new History<null>();
    const before = buildMesh(torus(20, 10)).mesh;
    history.pushMesh('open', before, null);
    const { record } = applyEdit(before, { kind: 'poke-face', face: 3 });
    history.pushChange('poke', record!, null);
    const poked = meshContents(before);
    const after = before.clone();
    subdivide(after, 'catmull-clark');
    history.pushMesh('subdivide', after, null);
    expect(history.mesh()).toBe(after);
    history.moveTo(1);
    expect(meshContents(history.mesh()!)).toEqual(poked);
    history.moveTo(0);
    expect(history.mesh()).toBe(before);
    expect(validate(before)).toEqual([]);
    history.moveTo(2);
    expect(history.mesh()).toBe(after);
    // an edit after going back drops the entries after it
    history.moveTo(0);
    history.pushChange('poke again', applyEdit(before, { kind: 'poke-face', face: 4 }).record!, null);
    expect(history.length).toBe(2);
  });

  it('holds a million-triangle mesh and a hundred edits in under 5% more than the mesh', () => {
    const history = new History<null>();
    const mesh = buildMesh(sphereWithFaces(1_000_000)).mesh;
    history.pushMesh('open', mesh, null);
    const one = history.bytes();
    for (let i = 0; i < 100; i++) {
      const { record } = applyEdit(mesh, i % 2 ? { kind: 'poke-face', face: 1000 * i } : { kind: 'flip-edge', edge: 7919 * i });
      history.pushChange(`edit ${i}`, record!, null);
    }
    expect(history.bytes()).toBeLessThan(1.05 * one);
  });
});
