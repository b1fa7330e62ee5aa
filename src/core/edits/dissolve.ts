/**
 * Dissolves: an element goes and the faces around it merge into one.
 *
 * **Dissolve edge** (`mergeFaces` is its old name, kept for interior edges): the two faces beside
 * edge e become one; e is deleted, and so is the face on its `2e + 1` side (the face on the `2e`
 * side keeps its id and attributes).
 * ```
 *      d ◄──────── c ◄──────── x          d ◄──────── c ◄──────── x
 *      │           ▲           ▲          │                       ▲
 *      │    f0     h   f1      │   ──►    │          f0           │
 *      ▼           │           │          ▼                       │
 *      a ────────► b ────────► y          a ────────► b ────────► y
 * ```
 * (here h = 2e runs b → c with f0 on its left.) On a **boundary edge** the face merges with the
 * hole, as the original assignment has it ("if applied to a boundary edge, the merged face is a
 * boundary"): the face goes, and its other edges become boundary, which is `makeBoundary` of that
 * face (any other edge of it along a hole goes too: it would have a hole on both sides).
 *
 * **Dissolve vertex**: v and its edges go, and the faces around v merge into one face.
 * ```
 *          u2                              u2
 *        ╱ │ ╲                           ╱    ╲
 *      ╱ f1│f0 ╲                       ╱        ╲
 *    u3 ── v ── u1        ──►        u3     f0    u1        an interior v of degree 4
 *      ╲ f2│f3 ╱                       ╲        ╱
 *        ╲ │ ╱                           ╲    ╱
 *          u4                              u4
 *
 *    ─ a ── v ── b ─  (hole above)      ─ a ─────── b ─      a boundary v: the faces below v
 *       ╲ f0│ f1╱                          ╲    f0   ╱        merge, and a new edge a–b closes
 *        ╲  │  ╱               ──►         ╲       ╱         the merged face where v was
 *          u2                                u2
 * ```
 * A boundary vertex does not merge its faces with the hole (the original: "dissolving a vertex on
 * the boundary does not merge with the boundary face"; its figure shows the two boundary edges at
 * v replaced by one straight edge between v's neighbours along the boundary). That new edge
 * copies the attributes of the edge a–v, and its halfedges the corner values of the halfedges
 * they replace. The merged face keeps the id and attributes of the face of v's handle, or at a
 * boundary vertex of the face along v–a (where the hole runs a → v → b, as above).
 *
 * The cases of both dissolves:
 *   - refused, the merged face would pass through a vertex twice (two faces beside e that share
 *     another corner; two faces around v that share a corner other than across an edge at v):
 *     it would touch itself there, or, when the faces share another edge, border itself along a
 *     dangling edge; a face no file can hold, and one that later edits cannot take apart;
 *   - refused, the merged face would have fewer than 3 sides (two triangles on the same two
 *     neighbours of a vertex of degree 2);
 *   - refused, an edge with the same face on both sides, and a vertex with no edges;
 *   - refused, a boundary vertex with one face only: there are no faces to merge (dissolving it
 *     would only cut the corner off; the original's test on the corner of a lone quad refuses it);
 *   - refused, a boundary vertex whose two neighbours along the boundary are already joined by an
 *     edge: the closing edge would be a second edge between them;
 *   - refused, a boundary edge whose face cannot become a hole (see `canMakeBoundary`);
 *   - accepted, a vertex whose merged face has the same corners as another face: a
 *     tetrahedron's vertex leaves two triangles on the same three corners, a valid, if flat,
 *     closed mesh (whose vertices the rule on 3 sides then refuses);
 *   - the merged face may be non-convex or non-planar. A face cannot pass through v twice in a
 *     valid mesh, so the faces around v are all different.
 *
 * χ = V − E + F stays the same for both dissolves at interior elements and at a boundary vertex
 * (an interior v: V − 1, E − d, F − (d − 1)); a boundary edge changes it as `makeBoundary` does.
 * O(the sides of the faces around the element): one walk round them to check, one to rewrite.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { halfedgeFromTo, missingEdge, missingVertex, rotationFrom } from './find.js';
import { canMakeBoundary, makeBoundaryAt } from './make-boundary.js';
import { type EditOptions, type FaceEditResult, PointerWriter } from '../change/writer.js';

// ---------------------------------------------------------------------------------------------
// Dissolve edge

/**
 * Why edge `e` cannot be dissolved, or null when it can (the rules above): for an interior edge,
 * the two faces must be different and share no corner but e's ends; for a boundary edge, its face
 * must be able to become a hole.
 * @example canDissolveEdge(mesh, e); // "f0 and f2 also share v1: the merged face would pass through v1 twice"
 */
