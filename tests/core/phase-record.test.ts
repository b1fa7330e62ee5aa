/**
 * Every phase of every stepped operation carries its change record, written as it wrote: on closed
 * and open meshes, the pointer diff read off the record equals what a comparison of the whole mesh
 * before and after finds, the record applied backwards gives back the mesh before (fingerprint and
 * all) and forwards again the mesh after, and what it marks as moved is every vertex that moved.
 */
import { describe, expect, it } from 'vitest';
import { applyChange, buildMesh, cannotDecimate, collapseEdge, diffPointers, disk, type HalfedgeMesh, meshFingerprint, phaseElements, pointerDiffOf, torus, triangulateMesh, uvSphere } from '../../src/index.js';
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

describe('the record of a phase', () => {
  it('is checked on every stepped operation', () => {
    expect(new Set(cases.map(([, request]) => request.kind === 'subdivide' ? request.scheme : request.kind))).toEqual(
      new Set([...subdivisionSchemes, 'cut', 'decimate', 'smooth', 'remesh']),
    );
  });

  it.each(cases)('is the change the phase made, on %s: %j', (_, request, make) => {
    const mesh = make();
    const { operation } = startOperation(mesh, request);
    let phases = 0;
    for (;;) {
      const before = mesh.clone();
      const next = operation.next();
      if (next.done) break;
      phases++;
      const name = `phase ${phases}: ${next.value.name}`;
      const change = next.value.change!;
      expect(pointerDiffOf(change, Infinity), name).toEqual(diffPointers(before, mesh, Infinity));
      const moved = [...before.vertices()].filter((v) => [0, 1, 2].some((k) => before.positions[3 * v + k] !== mesh.positions[3 * v + k]) && !mesh.vDeleted[v]);
      expect(Array.from(phaseElements(change).moved.vertices ?? []), name).toEqual(moved);
      const copy = mesh.clone();
      applyChange(copy, change, 'backward');
      expect(meshFingerprint(copy), name).toBe(meshFingerprint(before));
      applyChange(copy, change, 'forward');
      expect(meshFingerprint(copy), name).toBe(meshFingerprint(mesh));
    }
    expect(phases).toBeGreaterThan(0);
  });
});
