/**
 * Edge split: a new vertex m on edge e = a–b, and a new edge, so a–b becomes a–m–b.
 *
 * ```
 *                f0                              f0
 *      a ──────── h ───────► b         a ── h ──► m ── g ──► b
 *      a ◄─────── t ──────── b   ──►   a ◄── t ── m ◄── g' ── b      g = 2·new edge, g' = twin(g)
 *                f1                              f1
 * ```
 * `h` keeps its origin a and now ends at m; `t` now starts at m. The faces on either side gain a
 * corner: a triangle becomes a quad with one straight angle. `splitEdgeTriangulated` then cuts
 * each such quad back into two triangles through m, as remeshing does when it splits long edges:
 *
 * ```
 *              c                             c
 *            ╱   ╲                         ╱ │ ╲
 *          ╱  f0   ╲                     ╱   │   ╲
 *        a ───────► b       ──►        a ──► m ──► b
 *          ╲  f1   ╱                     ╲   │   ╱
 *            ╲   ╱                         ╲ │ ╱
 *              d                             d
 * ```
 * The new vertex takes the blend of a and b (weights 1 − t and t) for every vertex attribute,
 * positions included; corner values are blended the same way.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { isTriangleLoop, missingEdge } from './find.js';
import { splitFaceAt } from './split-face.js';
import { type EditOptions, PointerWriter, type VertexEditResult } from '../change/writer.js';

export interface SplitEdgeOptions extends EditOptions {
  /** Where the new vertex goes along the edge, from origin(2e) (0) to origin(2e + 1) (1); default 0.5. */
  t?: number;
}

/** Why edge `e` cannot be split at `t`, or null when it can: the edge must exist and 0 < t < 1. */
export function canSplitEdge(mesh: HalfedgeMesh, e: number, t = 0.5): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  if (!(t > 0 && t < 1)) {
    return `t = ${t} is not strictly between 0 and 1: the new vertex would not lie inside e${e}`;
  }
  return null;
}

/**
 * Why edge `e` cannot be split with its neighbouring triangles, or null: as `canSplitEdge`, each
 * face beside `e` must be a triangle, and the two triangles may not have the same third corner
 * (two triangles on the same three corners, as in a pillow): both would join the new vertex to
 * it, a second edge between the same two vertices.
 */
export function canSplitEdgeTriangulated(mesh: HalfedgeMesh, e: number, t = 0.5): string | null {
  const why = canSplitEdge(mesh, e, t);
  if (why) return why;
  for (const h of [2 * e, 2 * e + 1]) {
    if (mesh.heFace[h] !== -1 && !isTriangleLoop(mesh, h)) {
      return `f${mesh.heFace[h]} beside e${e} has ${mesh.loopLength(h)} sides: the triangulated split needs triangles (use splitEdge)`;
    }
  }
  const { heFace, hePrev, heVertex } = mesh;
  const c = heVertex[hePrev[2 * e]];
  if (heFace[2 * e] !== -1 && heFace[2 * e + 1] !== -1 && c === heVertex[hePrev[2 * e + 1]]) {
    return `the triangles beside e${e} (f${heFace[2 * e]}, f${heFace[2 * e + 1]}) have the same third corner v${c}: the new vertex would be joined to it twice`;
  }
  return null;
}

/**
 * Inserts a vertex on edge `e`; the faces beside it gain one side each. Returns the new vertex.
 * @example const { vertex } = splitEdge(mesh, e, { t: 0.25 });
 * @throws TopologyError with `canSplitEdge`'s sentence when the split does not apply.
 */
export function splitEdge(mesh: HalfedgeMesh, e: number, options: SplitEdgeOptions = {}): VertexEditResult {
  const t = options.t ?? 0.5;
  const why = canSplitEdge(mesh, e, t);
  if (why) throw new TopologyError(`splitEdge: ${why}`);
  const w = new PointerWriter(mesh, options);
  const vertex = splitEdgeAt(w, e, t);
  return { ...w.result(), vertex };
}

/**
 * Inserts a vertex on edge `e` and joins it to the opposite corner of each triangle beside `e`:
 * two triangles become four (one becomes two on the boundary). Returns the new vertex.
 * @throws TopologyError with `canSplitEdgeTriangulated`'s sentence when the split does not apply.
 */
export function splitEdgeTriangulated(mesh: HalfedgeMesh, e: number, options: SplitEdgeOptions = {}): VertexEditResult {
  const t = options.t ?? 0.5;
  const why = canSplitEdgeTriangulated(mesh, e, t);
  if (why) throw new TopologyError(`splitEdgeTriangulated: ${why}`);
  const w = new PointerWriter(mesh, options);
  const vertex = splitEdgeTriangulatedAt(w, e, t);
  return { ...w.result(), vertex };
}

/** The triangulated split itself (the triangles beside `e` checked); returns the new vertex. Used by the plane cut's caps too. */
export function splitEdgeTriangulatedAt(w: PointerWriter, e: number, t: number): number {
  const mesh = w.mesh;
  const h = 2 * e;
  const vertex = splitEdgeAt(w, e, t);
  // (read the arrays afresh each time: a split may have grown them)
  // f0 is now a → m → b → c: join m (start of next(h)) to c (start of prev(h))
  if (mesh.heFace[h] !== -1) splitFaceAt(w, mesh.heNext[h], mesh.hePrev[h]);
  // f1 is now b → m → a → d: join m (start of t) to d (start of prev(prev(t)))
  if (mesh.heFace[h + 1] !== -1) splitFaceAt(w, h + 1, mesh.hePrev[mesh.hePrev[h + 1]]);
  return vertex;
}

/** The split itself; returns the new vertex. Used by the other edits and the plane cut. */
export function splitEdgeAt(w: PointerWriter, e: number, t: number): number {
  const mesh = w.mesh;
  const m = w.addVertex();
  const n = w.addEdge();
  const { heNext, hePrev, heVertex, heFace, vHalfedge } = mesh; // after any growth
  const h = 2 * e; // a → b, will end at m
  const o = h + 1; // b → a, will start at m
  const g = 2 * n; // m → b, after h
  const gt = g + 1; // b → m, before o
  const a = heVertex[h];
  const b = heVertex[o];
  const afterH = heNext[h];
  const beforeO = hePrev[o];

  w.blend('vertex', m, [a, b], [1 - t, t]);
  w.copy('edge', n, e);
  // corner values: g' takes o's (corner b in f1), g and o the blends at m in f0 and f1
  w.copy('halfedge', gt, o);
  w.blend('halfedge', g, [h, afterH], [1 - t, t]);
  w.blend('halfedge', o, [gt, heNext[o]], [t, 1 - t]);

  w.setOrigin(g, m);
  w.setFace(g, heFace[h]);
  w.link(g, afterH);
  w.link(h, g);
  w.setOrigin(gt, b);
  w.setFace(gt, heFace[o]);
  w.link(beforeO, gt);
  w.link(gt, o);
  w.setOrigin(o, m);
  if (vHalfedge[b] === o) w.setVertexHalfedge(b, gt);
  // on the boundary, m's halfedge must be its boundary one
  w.setVertexHalfedge(m, heFace[o] === -1 ? o : g);
  return m;
}
