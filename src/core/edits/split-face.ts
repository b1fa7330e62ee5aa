/**
 * Face split: a new edge between two corners of a face cuts it in two. The face keeps the side
 * that runs from `u` round to `v`; a new face takes the side from `v` round to `u`.
 *
 * ```
 *      v ◄──────── x            v ◄──────── x
 *      │           ▲            │ ╲   f     ▲
 *      │     f     │    ──►     │   ╲       │        new edge: g = v → u (in f),
 *      ▼           │            ▼ f'  ╲     │                  twin(g) = u → v (in f')
 *      y ────────► u            y ────────► u
 * ```
 * Only the new edge's halfedges, the two `next` links into them, and the faces of the halfedges
 * that move to the new face change: O(degree of the face).
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { faceHalfedgeFrom, halfedgeFromTo, missingFace } from './find.js';
import { type EditOptions, type EditResult, PointerWriter } from '../change/writer.js';

export interface FaceSplitResult extends EditResult {
  /** The new edge; its halfedge `2 · edge` runs from `v` to `u` in the old face. */
  edge: number;
}

/**
 * Why face `f` cannot be split between its corners `u` and `v`, or null when it can. Refused:
 * corners not on `f`, the same corner twice, neighbouring corners (the new edge would lie on an
 * existing one), and corners already joined by an edge elsewhere.
 */
export function canSplitFace(mesh: HalfedgeMesh, f: number, u: number, v: number): string | null {
  const missing = missingFace(mesh, f);
  if (missing) return missing;
  if (u === v) return `a face is split between two different corners, not v${u} twice`;
  const hu = faceHalfedgeFrom(mesh, f, u);
  const hv = faceHalfedgeFrom(mesh, f, v);
  for (const [x, hx] of [
    [u, hu],
    [v, hv],
  ]) {
    if (hx === -1) return `v${x} is not a corner of f${f}`;
  }
  const { heNext, heVertex } = mesh;
  if (heVertex[heNext[hu]] === v || heVertex[heNext[hv]] === u) {
    return `v${u} and v${v} are neighbours on f${f}: the new edge would lie on e${(heVertex[heNext[hu]] === v ? hu : hv) >> 1}`;
  }
  const existing = halfedgeFromTo(mesh, u, v);
  if (existing !== -1) return `v${u} and v${v} are already joined by e${existing >> 1}: a second edge between them is not allowed`;
  return null;
}

/**
 * Splits face `f` with a new edge from corner `u` to corner `v` (see the diagram above). The new
 * face copies `f`'s attributes; the new halfedges copy the corner values of `u` and `v` in `f`.
 * @example const { edge } = splitFace(mesh, f, 0, 2); // a quad 0, 1, 2, 3 becomes two triangles
 * @throws TopologyError with `canSplitFace`'s sentence when the split does not apply.
 */
export function splitFace(mesh: HalfedgeMesh, f: number, u: number, v: number, options: EditOptions = {}): FaceSplitResult {
  const why = canSplitFace(mesh, f, u, v);
  if (why) throw new TopologyError(`splitFace: ${why}`);
  const w = new PointerWriter(mesh, options);
  const edge = splitFaceAt(w, faceHalfedgeFrom(mesh, f, u), faceHalfedgeFrom(mesh, f, v));
  return { ...w.result(), edge };
}

/**
 * The split itself, between the corners where halfedges `hu` and `hv` (of the same face, not
 * neighbours) start. Returns the new edge. Used by the other edits and the plane cut.
 */
export function splitFaceAt(w: PointerWriter, hu: number, hv: number): number {
  const mesh = w.mesh;
  const n = w.addEdge();
  const fNew = w.addFace();
  const { hePrev, heNext, heVertex, heFace, fHalfedge } = mesh; // after any growth
  const f = heFace[hu];
  const g = 2 * n; // v → u, closes f
  const gt = g + 1; // u → v, closes the new face
  const pu = hePrev[hu];
  const pv = hePrev[hv];
  w.copy('face', fNew, f);
  w.copy('halfedge', g, hv);
  w.copy('halfedge', gt, hu);

  w.setOrigin(g, heVertex[hv]);
  w.setOrigin(gt, heVertex[hu]);
  w.link(pv, g);
  w.link(g, hu);
  w.link(pu, gt);
  w.link(gt, hv);
  w.setFace(g, f);
  let h = gt;
  do {
    w.setFace(h, fNew);
    h = heNext[h];
  } while (h !== gt);
  w.setFaceHalfedge(fNew, gt);
  // f's own halfedge may have moved to the new face
  if (heFace[fHalfedge[f]] !== f) w.setFaceHalfedge(f, g);
  return n;
}
