/**
 * Edge collapse: edge e = a–b shrinks to a point. Vertex b merges into a (a survives, by default
 * at the midpoint), every halfedge that left b now leaves a, and each triangle beside e
 * disappears with one of its two other edges (the one at b); a longer face just loses a side.
 *
 * ```
 *              c                                c
 *            ╱   ╲                              │
 *          ╱  f0   ╲                            │      f0, f1, e, b–c and d–b deleted;
 *     ── a ───h───► b ──        ──►        ──── a ────  c–a and a–d stay
 *          ╲  f1   ╱                            │
 *            ╲   ╱                              │
 *              d                                d
 * ```
 *
 * When it would not give a manifold mesh, the collapse is refused (`canCollapseEdge` says why):
 *   - the *link condition*: a and b may share no neighbour other than c and d (the corners
 *     across their triangles), or the two edges to that neighbour would become one edge with
 *     three faces; nor may a second edge join a and b (it would become a loop);
 *   - a and b may share no face other than those beside e: it would pass through one vertex
 *     twice. Only the faces beside e lose a side (a triangle there goes entirely), so this is
 *     also what keeps every face at 3 sides or more;
 *   - an interior edge whose two ends are both on the boundary: a and b would merge into a vertex
 *     with two fans (a pinch);
 *   - a triangle beside e whose two other edges are both on the boundary: they would merge into
 *     a dangling edge with no face;
 *   - two triangles beside e with the same third corner, and an edge of a tetrahedron (the
 *     tetrahedron would flatten into two triangles on the same three corners).
 *
 * The work is O(valence of a and b): one rotation around b to re-point its halfedges, a few
 * relinks, and a rotation around a to choose its handle; the check compares the two one-rings
 * (a few dozen comparisons at the usual valence 6). Pass `{ record: false }` when collapsing in
 * bulk; decimation calls `collapseEdgeAt` with one writer for a whole batch.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { isTriangleLoop, missingEdge } from './find.js';
import { type EditOptions, PointerWriter, type VertexEditResult } from '../change/writer.js';

export interface CollapseOptions extends EditOptions {
  /** Where the surviving vertex goes, as x, y, z; default the midpoint of the edge. */
  position?: ArrayLike<number>;
}

/** The two ends of a collapsing edge, blended half and half (reused: no allocation per collapse). */
const ends = [0, 0];
const halves = [0.5, 0.5];

/**
 * Scratch lists of the link condition, reused: decimation asks it a million times. They are never
 * emptied, only counted from 0 again: an array emptied by `length = 0` gives its memory up, and
 * the next pushes allocate it again.
 */
const neighboursOfB: number[] = [];
const facesOfB: number[] = [];

/** True when `x` is among the first `count` items of `list`. */
function listed(list: number[], count: number, x: number): boolean {
  for (let i = 0; i < count; i++) if (list[i] === x) return true;
  return false;
}

/**
 * Why edge `e` cannot be collapsed, or null when it can (the rules are listed above).
 * @example const why = canCollapseEdge(mesh, e); // "v3 and v7 (the ends of e5) are both joined to v9, …"
 */
export function canCollapseEdge(mesh: HalfedgeMesh, e: number): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const h = 2 * e;
  const t = h + 1;
  const a = heVertex[h];
  const b = heVertex[t];
  const f0 = heFace[h];
  const f1 = heFace[t];
  if (f0 !== -1 && f1 !== -1 && mesh.isBoundaryVertex(a) && mesh.isBoundaryVertex(b)) {
    return `e${e} joins two boundary vertices (v${a}, v${b}) but is not on the boundary itself: collapsing it would pinch the surface at one vertex`;
  }
  // the corner across each triangle beside e, -1 where that side is no triangle
  const c = f0 !== -1 && isTriangleLoop(mesh, h) ? heVertex[hePrev[h]] : -1;
  const d = f1 !== -1 && isTriangleLoop(mesh, t) ? heVertex[hePrev[t]] : -1;
  if (c !== -1 && c === d) {
    return `the triangles beside e${e} (f${f0}, f${f1}) have the same three corners: collapsing e${e} would leave nothing of them`;
  }
  for (let g = h; g <= t; g++) {
    if ((g === h ? c : d) !== -1 && heFace[heNext[g] ^ 1] === -1 && heFace[hePrev[g] ^ 1] === -1) {
      return `the other two edges of f${heFace[g]} are both on the boundary: collapsing e${e} would leave them as one dangling edge`;
    }
  }

  // the link condition: gather b's neighbours and faces, then look at a's
  let neighbours = 0;
  let faces = 0;
  let x = t;
  do {
    neighboursOfB[neighbours++] = heVertex[x ^ 1];
    if (heFace[x] !== f0 && heFace[x] !== f1 && heFace[x] !== -1) facesOfB[faces++] = heFace[x];
    x = hePrev[x] ^ 1;
  } while (x !== t);
  x = h;
  do {
    const y = heVertex[x ^ 1];
    if (y === b && x !== h) {
      return `v${a} and v${b} are also joined by e${x >> 1}: collapsing e${e} would turn e${x >> 1} into a loop`;
    }
    if (y !== b && y !== c && y !== d && listed(neighboursOfB, neighbours, y)) {
      return `v${a} and v${b} (the ends of e${e}) are both joined to v${y}, which is not across a triangle of e${e}: collapsing would join them twice (the link condition fails)`;
    }
    const f = heFace[x];
    if (listed(facesOfB, faces, f)) {
      return `f${f} has both v${a} and v${b} as corners but not along e${e}: collapsing would make it pass through one vertex twice`;
    }
    x = hePrev[x] ^ 1;
  } while (x !== h);

  // a tetrahedron: the faces across a's and b's other edges close up in two more triangles
  if (c !== -1 && d !== -1) {
    const atA = heFace[hePrev[h] ^ 1]; // across c–a
    const atB = heFace[heNext[h] ^ 1]; // across b–c
    if (
      atA !== -1 &&
      atA === heFace[heNext[t] ^ 1] &&
      atB !== -1 &&
      atB === heFace[hePrev[t] ^ 1] &&
      isTriangleLoop(mesh, hePrev[h] ^ 1) &&
      isTriangleLoop(mesh, heNext[h] ^ 1)
    ) {
      return `e${e} is an edge of a tetrahedron (f${f0}, f${f1}, f${atA}, f${atB}): collapsing it would flatten it into two triangles on the same three corners`;
    }
  }
  return null;
}

