/**
 * The counts and checks a snapshot carries: everything that takes a pass over the whole mesh,
 * computed here in the worker so that the page's thread only shows them. After a change small
 * enough to patch, the exact counts come at once and the full pass on request (`details()`),
 * so the edit is drawn without waiting for it.
 */
import { type BuildReport, cannotDecimate, type HalfedgeMesh, meshStats, validate } from '../core/index.js';
import { cannotSmooth } from '../core/smoothing/index.js';
import { cannotSubdivide, subdivisionSchemes } from '../core/subdivision/index.js';
import type { Snapshot, SnapshotDetails } from './protocol.js';

export function fullDetails(mesh: HalfedgeMesh, report: BuildReport | null, version: number): SnapshotDetails {
  return {
    version,
    stats: meshStats(mesh, report ?? undefined),
    problems: validate(mesh, { limit: 200 }),
    unavailable: unavailable(mesh),
  };
}

/** The counts that follow from the slots (exact), the rest as the last full pass found them. */
export function patchedDetails(mesh: HalfedgeMesh, last: SnapshotDetails, version: number): Snapshot['details'] {
  const { nVertices: vertices, nEdges: edges, nFaces: faces } = mesh;
  const stats = { ...last.stats, vertices, edges, faces, halfedges: 2 * edges, eulerCharacteristic: vertices - edges + faces };
  return { ...last, version, stats, pending: true };
}

/** The checks of every face that the page would otherwise run on its thread. */
function unavailable(mesh: HalfedgeMesh): SnapshotDetails['unavailable'] {
  const reasons = Object.fromEntries(subdivisionSchemes.map((scheme) => [scheme, cannotSubdivide(mesh, scheme)]));
  return {
    ...reasons,
    cotan: cannotSmooth(mesh, { method: 'cotan' }),
    decimate: cannotDecimate(mesh),
  } as SnapshotDetails['unavailable'];
}
