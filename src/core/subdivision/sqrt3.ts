/**
 * √3 subdivision (Leif Kobbelt, 2000), for triangle meshes: a point in each triangle, joined to
 * its corners, then every old edge flipped to join two of the new points. Each level triples the
 * number of triangles (Loop quadruples it), so the resolution grows more gently; two levels
 * split every old edge in three, and each level turns the triangulation by 30° against the one
 * before, so the orientation alternates from level to level.
 * ```
 *         c                   c                   c
 *        / \                 /|\                 / \
 *       /   \               / p \               / p \
 *      a ─── b     →       a─/ \─b     →       a  |  b
 *       \   /               \ q /               \ q /
 *        \ /                 \|/                 \ /
 *         d                   d                   d
 *   two triangles      a face point in each,   the old edge ab, flipped,
 *                      joined to its corners   now joins p and q
 * ```
 * The rules: a face point at the centroid; an old interior vertex with n neighbours moves to
 * (1 − α_n)·itself + α_n·(mean of its neighbours), α_n = (4 − 2cos(2π/n))/9.
 *
 * The boundary follows Kobbelt's rule, in two kinds of level. On even levels (0, 2, …) boundary
 * edges are not flipped and boundary vertices stay put. On odd levels (1, 3, …) each boundary edge
 * is split in three, its triangle is fanned from the corner opposite it (and gets no face point),
 * and the boundary is smoothed as a curve: an old boundary vertex moves to (4, 19, 4)/27 of
 * itself and its two boundary neighbours, and the new points on edge P2P3 of boundary P1 P2 P3 P4
 * go to (P1 + 16·P2 + 10·P3)/27 and (10·P2 + 16·P3 + P4)/27. Two levels thus refine the boundary
 * by three, in step with the inside. An operation cannot tell which level it runs: pass `level`
 * (`subdivide` does). A triangle with two or three boundary edges (only possible on a mesh that
 * did not come from an even level) cannot be fanned from one corner; on odd levels it gets a face
 * point at its centroid, joined to all its corners, old and new.
 *
 * Phases: [odd levels with a boundary: split the boundary edges in three · join the boundary
 * points to the opposite corners] · insert face points · flip the old edges · relax the old
 * vertices. Counts after an even level (or any level of a closed mesh): V' = V + F, E' = E + 3F,
 * F' = 3F.
 */
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { compactAtOnce, requireApplicable, startLevel } from './preconditions.js';
import { addScaled, blendedAttributes, neighbourSums, storeValues } from './stencil.js';
import { addFacePoints, appendSlots, fanFaces, splitEdges } from './topology.js';
import { ChangeRecorder } from '../change/recorder.js';

export interface SubdivisionOptions {
  /**
   * Which level of a sequence this run is, counting from 0 (default 0). Only √3 reads it: on odd
   * levels it splits the boundary, on even ones it keeps it.
   */
  level?: number;
}

/**
 * One level of √3 subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(sqrt3Subdivision(mesh, { level: 0 })); // F → 3F triangles
 * @throws TopologyError when a face is not a triangle (nothing is changed).
 * @throws InvalidInputError when `level` is not a whole number ≥ 0.
 */
export function sqrt3Subdivision(mesh: HalfedgeMesh, options: SubdivisionOptions = {}): Operation {
  const level = options.level ?? 0;
  if (!Number.isInteger(level) || level < 0) {
    throw new InvalidInputError(`√3 subdivision: level must be a whole number ≥ 0, not ${level}`);
  }
  requireApplicable(mesh, 'sqrt3');
  compactAtOnce(mesh);
  return sqrt3Level(mesh, true, level);
}