/**
 * Collapses edge `e`: origin(2e) survives (at `position`, default the midpoint) and takes over
 * origin(2e + 1). Other vertex attributes take the average of the two ends.
 * @example
 *   if (!canCollapseEdge(mesh, e)) collapseEdge(mesh, e, { position: optimal, record: false });
 * @throws TopologyError with `canCollapseEdge`'s sentence when the collapse does not apply.
 */
export function collapseEdge(mesh: HalfedgeMesh, e: number, options: CollapseOptions = {}): VertexEditResult {
  const why = canCollapseEdge(mesh, e);
  if (why) throw new TopologyError(`collapseEdge: ${why}`);
  const w = new PointerWriter(mesh, options);
  const vertex = collapseEdgeAt(w, e, options.position ?? null);
  return { ...w.result(), vertex };
}

/**
 * The collapse itself, through a caller's writer, for a caller that has just asked
 * `canCollapseEdge` (decimation, a million times over, with one writer per batch). `position`
 * null leaves a at the midpoint. Returns a, the survivor.
 */
export function collapseEdgeAt(w: PointerWriter, e: number, position: ArrayLike<number> | null): number {
  const mesh = w.mesh;
  const { heNext, hePrev, heVertex, heFace, vHalfedge } = mesh; // a collapse never grows the arrays
  const h = 2 * e;
  const t = h + 1;
  const a = heVertex[h];
  const b = heVertex[t];
  const f0 = heFace[h];
  const f1 = heFace[t];
  const triangle0 = f0 !== -1 && isTriangleLoop(mesh, h);
  const triangle1 = f1 !== -1 && isTriangleLoop(mesh, t);
  // a halfedge that will still leave a afterwards, to rotate from: the one after t (it leaves a,
  // and each side's repair keeps it, where the one after h may go with a boundary ear)
  const survivor = heNext[t];

  ends[0] = a;
  ends[1] = b;
  w.blend('vertex', a, ends, halves);
  if (position) w.setPosition(a, position[0], position[1], position[2]);

  // everything that left b now leaves a
  let x = hePrev[t] ^ 1;
  while (x !== t) {
    w.setOrigin(x, a);
    x = hePrev[x] ^ 1;
  }
  // h's side: a triangle a, b, c loses b–c (c–a takes its place); a longer loop just loses h
  if (triangle0) replaceParallel(w, heNext[h] ^ 1, hePrev[h]);
  else unlink(w, h);
  // t's side: a triangle b, a, d loses d–b (a–d takes its place)
  if (triangle1) replaceParallel(w, hePrev[t] ^ 1, heNext[t]);
  else unlink(w, t);

  w.deleteEdge(e);
  w.deleteVertex(b);
  if (triangle0) w.deleteFace(f0);
  if (triangle1) w.deleteFace(f1);

  // a's handle: its boundary halfedge if it has one now, else any live one
  let boundary = -1;
  x = survivor;
  do {
    if (heFace[x] === -1) boundary = x;
    x = hePrev[x] ^ 1;
  } while (x !== survivor && boundary === -1);
  if (boundary !== -1) w.setVertexHalfedge(a, boundary);
  else if (mesh.eDeleted[vHalfedge[a] >> 1]) w.setVertexHalfedge(a, survivor);
  return a;
}

/**
 * After b merged into a, halfedge `gone` runs parallel to `kept` (same ends, same direction):
 * `kept` takes gone's place in its loop, and gone's edge is deleted. (The face collapse merges
 * the edges of each triangle beside the face the same way.)
 */
export function replaceParallel(w: PointerWriter, gone: number, kept: number): void {
  const { hePrev, heNext, heVertex, heFace, fHalfedge, vHalfedge } = w.mesh;
  const f = heFace[gone];
  w.copy('halfedge', kept, gone);
  w.link(hePrev[gone], kept);
  w.link(kept, heNext[gone]);
  w.setFace(kept, f);
  if (f !== -1 && fHalfedge[f] === gone) w.setFaceHalfedge(f, kept);
  // a vertex whose handle was gone (or its twin) takes kept (or its twin)
  const goneTwin = gone ^ 1;
  if (vHalfedge[heVertex[gone]] === gone) w.setVertexHalfedge(heVertex[gone], kept);
  if (vHalfedge[heVertex[goneTwin]] === goneTwin) w.setVertexHalfedge(heVertex[goneTwin], kept ^ 1);
  w.deleteEdge(gone >> 1);
}

/** Takes `g` out of its loop (a face of four or more sides, or a hole of three or more). */
function unlink(w: PointerWriter, g: number): void {
  const { hePrev, heNext, heFace, fHalfedge } = w.mesh;
  const f = heFace[g];
  w.link(hePrev[g], heNext[g]);
  if (f !== -1 && fHalfedge[f] === g) w.setFaceHalfedge(f, heNext[g]);
}
