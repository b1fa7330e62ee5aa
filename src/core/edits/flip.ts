/**
 * Edge flip: the edge between two triangles turns to join their other two corners. The two
 * halfedges of `e` and both faces are reused, so no element is created or removed: only six
 * `next` links (and their `prev`s), two origins, two faces and a few vertex/face handles move.
 *
 * ```
 *            c                           c
 *          ╱   ╲                       ╱ ▲ ╲
 *        ╱  f0   ╲                   ╱   │   ╲
 *      a ───h───► b       ──►      a  f0 h  f1  b        h = 2e, t = 2e + 1 = twin(h)
 *        ╲  f1   ╱                   ╲   │   ╱
 *          ╲   ╱                       ╲ │ ╱
 *            d                           d
 *   f0 = (a, b, c), f1 = (b, a, d)   f0 = (a, d, c), f1 = (d, b, c)
 * ```
 * Afterwards `h` runs d → c and `t` runs c → d; the quad a, d, b, c keeps its outline.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { halfedgeFromTo, isTriangleLoop, missingEdge } from './find.js';
import { type EditOptions, type EditResult, PointerWriter } from '../change/writer.js';

/**
 * Why edge `e` cannot be flipped, or null when it can. Refused: a boundary edge, an edge not
 * between two triangles, two triangles with the same third corner, and a flip that would
 * duplicate an existing edge.
 * @example const why = canFlipEdge(mesh, e); if (why) console.log(why);
 */
export function canFlipEdge(mesh: HalfedgeMesh, e: number): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  const { heNext, heVertex, heFace } = mesh;
  const h = 2 * e;
  const t = h + 1;
  if (heFace[h] === -1 || heFace[t] === -1) return `e${e} is on the boundary: a flip needs a face on both sides`;
  for (const g of [h, t]) {
    if (!isTriangleLoop(mesh, g)) {
      return `f${heFace[g]} beside e${e} has ${mesh.loopLength(g)} sides: a flip needs a triangle on both sides`;
    }
  }
  const c = heVertex[heNext[heNext[h]]];
  const d = heVertex[heNext[heNext[t]]];
  if (c === d) return `the triangles beside e${e} share their third corner v${c}: the flipped edge would be a loop`;
  if (halfedgeFromTo(mesh, c, d) !== -1) return `flipping e${e} would create an edge that already exists (v${c}–v${d})`;
  return null;
}

/**
 * Turns edge `e` to join the opposite corners of its two triangles (see the diagram above).
 * @example if (!canFlipEdge(mesh, e)) flipEdge(mesh, e);
 * @throws TopologyError with `canFlipEdge`'s sentence when the flip does not apply.
 */
export function flipEdge(mesh: HalfedgeMesh, e: number, options: EditOptions = {}): EditResult {
  const why = canFlipEdge(mesh, e);
  if (why) throw new TopologyError(`flipEdge: ${why}`);
  const w = new PointerWriter(mesh, options);
  flipEdgeAt(w, e);
  return w.result();
}

/**
 * The flip itself, through a caller's writer, for a caller that has just asked `canFlipEdge`
 * (remeshing flips many edges with one writer per phase).
 */
export function flipEdgeAt(w: PointerWriter, e: number): void {
  const mesh = w.mesh;
  const { heNext, heVertex, heFace, vHalfedge } = mesh;
  const h = 2 * e;
  const t = h + 1;
  const h1 = heNext[h]; // b → c
  const h2 = heNext[h1]; // c → a
  const t1 = heNext[t]; // a → d
  const t2 = heNext[t1]; // d → b
  const a = heVertex[h];
  const b = heVertex[t];
  const c = heVertex[h2];
  const d = heVertex[t2];
  const f0 = heFace[h];
  const f1 = heFace[t];

  // corner values (texture coordinates…) follow their vertex: h now starts at d, t at c
  w.copy('halfedge', h, t2);
  w.copy('halfedge', t, h2);
  // a and b lose the edge: hand them another outgoing halfedge if theirs was on it
  if (vHalfedge[a] === h) w.setVertexHalfedge(a, t1);
  if (vHalfedge[b] === t) w.setVertexHalfedge(b, h1);

  // f0 = (a, d, c): c → a, a → d, d → c
  w.setOrigin(h, d);
  w.link(h2, t1);
  w.link(t1, h);
  w.link(h, h2);
  w.setFace(t1, f0);
  w.setFaceHalfedge(f0, h);
  // f1 = (d, b, c): d → b, b → c, c → d
  w.setOrigin(t, c);
  w.link(t2, h1);
  w.link(h1, t);
  w.link(t, t2);
  w.setFace(h1, f1);
  w.setFaceHalfedge(f1, t);
}
