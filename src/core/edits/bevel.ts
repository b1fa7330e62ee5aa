/**
 * Bevels: a vertex, or an edge, is replaced by a new face with one corner on each edge leaving it.
 *
 * Vertex bevel: v, of degree d, opens into a face F of d corners. Spoke j (the j-th halfedge
 * leaving v, counter-clockwise) now leaves corner w_j, and in each wedge between two spokes a new
 * side joins their corners, so the face of that wedge gains one side and F gets the other half:
 *
 * ```
 *                 x2                                       x2
 *                 │                                        │
 *         W1      │      W0                        W1      w2      W0
 *                 │                                      ╱    ╲
 *     x3 ──────── v ──────── x1         ──►     x3 ── w3    F    w1 ── x1
 *                 │                                      ╲    ╱
 *         W2      │      W3                        W2      w0      W3
 *                 │                                        │
 *                 x0                                       x0
 * ```
 * (spoke j runs v → x_j; wedge W_j lies between spokes j and j + 1; w_0 is v itself.) Counts:
 * d − 1 vertices, d edges and one face more; the Euler characteristic does not change.
 *
 * Edge bevel: e = a–b is replaced by F, whose corners are those of a vertex bevel at a and at b
 * along every edge leaving them except e itself. e stays, as F's side toward f0 (the face on the
 * `2e` side); a new edge g becomes F's side toward f1:
 *
 * ```
 *            x1               y3                       x1                y3
 *            │       f0       │                        │       f0        │
 *            │                │                        w1 ───── h ────► z3
 *     x2 ─── a ────── h ────► b ─── y2     ──►   x2 ── w2        F         z2 ── y2
 *            │                │                        w3 ◄──── g ────── z1
 *            │       f1       │                        │       f1        │
 *            x3               y1                       x3                y1
 * ```
 * (w1 is a and z1 is b.) Counts, with m and n the degrees of a and b: m + n − 4 vertices and
 * m + n − 3 edges more, one face more; the Euler characteristic does not change.
 *
 * Where the corners go: each is `amount` of the way along its edge from the vertex it replaces
 * (every vertex attribute is blended so, position included). The default, 0, leaves every corner
 * on that vertex: F has zero area, the face the assignment's bevel makes before its positions
 * helper pulls the corners apart; with `amount > 0` the bevel is done in one step.
 *
 * Hard cases, and what happens:
 *   - a boundary vertex is bevelled (as the assignment's own test expects): the wedge that is the
 *     hole gains the side instead of a face, so F borders the hole along one side;
 *   - a vertex of degree 1 or 2 is refused: F would have fewer than 3 sides (on the boundary, a
 *     degree-2 vertex is a corner of the surface, such as a grid's);
 *   - a boundary edge is refused, as the assignment's test does: a bevel of an edge replaces an
 *     edge between two faces; interior edges whose ends are on the boundary are bevelled, F then
 *     bordering the hole at each boundary end;
 *   - an edge whose two ends have 2 edges each (m + n < 5) is refused: F would have 2 sides.
 * Nothing else can go wrong: every new edge joins two new corners, so no edge is doubled, and
 * each face around gains one corner where it had one.
 *
 * Attributes: F copies the face attributes of the first face around (f0 for an edge). Corner
 * values (texture coordinates…) follow the corner they come from: a wedge face's two corners where
 * it had v both take its old value at v; F's corner on spoke j takes that of the face after spoke j
 * (the one before it when that is the hole). New edges have zero edge attributes, but g copies e's.
 */
import { vertexOutgoingHalfedges } from '../circulators.js';
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingEdge, missingVertex, rotationFrom } from './find.js';
import { type EditOptions, type FaceEditResult, PointerWriter } from '../change/writer.js';

export interface BevelOptions extends EditOptions {
  /** The fraction of the way each new corner moves along its edge, 0 … 1; default 0 (a face of zero area). */
  amount?: number;
}

/** Why `amount` cannot place the corners replacing `what`, or null. */
function badAmount(amount: number, what: string): string | null {
  if (amount >= 0 && amount <= 1) return null;
  return `amount = ${amount} is not between 0 and 1: it is the fraction of the way the new corners move from ${what} along its edges`;
}

/**
 * Why vertex `v` cannot be bevelled, or null when it can: it must have at least 3 edges (on the
 * boundary too), and `amount` must lie in 0 … 1.
 * @example canBevelVertex(mesh, v) // "v4 has only 2 edges: …"
 */
