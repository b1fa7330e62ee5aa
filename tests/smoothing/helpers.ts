/** Fixtures and checks shared by the smoothing tests. */
import { expect } from 'vitest';
import { buildMesh } from '../../src/core/build.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { type Phase, type PhaseElements, phaseElements } from '../../src/core/change/operation.js';
import { type SmoothingOptions, smoothing } from '../../src/core/smoothing/index.js';
import { seededRandom } from '../../src/core/random.js';
import type { PolygonSoup } from '../../src/core/soup.js';
import { validate } from '../../src/core/validate.js';

export function meshOf(soup: PolygonSoup): HalfedgeMesh {
  const { mesh, report } = buildMesh(soup);
  expect(report.repairs).toEqual([]);
  return mesh;
}

/** Moves every vertex by up to `amount` along each axis (`axes` of them: 2 keeps z), seeded. */
export function addNoise(mesh: HalfedgeMesh, seed: number, amount: number, axes = 3, only?: (v: number) => boolean): void {
  const next = seededRandom(seed);
  const p = mesh.positions;
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (only && !only(v)) continue;
    for (let k = 0; k < axes; k++) p[3 * v + k] += amount * (2 * next() - 1);
  }
}

/** The connectivity arrays, copied, to check that smoothing leaves them alone. */
export function connectivity(mesh: HalfedgeMesh): Int32Array[] {
  return [mesh.heNext, mesh.hePrev, mesh.heVertex, mesh.heFace, mesh.vHalfedge, mesh.fHalfedge].map((a) => a.slice());
}

/** Steps through the smoothing, checking the mesh after every phase; returns the phases. */
export function stepSmoothing(mesh: HalfedgeMesh, options: SmoothingOptions): Array<Phase & PhaseElements> {
  const phases: Array<Phase & PhaseElements> = [];
  for (const phase of smoothing(mesh, options)) {
    expect(validate(mesh), `after "${phase.name}"`).toEqual([]);
    phases.push({ ...phase, ...phaseElements(phase.change!) });
  }
  return phases;
}

/** Largest distance between the same vertex in two position arrays. */
export function largestMove(before: Float64Array, after: Float64Array): number {
  let worst = 0;
  for (let i = 0; i < before.length; i += 3) {
    worst = Math.max(worst, Math.hypot(after[i] - before[i], after[i + 1] - before[i + 1], after[i + 2] - before[i + 2]));
  }
  return worst;
}
