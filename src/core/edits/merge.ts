/**
 * Merge faces (erase an edge): the old name of `dissolveEdge` (see `dissolve.ts`) for interior
 * edges. The two faces beside edge e become one; e is deleted, and so is the face on its `2e + 1`
 * side (the face on the `2e` side keeps its id and attributes).
 *
 * ```
 *      d ◄──────── c ◄──────── x          d ◄──────── c ◄──────── x
 *      │           ▲           ▲          │                       ▲
 *      │    f0     h   f1      │   ──►    │          f0           │
 *      ▼           │           │          ▼                       │
 *      a ────────► b ────────► y          a ────────► b ────────► y
 * ```
 * Unlike `dissolveEdge`, it refuses a boundary edge (there is no second face to merge with),
 * which is what the app's "erase edge" offers. Refused too, as by `dissolveEdge`: an edge with the
 * same face on both sides, and two faces that also share another corner (the merged face would
 * pass through it twice).
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { mergeAcrossAt, whyNotMergeAcross } from './dissolve.js';
import { missingEdge } from './find.js';
import { type EditOptions, type FaceEditResult, PointerWriter } from '../change/writer.js';

/** What `mergeFaces` returns: the merged face (the one that was on the `2e` side). */
export type MergeResult = FaceEditResult;

/** Why the faces beside edge `e` cannot be merged, or null when they can (rules above). */
export function canMergeFaces(mesh: HalfedgeMesh, e: number): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  const f0 = mesh.heFace[2 * e];
  const f1 = mesh.heFace[2 * e + 1];
  if (f0 === -1 || f1 === -1) return `e${e} is on the boundary: there is no second face to merge f${f0 === -1 ? f1 : f0} with`;
  return whyNotMergeAcross(mesh, e);
}

/**
 * Erases interior edge `e`, merging its two faces into the one on the `2e` side: `dissolveEdge`
 * on an interior edge, the same change and result.
 * @example const { face } = mergeFaces(mesh, e); // two triangles → one quad
 * @throws TopologyError with `canMergeFaces`'s sentence when the merge does not apply.
 */
export function mergeFaces(mesh: HalfedgeMesh, e: number, options: EditOptions = {}): MergeResult {
  const why = canMergeFaces(mesh, e);
  if (why) throw new TopologyError(`mergeFaces: ${why}`);
  const w = new PointerWriter(mesh, options);
  const face = mergeAcrossAt(w, e);
  return { ...w.result(), face };
}