export function canDissolveEdge(mesh: HalfedgeMesh, e: number): string | null {
  const missing = missingEdge(mesh, e);
  if (missing) return missing;
  const f0 = mesh.heFace[2 * e];
  const f1 = mesh.heFace[2 * e + 1];
  if (f0 === -1 || f1 === -1) {
    const f = f0 === -1 ? f1 : f0;
    const why = canMakeBoundary(mesh, f);
    return why && `e${e} is on the boundary, so f${f} would join the hole, but ${why}`;
  }
  return whyNotMergeAcross(mesh, e);
}

/**
 * Dissolves edge `e`: its two faces merge into the one on the `2e` side, or, on a boundary edge,
 * its face joins the hole. Returns the merged face, or -1 for a boundary edge: there the face
 * became part of the hole (`makeBoundary` of that face makes the same change and names a
 * halfedge of the hole).
 * @example const { face } = dissolveEdge(mesh, e); // two triangles → one quad
 * @throws TopologyError with `canDissolveEdge`'s sentence when the dissolve does not apply.
 */
export function dissolveEdge(mesh: HalfedgeMesh, e: number, options: EditOptions = {}): FaceEditResult {
  const why = canDissolveEdge(mesh, e);
  if (why) throw new TopologyError(`dissolveEdge: ${why}`);
  const w = new PointerWriter(mesh, options);
  const f0 = mesh.heFace[2 * e];
  const f1 = mesh.heFace[2 * e + 1];
  if (f0 === -1 || f1 === -1) {
    // the boundary edge's face becomes part of the hole
    makeBoundaryAt(w, f0 === -1 ? f1 : f0);
    return { ...w.result(), face: -1 };
  }
  const face = mergeAcrossAt(w, e);
  return { ...w.result(), face };
}

/**
 * Why the two faces of interior edge `e` cannot merge into one, or null when they can: the same
 * face on both sides, or two faces that share a corner besides e's ends.
 */