/** The phases of level `level`; `recording` false leaves the phases' records out (a run straight through). */
export function* sqrt3Level(mesh: HalfedgeMesh, recording: boolean, level: number): Operation {
  // each phase's record: of a topology step, which rewires the whole mesh, or of the moved vertices
  let recorder: ChangeRecorder | null = null;
  const record = (before: (recorder: ChangeRecorder) => void = (r) => r.wholeMesh()) => {
    recorder = recording ? new ChangeRecorder(mesh) : null;
    if (recorder) before(recorder);
  };
  const recorded = () => (recorder ? { change: recorder.record() } : {});
  const oddLevel = level % 2 === 1;
  startLevel(mesh);
  const V = mesh.vertexSlots;
  const E = mesh.edgeSlots;
  const F = mesh.faceSlots;
  const boundary = boundaryEdges(mesh);
  const splitBoundary = oddLevel && boundary.length > 0;
  const newBoundaryPoints = splitBoundary ? 2 * boundary.length : 0;

  // compute the new positions while the old one-rings are intact
  const attributes = blendedAttributes(mesh);
  const vertexPoints = attributes.map((a) => sqrt3VertexPoints(mesh, a.data, splitBoundary));
  const boundaryPoints = splitBoundary ? attributes.map((a) => sqrt3BoundaryPoints(mesh, a.data, boundary)) : [];

  // reserve memory (at most this much: a triangle fanned from its corner needs less)
  mesh.reserve({ vertices: V + F + newBoundaryPoints, edges: E + 3 * F + 2 * newBoundaryPoints, faces: 3 * F + newBoundaryPoints });

  // split the boundary (odd levels); the triangles fanned from their corner get no face point
  let faces: Int32Array | 'all' = 'all';
  if (splitBoundary) {
    const beforeBoundary = trianglesOnOneBoundaryEdge(mesh, boundary);
    record();
    splitEdges(mesh, boundary, 3);
    yield {
      name: 'split the boundary edges in three',
      explanation:
        'On every other level, √3 refines the boundary: each boundary edge gets two new vertices, a third of the way from either end. ' +
        'Two levels of √3 split every inner edge in three too, so this keeps the boundary in step with the inside.',
      ...recorded(),
    };
    const fanned = new Uint8Array(F);
    for (const h of beforeBoundary) fanned[mesh.heFace[h]] = 1;
    faces = marked(fanned.map((skip) => 1 - skip));
    record();
    fanFromOppositeCorners(mesh, beforeBoundary);
    yield {
      name: 'join the boundary points to the opposite corners',
      explanation:
        'Each boundary triangle, now with five corners, is cut into three triangles ' +
        'by joining its two new points to the corner facing the boundary. ' +
        'These triangles get no face point on this level: the boundary has already been refined.',
      ...recorded(),
    };
  }

  // insert face points and split faces
  record();
  addFacePoints(mesh, faces, V);
  fanFaces(mesh, faces, V + newBoundaryPoints, 1);
  yield {
    name: 'insert face points',
    explanation:
      (splitBoundary ? 'Each triangle away from the boundary' : 'Each triangle') +
      ' gets a new vertex at its centroid, joined to its three corners: one triangle becomes three. ' +
      'No edge is split, so the new triangles are thin; the next phase fixes their shape.',
    ...recorded(),
  };

  // flip the old edges
  record();
  flipOldEdges(mesh, E);
  yield {
    name: 'flip the old edges',
    explanation:
      'Every old edge between two triangles is flipped, so that it joins the two face points beside it instead of two old vertices. ' +
      'The triangles are well shaped again, and the mesh is turned by 30° against the old one: two levels together split each old edge in three.',
    ...recorded(),
  };

  // relax the old vertices (and place the new boundary points)
  record((r) => r.valueRange('vertex', 0, V + newBoundaryPoints));
  storeValues(attributes, vertexPoints, 0);
  if (splitBoundary) storeValues(attributes, boundaryPoints, V);
  yield {
    name: 'relax the old vertices',
    explanation:
      'Each old vertex with n neighbours moves towards their mean by α = (4 − 2cos(2π/n))/9, the weight that makes the limit surface smooth. ' +
      (splitBoundary
        ? 'On this level the boundary is smoothed as a curve: old boundary vertices take 4/27, 19/27, 4/27 ' +
          'of themselves and their neighbours, and the new boundary points their own cubic weights.'
        : 'On this level the boundary vertices stay where they are; the boundary is refined and smoothed on the next level.'),
    ...recorded(),
  };
}

/** The indices where `marks` is 1. */
function marked(marks: Uint8Array): Int32Array {
  let count = 0;
  for (let i = 0; i < marks.length; i++) count += marks[i];
  const ids = new Int32Array(count);
  let k = 0;
  for (let i = 0; i < marks.length; i++) if (marks[i] === 1) ids[k++] = i;
  return ids;
}

