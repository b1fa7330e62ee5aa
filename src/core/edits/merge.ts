/**
 * Merge faces (erase an edge): the two faces beside edge e become one; e is deleted, and so is
 * the face on its `2e + 1` side (the face on the `2e` side keeps its id and attributes).
 *
 * ```
 *      d ◄──────── c ◄──────── x          d ◄──────── c ◄──────── x
 *      │           ▲           ▲          │                       ▲
 *      │    f0     h   f1      │   ──►    │          f0           │
 *      ▼           │           │          ▼                       │
 *      a ────────► b ────────► y          a ────────► b ────────► y
 * ```
 * (here h = 2e runs b → c with f0 on its left.) What is allowed: two *different* faces that share
 * this one edge and no other corner than its two ends. Refused: a boundary edge (only one face),
 * an edge with the same face on both sides, and two faces that also share another corner: the
 * merged face would pass through that vertex twice, touching itself there (or, when they share
 * another edge too, bordering itself along a dangling edge) — a face no file can hold, and one
 * that later edits cannot take apart. The merged face may be non-convex or non-planar.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingEdge } from './find.js';
import { PointerWriter, type EditOptions, type EditResult } from './writer.js';

export interface MergeResult extends EditResult {
  /** The merged face (the one that was on the `2e` side). */
  face: number;
}

/** Why the faces beside edge `e` cannot be merged, or null when they can (rules above). */
export function canMergeFaces(mesh: HalfedgeMesh, e: number): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  const { heNext, heVertex, heFace } = mesh;
  const h = 2 * e;
  const f0 = heFace[h];
  const f1 = heFace[h + 1];
  if (f0 === -1 || f1 === -1) return `e${e} is on the boundary: there is no second face to merge f${f0 === -1 ? f1 : f0} with`;
  if (f0 === f1) return `e${e} has f${f0} on both sides: there is nothing to merge`;
  // every corner of f0 but the two ends of e (the loop from h starts at them), against every
  // corner of f1 but those: faces are small, and this asks no memory
  for (let g = heNext[heNext[h]], i = 0; g !== h && i < mesh.halfedgeSlots; g = heNext[g], i++) {
    const v = heVertex[g];
    for (let k = heNext[heNext[h + 1]], j = 0; k !== h + 1 && j < mesh.halfedgeSlots; k = heNext[k], j++) {
      if (heVertex[k] === v) {
        return `f${f0} and f${f1} also share v${v}: the merged face would pass through v${v} twice`;
      }
    }
  }
  return null;
}

/**
 * Erases edge `e`, merging its two faces into the one on the `2e` side.
 * @example const { face } = mergeFaces(mesh, e); // two triangles → one quad
 * @throws TopologyError with `canMergeFaces`'s sentence when the merge does not apply.
 */
export function mergeFaces(mesh: HalfedgeMesh, e: number, options: EditOptions = {}): MergeResult {
  const why = canMergeFaces(mesh, e);
  if (why) throw new TopologyError(`mergeFaces: ${why}`);
  const w = new PointerWriter(mesh, options);
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  const h = 2 * e;
  const t = h + 1;
  const f0 = heFace[h];
  const f1 = heFace[t];
  const afterH = heNext[h];
  const afterT = heNext[t];

  // f1's other halfedges join f0
  for (let g = afterT; g !== t; g = heNext[g]) w.setFace(g, f0);
  w.link(hePrev[h], afterT);
  w.link(hePrev[t], afterH);
  if (fHalfedge[f0] === h) w.setFaceHalfedge(f0, afterH);
  // the ends of e keep a live handle (an interior one: e had faces on both sides, so neither
  // handle was on e if its vertex is on the boundary)
  if (vHalfedge[heVertex[h]] === h) w.setVertexHalfedge(heVertex[h], afterT);
  if (vHalfedge[heVertex[t]] === t) w.setVertexHalfedge(heVertex[t], afterH);
  w.deleteEdge(e);
  w.deleteFace(f1);
  return { ...w.result(), face: f0 };
}
