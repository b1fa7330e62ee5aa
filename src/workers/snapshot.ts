/**
 * The counts and checks a snapshot carries: everything that takes a pass over the whole mesh,
 * computed here in the worker so that the page's thread only shows them. After a change small
 * enough to patch, what the change's record tells exactly comes at once (the counts of elements,
 * χ, the boundary edges, the check of what the change touched) and the full pass on request
 * (`details()`), so the edit is drawn, and checked, without waiting for it.
 */
import {
  boundaryEdgesChange,
  type BuildReport,
  cannotDecimate,
  type ChangeRecord,
  geometryStats,
  type HalfedgeMesh,
  meshStats,
  validate,
  validateChange,
} from '../core/index.js';
import { cannotRemesh } from '../core/remeshing/index.js';
import { cannotSmooth } from '../core/smoothing/index.js';
import { cannotSubdivide, subdivisionSchemes } from '../core/subdivision/index.js';
import type { SnapshotDetails } from './protocol.js';

/** Violations a snapshot lists at most. */
const PROBLEMS_LIMIT = 200;

export function fullDetails(mesh: HalfedgeMesh, report: BuildReport | null, version: number): SnapshotDetails {
  return {
    version,
    stats: meshStats(mesh, report ?? undefined),
    problems: validate(mesh, { limit: PROBLEMS_LIMIT }),
    unavailable: unavailable(mesh),
  };
}

/**
 * The details after `change`, from those of the snapshot before it (`previous`): V, E, F, χ and
 * the boundary edges exact, the problems those the local check finds where the change wrote; the
 * rest (boundary loops, components, genus, the operations that apply) as the last full pass found
 * them, for `details()` to bring up to date.
 */
export function patchedDetails(mesh: HalfedgeMesh, change: ChangeRecord, previous: SnapshotDetails, version: number): SnapshotDetails {
  const { nVertices: vertices, nEdges: edges, nFaces: faces } = mesh;
  // a phase that rewrote whole ranges (a subdivision step) touched everything: its check is the
  // full pass, which comes after, and the boundary edges are counted rather than followed
  const bulk = change.ranges.length > 0;
  const stats = {
    ...previous.stats,
    vertices,
    edges,
    faces,
    halfedges: 2 * edges,
    eulerCharacteristic: vertices - edges + faces,
    boundaryEdges: bulk ? boundaryEdgeCount(mesh) : previous.stats.boundaryEdges + boundaryEdgesChange(mesh, change),
  };
  // The local check vouches for the whole mesh only when the mesh before was sound. One that was
  // not (a practice state) keeps the problems it had, unchecked, until the full pass: simpler than
  // sorting out which of them the change may have mended, and they are marked pending.
  const problems = previous.problems.length > 0 || bulk ? previous.problems : validateChange(mesh, change, { limit: PROBLEMS_LIMIT });
  return { ...previous, version, stats, problems };
}

/**
 * The full details of a mesh whose connectivity is that of `previous`'s full pass (only vertices
 * moved since): the counts, checks and operations that apply as they were, the measures of the
 * surface taken again. A pass over the positions, not over everything.
 */
export function movedDetails(mesh: HalfedgeMesh, previous: SnapshotDetails, version: number): SnapshotDetails {
  return { ...previous, version, stats: { ...previous.stats, ...geometryStats(mesh, previous.stats.closed) } };
}

/** The live edges with a side that has no face. */
function boundaryEdgeCount(mesh: HalfedgeMesh): number {
  const { heFace, eDeleted } = mesh;
  let count = 0;
  for (let e = 0; e < mesh.edgeSlots; e++) if (!eDeleted[e] && (heFace[2 * e] === -1 || heFace[2 * e + 1] === -1)) count++;
  return count;
}

/** The checks of every face that the page would otherwise run on its thread. */
function unavailable(mesh: HalfedgeMesh): SnapshotDetails['unavailable'] {
  const reasons = Object.fromEntries(subdivisionSchemes.map((scheme) => [scheme, cannotSubdivide(mesh, scheme)]));
  return {
    ...reasons,
    cotan: cannotSmooth(mesh, { method: 'cotan' }),
    decimate: cannotDecimate(mesh),
    remesh: cannotRemesh(mesh),
  } as SnapshotDetails['unavailable'];
}