/** The edges with a boundary halfedge, in id order. */
function boundaryEdges(mesh: HalfedgeMesh): Int32Array {
  const { heFace } = mesh;
  const marks = new Uint8Array(mesh.edgeSlots);
  for (let e = 0; e < mesh.edgeSlots; e++) marks[e] = heFace[2 * e] === -1 || heFace[2 * e + 1] === -1 ? 1 : 0;
  return marked(marks);
}

/**
 * For each triangle with exactly one boundary edge, the halfedge before that edge inside the
 * triangle: it runs from the opposite corner, and the split of the boundary leaves it in place.
 */
function trianglesOnOneBoundaryEdge(mesh: HalfedgeMesh, boundary: Int32Array): Int32Array {
  const { hePrev, heFace } = mesh;
  const inside = (e: number) => (heFace[2 * e] === -1 ? 2 * e + 1 : 2 * e);
  const count = new Uint8Array(mesh.faceSlots);
  for (const e of boundary) count[heFace[inside(e)]]++;
  return Int32Array.from(boundary.filter((e) => count[heFace[inside(e)]] === 1), (e) => hePrev[inside(e)]);
}

/**
 * Cuts each boundary triangle that `splitEdges` turned into a pentagon (a, p, q, b, x) into three
 * triangles by joining x to p and q. `before[i]` is the halfedge x → a of the i-th one; the two
 * new edges of the i-th are `E + 2i` (p–x) and `E + 2i + 1` (q–x), its new faces `F + 2i` (p q x)
 * and `F + 2i + 1` (q b x), while (a p x) keeps the face id.
 */
function fanFromOppositeCorners(mesh: HalfedgeMesh, before: Int32Array): void {
  const count = before.length;
  const first = appendSlots(mesh, 0, 2 * count, 2 * count);
  const { heNext, hePrev, heVertex, heFace, fHalfedge } = mesh;
  const link = (g: number, next: number) => {
    heNext[g] = next;
    hePrev[next] = g;
  };
  for (let i = 0; i < count; i++) {
    const xa = before[i];
    const ap = heNext[xa];
    const pq = heNext[ap];
    const qb = heNext[pq];
    const bx = heNext[qb];
    const f = heFace[xa];
    const pqx = first.face + 2 * i;
    const qbx = pqx + 1;
    const px = 2 * (first.edge + 2 * i); // p → x; px + 1 runs x → p
    const qx = px + 2; // q → x; qx + 1 runs x → q
    const x = heVertex[xa];
    heVertex[px] = heVertex[pq];
    heVertex[px + 1] = x;
    heVertex[qx] = heVertex[qb];
    heVertex[qx + 1] = x;
    // (a p x) keeps f
    link(ap, px);
    link(px, xa);
    heFace[px] = f;
    fHalfedge[f] = ap;
    // (p q x)
    link(pq, qx);
    link(qx, px + 1);
    link(px + 1, pq);
    heFace[pq] = heFace[qx] = heFace[px + 1] = pqx;
    fHalfedge[pqx] = pq;
    // (q b x)
    link(bx, qx + 1);
    link(qx + 1, qb);
    heFace[qb] = heFace[bx] = heFace[qx + 1] = qbx;
    fHalfedge[qbx] = qb;
    if (mesh.faceAttributes.size > 0) {
      mesh.faceAttributes.copy(pqx, f);
      mesh.faceAttributes.copy(qbx, f);
    }
  }
}

/**
 * Flips every interior edge with id below `oldEdges`. After `fanFaces`, each such edge a–b lies
 * between two triangles (a, b, p) and (b, a, q), each holding no other old edge, so all the flips
 * are independent and can be written in place, reading only the edge's own two halfedges:
 * ```
 *        p                 p
 *       / \               /|\          h: a → b  becomes  q → p, in (p, a, q)
 *      a─h─b     →       a | b         t: b → a  becomes  p → q, in (q, b, p)
 *       \ /               \|/
 *        q                 q
 * ```
 */
