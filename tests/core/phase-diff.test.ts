/**
 * A phase's pointer diff is read off what the phase says it created, rewired and removed: for every
 * phase of every stepped operation, on closed and open meshes, it equals what a comparison of the
 * whole mesh before and after finds.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, cannotDecimate, collapseEdge, diffPointers, triangulateMesh, disk, type HalfedgeMesh, phaseDiff, pointerCopy, torus, uvSphere } from '../../src/index.js';
import { cannotRemesh } from '../../src/core/remeshing/index.js';
import { cannotSubdivide, subdivisionSchemes } from '../../src/core/subdivision/index.js';
import { type OperationRequest, startOperation } from '../../src/workers/operations.js';

const meshes: Array<[string, () => HalfedgeMesh]> = [
  ['a sphere of triangles and quads', () => buildMesh(uvSphere(6, 8)).mesh],
  ['a torus of quads', () => buildMesh(torus(6, 5)).mesh],
  ['a disk (open)', () => buildMesh(disk(3)).mesh],
  // deleted slots among the live ones, as after an edit: a phase's lists must not trip over them
  [
    'a sphere after two collapses',
    () => {
      const { mesh } = buildMesh(uvSphere(6, 8));
      triangulateMesh(mesh);
      for (const e of [7, 30]) collapseEdge(mesh, e);
      return mesh;
    },
  ],
];

const requests: OperationRequest[] = [
  ...subdivisionSchemes.map((scheme) => ({ kind: 'subdivide' as const, scheme, level: 0 })),
  ...subdivisionSchemes.map((scheme) => ({ kind: 'subdivide' as const, scheme, level: 1 })),
  { kind: 'cut', plane: [0.3, 0.2, 1, 0.1] },
  { kind: 'cut', plane: [0.3, 0.2, 1, 0.1], cap: true },
  { kind: 'decimate', options: { targetFaces: 40 } },
  { kind: 'smooth', options: { method: 'laplacian', iterations: 2 } },
  { kind: 'remesh', options: { iterations: 2 } },
  { kind: 'remesh', options: { iterations: 1, targetEdgeLength: 0.2 } },
];

/** Whether an operation applies to a mesh: Loop, √3, Butterfly, decimation and remeshing need triangles. */
function applies(mesh: HalfedgeMesh, request: OperationRequest): boolean {
  if (request.kind === 'subdivide') return cannotSubdivide(mesh, request.scheme) === null;
  if (request.kind === 'decimate') return cannotDecimate(mesh) === null;
  if (request.kind === 'remesh') return cannotRemesh(mesh) === null;
  return true;
}

const cases = meshes.flatMap(([name, make]) => requests.filter((request) => applies(make(), request)).map((request) => [name, request, make] as const));

describe('the pointer diff of a phase', () => {
  it('is checked on every stepped operation', () => {
    expect(new Set(cases.map(([, request]) => request.kind === 'subdivide' ? request.scheme : request.kind))).toEqual(
      new Set([...subdivisionSchemes, 'cut', 'decimate', 'smooth', 'remesh']),
    );
  });

  it.each(cases)('is what the whole comparison finds, on %s: %j', (_, request, make) => {
    const mesh = make();
    const { operation } = startOperation(mesh, request);
    let phases = 0;
    for (;;) {
      const before = pointerCopy(mesh);
      const next = operation.next();
      if (next.done) break;
      phases++;
      expect(phaseDiff(before, mesh, next.value, Infinity), `phase ${phases}: ${next.value.name}`).toEqual(diffPointers(before, mesh, Infinity));
    }
    expect(phases).toBeGreaterThan(0);
  });
});