export function canBevelVertex(mesh: HalfedgeMesh, v: number, amount = 0): string | null {
  const missing = missingVertex(mesh, v);
  if (missing) return missing;
  const degree = mesh.vertexDegree(v);
  if (degree === 0) return `v${v} has no edges: there is nothing to bevel`;
  if (degree < 3) return `v${v} has only ${degree} edges: the face replacing it would have ${degree} sides, and a face needs at least 3`;
  return badAmount(amount, `v${v}`);
}

/**
 * Replaces vertex `v` by a face with a corner on each of its edges (see the diagram above).
 * Returns the new face; v itself becomes its corner on v's own halfedge.
 * @example const { face } = bevelVertex(mesh, v, { amount: 0.25 });
 * @throws TopologyError with `canBevelVertex`'s sentence when the bevel does not apply.
 */
export function bevelVertex(mesh: HalfedgeMesh, v: number, options: BevelOptions = {}): FaceEditResult {
  const amount = options.amount ?? 0;
  const why = canBevelVertex(mesh, v, amount);
  if (why) throw new TopologyError(`bevelVertex: ${why}`);
  // the spokes, counter-clockwise from v's halfedge (the boundary one on the boundary)
  const spokes = [...vertexOutgoingHalfedges(mesh, v)];
  const model = spokes.map((s) => mesh.heFace[s]).find((f) => f !== -1)!;

  // new elements first: adding may grow the arrays
  const w = new PointerWriter(mesh, options);
  const corners = spokes.map((_, j) => (j === 0 ? v : w.addVertex()));
  const sides = spokes.map(() => w.addEdge());
  const face = w.addFace();

  w.copy('face', face, model);
  const inside = openFan(w, spokes, corners, sides, spokes[spokes.length - 1], amount);
  closeLoop(w, face, inside);
  return { ...w.result(), face };
}

/**
 * Why edge `e` cannot be bevelled, or null when it can: it must have a face on both sides, its
 * ends at least 5 edges between them (so the new face has 3 sides or more), and `amount` must lie
 * in 0 … 1.
 * @example canBevelEdge(mesh, e) // "e7 is on the boundary: …"
 */
export function canBevelEdge(mesh: HalfedgeMesh, e: number, amount = 0): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  if (mesh.heFace[2 * e] === -1 || mesh.heFace[2 * e + 1] === -1) {
    return `e${e} is on the boundary: a bevel replaces an edge between two faces, and e${e} has the hole on one side`;
  }
  const a = mesh.heVertex[2 * e];
  const b = mesh.heVertex[2 * e + 1];
  const m = mesh.vertexDegree(a);
  const n = mesh.vertexDegree(b);
  if (m + n < 5) {
    return `the ends of e${e} (v${a}, v${b}) have ${m} and ${n} edges: the face replacing it would have ${m + n - 2} sides, and a face needs at least 3`;
  }
  return badAmount(amount, `v${a} and v${b}`);
}

/**
 * Replaces edge `e` by a face with a corner on each edge leaving its ends, e excepted (see the
 * diagram above). Returns the new face; e is now its side toward the face on the `2e` side.
 * @example const { face } = bevelEdge(mesh, e, { amount: 0.1 });
 * @throws TopologyError with `canBevelEdge`'s sentence when the bevel does not apply.
 */
