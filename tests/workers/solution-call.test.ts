import { describe, expect, it } from 'vitest';
import { buildMesh, cube, meanEdgeLength, uvSphere } from '../../src/core/index.js';
import { exercises } from '../../src/core/practice/index.js';
import { solutionCall } from '../../src/workers/operations.js';
import type { EditRequest, OperationRequest } from '../../src/workers/operations.js';

describe('the exercise whose solution does an app request ("Use my code")', () => {
  const sphere = buildMesh(uvSphere(6, 8)).mesh;
  const edit = (request: EditRequest) => solutionCall(sphere, { verb: 'edit', request });
  const start = (request: OperationRequest) => solutionCall(sphere, { verb: 'start', request });

  it('is there for every edit exercise, called with the numbers the library would use', () => {
    const requests: Array<[string, ReturnType<typeof edit>]> = [
      ['flip-edge', edit({ kind: 'flip-edge', edge: 4 })],
      ['split-edge', edit({ kind: 'split-edge', edge: 4, triangulate: true })],
      ['collapse-edge', edit({ kind: 'collapse-edge', edge: 4 })],
      ['inset-vertex', edit({ kind: 'poke-face', face: 2 })],
      ['extrude-face', edit({ kind: 'extrude-face', face: 2, inset: 0.1 })],
      ['bevel-vertex', edit({ kind: 'bevel-vertex', vertex: 3 })],
      ['bevel-edge', edit({ kind: 'bevel-edge', edge: 4, amount: 0.4 })],
      ['dissolve-edge', edit({ kind: 'dissolve-edge', edge: 4 })],
      ['dissolve-vertex', edit({ kind: 'dissolve-vertex', vertex: 3 })],
      ['collapse-face', edit({ kind: 'collapse-face', face: 2 })],
      ['make-boundary', edit({ kind: 'make-boundary', face: 2 })],
      ['weld-edges', edit({ kind: 'weld-edges', edges: [1, 5] })],
      ['triangulate', edit({ kind: 'triangulate-mesh' })],
      ['loop-subdivision', start({ kind: 'subdivide', scheme: 'loop' })],
      ['catmull-clark', start({ kind: 'subdivide', scheme: 'catmull-clark' })],
      ['linear-subdivision', start({ kind: 'subdivide', scheme: 'linear' })],
      ['isotropic-remesh', start({ kind: 'remesh', options: { iterations: 2 } })],
      ['simplify', start({ kind: 'decimate', options: { targetFaces: 40 } })],
    ];
    expect(requests.map(([id]) => id).sort()).toEqual(exercises.filter((e) => e.kind === 'edit').map((e) => e.id).sort());
    for (const [id, call] of requests) expect(call?.exercise, id).toBe(id);
    const inputs = Object.fromEntries(requests.map(([id, call]) => [id, call!.input]));
    expect(inputs['flip-edge']).toBe(4);
    expect(inputs['weld-edges']).toEqual([1, 5]);
    expect(inputs['triangulate']).toBeUndefined();
    // the library's defaults: a bevel a quarter of the way, an extrusion half the face's mean side out
    expect(inputs['bevel-vertex']).toEqual({ vertex: 3, amount: 0.25 });
    expect(inputs['bevel-edge']).toEqual({ edge: 4, amount: 0.4 });
    const extrude = inputs['extrude-face'] as { face: number; offset: number; inset: number };
    expect(extrude).toMatchObject({ face: 2, inset: 0.1 });
    expect(extrude.offset).toBeGreaterThan(0);
    expect(inputs['isotropic-remesh']).toEqual({ targetEdgeLength: meanEdgeLength(sphere), iterations: 2 });
    expect(inputs['simplify']).toEqual({ faces: 40 });
    expect(start({ kind: 'decimate', options: {} })!.input).toEqual({ faces: Math.floor(sphere.nFaces / 2) });
    expect(edit({ kind: 'flip-edge', edge: 4 })!.label).toBe('flip e4');
    expect(start({ kind: 'subdivide', scheme: 'loop' })!.label).toMatch(/Loop/);
  });

  it('is none for a request no exercise sets', () => {
    const quads = buildMesh(cube()).mesh;
    expect(edit({ kind: 'split-edge', edge: 4 })).toBeNull(); // the exercise splits the triangles too
    expect(edit({ kind: 'split-face', face: 0, from: 0, to: 2 })).toBeNull();
    expect(edit({ kind: 'erase-edge', edge: 4 })).toBeNull();
    expect(start({ kind: 'subdivide', scheme: 'butterfly' })).toBeNull();
    expect(start({ kind: 'cut', plane: [0, 1, 0, 0] })).toBeNull();
    expect(start({ kind: 'smooth', options: { method: 'laplacian' } })).toBeNull();
    expect(start({ kind: 'decimate', options: { maxError: 0.01 } })).toBeNull();
    expect(solutionCall(quads, { verb: 'edit', request: { kind: 'triangulate-face', face: 0 } })).toBeNull();
  });
});