export function whyNotMergeAcross(mesh: HalfedgeMesh, e: number): string | null {
  const { heNext, heVertex, heFace } = mesh;
  const h = 2 * e;
  const f0 = heFace[h];
  const f1 = heFace[h + 1];
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
 * Erases interior edge `e`, merging its two faces into the one on the `2e` side, through a
 * caller's writer, for a caller that has asked `whyNotMergeAcross`. Returns the merged face.
 */
export function mergeAcrossAt(w: PointerWriter, e: number): number {
  const mesh = w.mesh;
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  const h = 2 * e;
  const t = h + 1;
  const f0 = heFace[h];
  const f1 = heFace[t];
  const afterH = heNext[h];
  const afterT = heNext[t];

  // f1's other halfedges join f0
  for (let g = afterT, i = 0; g !== t && i < mesh.halfedgeSlots; g = heNext[g], i++) w.setFace(g, f0);
  w.link(hePrev[h], afterT);
  w.link(hePrev[t], afterH);
  if (fHalfedge[f0] === h) w.setFaceHalfedge(f0, afterH);
  // the ends of e keep a live handle (an interior one: e had faces on both sides, so neither
  // handle was on e if its vertex is on the boundary)
  if (vHalfedge[heVertex[h]] === h) w.setVertexHalfedge(heVertex[h], afterT);
  if (vHalfedge[heVertex[t]] === t) w.setVertexHalfedge(heVertex[t], afterH);
  w.deleteEdge(e);
  w.deleteFace(f1);
  return f0;
}

// ---------------------------------------------------------------------------------------------
// Dissolve vertex

/*
 * Around the vertex: `out` lists the halfedges leaving v, counter-clockwise (each the next one's
 * `twin(prev(x))`), from its handle: at a boundary vertex the first is the outgoing boundary
 * halfedge. Face i of the fan is `face(x_i)`, between x_i and `prev(x_i)`; its *far path*, the part
 * of its outline away from v, runs from `next(x_i)` to `prev(prev(x_i))`, from x_i's target to
 * x_(i+1)'s, so the far paths one after another are the merged face's outline.
 */

/**
 * Why vertex `v` cannot be dissolved, or null when it can (the rules above).
 * @example canDissolveVertex(mesh, v); // "v4 is a corner of f2 and f5 away from v1: …"
 */
export function canDissolveVertex(mesh: HalfedgeMesh, v: number): string | null {
  const missing = missingVertex(mesh, v);
  if (missing) return missing;
  if (mesh.vHalfedge[v] === -1) return `v${v} has no edges: there are no faces around it to merge`;
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const out = rotationFrom(mesh, mesh.vHalfedge[v]);
  const boundary = heFace[out[0]] === -1;
  const first = boundary ? 1 : 0;
  if (boundary && out.length === 2) {
    return `v${v} is on the boundary with one face, f${heFace[out[1]]}: there are no faces to merge (dissolving it would only cut the corner off)`;
  }
  // walk the merged outline: each face's far path; every corner met must be new
  const metIn = new Map<number, number>(); // corner → the face it was met in
  let sides = 0;
  for (let i = first; i < out.length; i++) {
    const x = out[i];
    const f = heFace[x];
    const end = hePrev[x];
    for (let g = heNext[x], k = 0; g !== end && k < mesh.halfedgeSlots; g = heNext[g], k++) {
      const u = heVertex[g];
      const before = metIn.get(u);
      if (before !== undefined) {
        const faces = before === f ? `f${f}` : `f${before} and f${f}`;
        return `v${u} is a corner of ${faces} away from v${v}: the merged face would pass through v${u} twice`;
      }
      metIn.set(u, f);
      sides++;
    }
  }
  if (boundary) {
    // the hole runs a → v → b; the outline runs from a round to b, and a new edge b → a closes it
    const a = heVertex[out[1] ^ 1];
    const b = heVertex[out[0] ^ 1];
    if (metIn.has(b)) return `v${b} is a corner of f${metIn.get(b)} away from v${v}: the merged face would pass through v${b} twice`;
    sides++;
    const existing = halfedgeFromTo(mesh, a, b);
    if (existing !== -1) {
      return `v${a} and v${b}, v${v}'s neighbours along the boundary, are already joined by e${existing >> 1}: the edge closing the merged face would be a second edge between them`;
    }
  }
  if (sides < 3) {
    return `the faces around v${v} have only ${sides} other sides: the merged face would have ${sides} sides, and a face needs at least 3`;
  }
  return null;
}

/**
 * Dissolves vertex `v`: v and its edges are deleted and the faces around it merge into one (at a
 * boundary vertex, closed by a new edge between its two neighbours along the boundary).
 * @example const { face } = dissolveVertex(mesh, v); // a cube's corner: three quads → a hexagon
 * @throws TopologyError with `canDissolveVertex`'s sentence when the dissolve does not apply.
 */
export function dissolveVertex(mesh: HalfedgeMesh, v: number, options: EditOptions = {}): FaceEditResult {
  const why = canDissolveVertex(mesh, v);
  if (why) throw new TopologyError(`dissolveVertex: ${why}`);
  const w = new PointerWriter(mesh, options);
  const boundary = mesh.isBoundaryVertex(v);
  // a boundary vertex's merged face is closed by a new edge: added first, as adding may grow the
  // arrays, so that those read below are the grown ones
  const ne = boundary ? w.addEdge() : -1;
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  const out = rotationFrom(mesh, mesh.vHalfedge[v]);
  const d = out.length;
  const first = boundary ? 1 : 0;
  // each face's far path, by its first and last halfedge, and the halfedge into v after it; all
  // read before the first write
  const firsts = out.map((x) => heNext[x]);
  const entering = out.map((x) => hePrev[x]);
  const lasts = entering.map((x) => hePrev[x]);
  const faces = out.map((x) => heFace[x]);
  const face = faces[first];
  const faceHandle = fHalfedge[face];

  // the far paths, one after another, are the merged face's outline
  for (let i = first; i < d; i++) {
    if (faces[i] !== face) {
      for (let g = firsts[i], k = 0; g !== entering[i] && k < mesh.halfedgeSlots; g = heNext[g], k++) w.setFace(g, face);
    }
    if (i + 1 < d) w.link(lasts[i], firsts[i + 1]);
  }
  if (!boundary) {
    // round the whole fan: the last far path runs on into the first
    w.link(lasts[d - 1], firsts[0]);
  } else {
    // the outline runs from a round to b, and the hole … → a → v → b → …: a new edge closes the
    // face, n = b → a in it, and its twin a → b takes the hole's a → v → b
    const hb = out[0]; // v → b, on the hole
    const hp = entering[0]; // a → v, on the hole (twin of out[1])
    const a = heVertex[hp];
    const b = heVertex[hb ^ 1];
    const n = 2 * ne;
    w.copy('edge', ne, hp >> 1);
    w.copy('halfedge', n, hb ^ 1); // b's corner in the last face
    w.copy('halfedge', n + 1, hp);
    w.setOrigin(n, b);
    w.setOrigin(n + 1, a);
    w.setFace(n, face);
    w.link(lasts[d - 1], n);
    w.link(n, firsts[1]);
    w.link(hePrev[hp], n + 1); // (neither is written above: both lie on the hole)
    w.link(n + 1, heNext[hb]);
    // a's outgoing boundary halfedge was a → v; b's, after v → b, stays
    w.setVertexHalfedge(a, n + 1);
  }
  // the kept face's handle, if it was on one of v's edges
  if (faceHandle === out[first] || faceHandle === entering[first]) w.setFaceHalfedge(face, firsts[first]);
  // a neighbour whose handle ran to v takes the far path's halfedge leaving it (a's is set above)
  for (let i = first; i < d; i++) {
    const u = heVertex[out[i] ^ 1];
    if (vHalfedge[u] === (out[i] ^ 1)) w.setVertexHalfedge(u, firsts[i]);
  }
  for (let i = first + 1; i < d; i++) w.deleteFace(faces[i]);
  for (let i = 0; i < d; i++) w.deleteEdge(out[i] >> 1);
  w.deleteVertex(v);
  return { ...w.result(), face };
}