export function bevelEdge(mesh: HalfedgeMesh, e: number, options: BevelOptions = {}): FaceEditResult {
  const amount = options.amount ?? 0;
  const why = canBevelEdge(mesh, e, amount);
  if (why) throw new TopologyError(`bevelEdge: ${why}`);
  const h = 2 * e; // a → b, in f0: stays there, from a to b's last corner
  const t = h + 1; // b → a, in f1: moves into the new face; g takes its place in f1
  const a = mesh.heVertex[h];
  const b = mesh.heVertex[t];
  const f0 = mesh.heFace[h];
  const f1 = mesh.heFace[t];
  const beforeT = mesh.hePrev[t]; // arrives at b, in f1
  const afterT = mesh.heNext[t]; // the last spoke of a, in f1
  // the spokes at each end, counter-clockwise from e: at a the first is in f0 and the last in f1
  const spokesA = rotationFrom(mesh, h).slice(1);
  const spokesB = rotationFrom(mesh, t).slice(1);

  // new elements first: adding may grow the arrays
  const w = new PointerWriter(mesh, options);
  const cornersA = spokesA.map((_, j) => (j === 0 ? a : w.addVertex()));
  const cornersB = spokesB.map((_, j) => (j === 0 ? b : w.addVertex()));
  const sidesA = spokesA.slice(1).map(() => w.addEdge());
  const sidesB = spokesB.slice(1).map(() => w.addEdge());
  const g = w.addEdge();
  const face = w.addFace();
  const lastA = cornersA[cornersA.length - 1];
  const lastB = cornersB[cornersB.length - 1];

  w.copy('face', face, f0);
  w.copy('edge', g, e);
  // each end opens like a vertex bevel, but only between its spokes (not across f0 or f1)
  const insideA = openFan(w, spokesA, cornersA, sidesA, h, amount);
  const insideB = openFan(w, spokesB, cornersB, sidesB, t, amount);

  // f1's side: g0 runs b → a's last corner where t ran b → a, and keeps t's corner value
  const g0 = 2 * g;
  const g1 = g0 + 1; // a's last corner → b, in F
  w.copy('halfedge', g0, t);
  w.copy('halfedge', g1, spokesA[spokesA.length - 1]);
  w.copy('halfedge', t, spokesB[spokesB.length - 1]);
  w.setOrigin(g0, b);
  w.setOrigin(g1, lastA);
  w.link(beforeT, g0);
  w.link(g0, afterT);
  w.setFace(g0, f1);
  if (mesh.fHalfedge[f1] === t) w.setFaceHalfedge(f1, g0);
  // f0's side is e itself: h keeps its place and origin a; t now leaves b's last corner, in F
  w.setOrigin(t, lastB);
  closeLoop(w, face, [t, ...insideA, g1, ...insideB]);
  return { ...w.result(), face };
}

/**
 * Opens a fan of spokes (halfedges leaving one vertex v, consecutive counter-clockwise) into a
 * chain of corners: spoke j now leaves corner j (corner 0 is v), `amount` of the way along it.
 * In each wedge j, between spokes j and j + 1 (the last wedge closes the fan when there are as
 * many sides as spokes), new side j gets halfedge corner j+1 → corner j into the wedge's loop,
 * just before spoke j; its twin, corner j → corner j+1, is returned for the new face's loop.
 * `before` is the halfedge before spoke 0 around v (for a corner value beside the hole).
 * The caller has added every new element: this reads the arrays once.
 */
function openFan(w: PointerWriter, spokes: number[], corners: number[], sides: number[], before: number, amount: number): number[] {
  const mesh = w.mesh;
  const { hePrev, heVertex, heFace } = mesh;
  const n = spokes.length;
  const v = corners[0];
  // values: every corner is v's, blended toward its spoke's far end (v last: it is every blend's source)
  for (let j = n - 1; j >= 0; j--) w.blend('vertex', corners[j], [v, heVertex[spokes[j] ^ 1]], [1 - amount, amount]);
  for (let j = 1; j < n; j++) w.setOrigin(spokes[j], corners[j]);
  for (let j = 0; j < n; j++) w.setVertexHalfedge(corners[j], spokes[j]);

  const inside: number[] = [];
  for (let j = 0; j < sides.length; j++) {
    const k = (j + 1) % n;
    const spoke = spokes[j];
    const wedge = heFace[spoke]; // -1: the hole
    const into = hePrev[spoke]; // x_k → v, the twin of spoke k
    const s = 2 * sides[j]; // corner k → corner j, in the wedge
    // corner values: the wedge's old one at v at both its corners there; F's from the wedge, or
    // from the face before it when the wedge is the hole
    w.copy('halfedge', s, spoke);
    w.copy('halfedge', s + 1, wedge !== -1 ? spoke : j === 0 ? before : spokes[j - 1]);
    w.setOrigin(s, corners[k]);
    w.setOrigin(s + 1, corners[j]);
    w.link(into, s);
    w.link(s, spoke);
    w.setFace(s, wedge);
    // on the boundary the corner after the hole leaves it along s (corner j already along spoke j)
    if (wedge === -1) w.setVertexHalfedge(corners[k], s);
    inside.push(s + 1);
  }
  return inside;
}

/** Links `loop` into a cycle and gives it to face `f`. */
function closeLoop(w: PointerWriter, f: number, loop: number[]): void {
  for (let i = 0; i < loop.length; i++) {
    w.link(loop[i], loop[(i + 1) % loop.length]);
    w.setFace(loop[i], f);
  }
  w.setFaceHalfedge(f, loop[0]);
}