function flipOldEdges(mesh: HalfedgeMesh, oldEdges: number): void {
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  for (let e = 0; e < oldEdges; e++) {
    const h = 2 * e;
    const t = h + 1;
    const hFace = heFace[h];
    const tFace = heFace[t];
    // boundary edge: never flipped
    if (hFace === -1 || tFace === -1) continue;
    const pa = hePrev[h]; // p → a
    const bp = heNext[h]; // b → p
    const qb = hePrev[t]; // q → b
    const aq = heNext[t]; // a → q
    const a = heVertex[h];
    const b = heVertex[t];
    // (p, a, q) keeps h's face: p → a → q → p
    heNext[pa] = aq;
    heNext[aq] = h;
    heNext[h] = pa;
    hePrev[aq] = pa;
    hePrev[h] = aq;
    hePrev[pa] = h;
    heVertex[h] = heVertex[qb];
    heFace[aq] = hFace;
    fHalfedge[hFace] = h;
    // (q, b, p) keeps t's face: q → b → p → q
    heNext[qb] = bp;
    heNext[bp] = t;
    heNext[t] = qb;
    hePrev[bp] = qb;
    hePrev[t] = bp;
    hePrev[qb] = t;
    heVertex[t] = heVertex[pa];
    heFace[bp] = tFace;
    fHalfedge[tFace] = t;
    // a vertex whose halfedge was the flipped one takes another that still leaves it
    if (vHalfedge[a] === h) vHalfedge[a] = aq;
    if (vHalfedge[b] === t) vHalfedge[b] = bp;
  }
}

/** The new place of each old vertex, three numbers per vertex. */
function sqrt3VertexPoints(mesh: HalfedgeMesh, x: ArrayLike<number>, splitBoundary: boolean): Float64Array {
  const { hePrev, heVertex, heFace, vHalfedge } = mesh;
  const { sums: out, valence } = neighbourSums(mesh, x, mesh.vertexSlots);
  for (let v = 0; v < mesh.vertexSlots; v++) {
    const o = 3 * v;
    const start = vHalfedge[v];
    // isolated vertex, or boundary vertex on a level that keeps the boundary?
    if (start === -1 || (heFace[start] === -1 && !splitBoundary)) {
      out[o] = x[o];
      out[o + 1] = x[o + 1];
      out[o + 2] = x[o + 2];
    }
    // boundary vertex on a level that splits the boundary: the curve rule
    else if (heFace[start] === -1) {
      const next = 3 * heVertex[start ^ 1];
      const prev = 3 * heVertex[hePrev[start]];
      out[o] = (19 * x[o] + 4 * (x[next] + x[prev])) / 27;
      out[o + 1] = (19 * x[o + 1] + 4 * (x[next + 1] + x[prev + 1])) / 27;
      out[o + 2] = (19 * x[o + 2] + 4 * (x[next + 2] + x[prev + 2])) / 27;
    }
    // interior vertex: (1 − α) of itself, α of the mean of its neighbours
    else {
      const n = valence[v];
      const alpha = (4 - 2 * Math.cos((2 * Math.PI) / n)) / 9;
      out[o] = (1 - alpha) * x[o] + (alpha / n) * out[o];
      out[o + 1] = (1 - alpha) * x[o + 1] + (alpha / n) * out[o + 1];
      out[o + 2] = (1 - alpha) * x[o + 2] + (alpha / n) * out[o + 2];
    }
  }
  return out;
}

/**
 * The two new points of each listed boundary edge, in the order `splitEdges` creates them (from
 * the origin of the edge's even halfedge), three numbers each.
 */
function sqrt3BoundaryPoints(mesh: HalfedgeMesh, x: ArrayLike<number>, boundary: Int32Array): Float64Array {
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const out = new Float64Array(6 * boundary.length);
  for (let i = 0; i < boundary.length; i++) {
    const e = boundary[i];
    const g = heFace[2 * e] === -1 ? 2 * e : 2 * e + 1; // the boundary halfedge, P2 → P3
    const p1 = heVertex[hePrev[g]];
    const p2 = heVertex[g];
    const p3 = heVertex[heNext[g]];
    const p4 = heVertex[heNext[heNext[g]]];
    // the point nearer P2 comes first when P2 is the origin of the even halfedge
    const nearP2 = 3 * (2 * i + (g === 2 * e ? 0 : 1));
    const nearP3 = 3 * (2 * i + (g === 2 * e ? 1 : 0));
    addScaled(out, nearP2, x, p1, 1 / 27);
    addScaled(out, nearP2, x, p2, 16 / 27);
    addScaled(out, nearP2, x, p3, 10 / 27);
    addScaled(out, nearP3, x, p2, 10 / 27);
    addScaled(out, nearP3, x, p3, 16 / 27);
    addScaled(out, nearP3, x, p4, 1 / 27);
  }
  return out;
}
