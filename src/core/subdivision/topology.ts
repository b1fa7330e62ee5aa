/**
 * The topology the subdivision schemes share, each step one bulk pass over the arrays:
 *
 * - `splitEdges`: every listed edge becomes `pieces` edges joined by new vertices (Loop, Butterfly
 *   and Catmull-Clark split every edge in two; √3 splits the boundary in three);
 * - `cutCorners`: each triangle, its edges split, becomes four triangles (Loop, Butterfly);
 * - `addFacePoints` and `fanFaces`: a new vertex in each listed face, joined to every corner
 *   (√3: each triangle becomes three) or to every other corner (Catmull-Clark: a split n-gon
 *   becomes n quads).
 *
 * No step searches for anything: the ids of the new elements follow from the old ones by
 * arithmetic (the new vertex on edge `e` is `V + e`, the three edges that cut the corners of face
 * `f` are `2E + 3f … 2E + 3f + 2`), so each pass writes every pointer of an element once, in a plain
 * loop. Each leaves a mesh that passes `validate()` (faces may have any number of sides in
 * between). What a step changed is not listed here: stepping, the phase that runs the step
 * records it (`ChangeRecorder.wholeMesh`), and straight through no one asks.
 *
 * Vertex attributes: a new vertex takes the linear blend of its sources for attributes of three
 * floats that interpolate linearly (positions, normals, colours as floats; see `stencil.ts`) and the
 * first source's value for the others. A face cut into pieces hands its face attributes to every
 * piece.
 */
import type { AttributeArray } from '../attributes.js';
import type { HalfedgeMesh } from '../mesh.js';
import { faceCentroids, isBlended } from './stencil.js';

/** The first id of each kind that `appendSlots` added. */
export interface FirstIds {
  vertex: number;
  edge: number;
  face: number;
}

/**
 * Appends live, not yet linked slots (room is reserved when needed; a scheme reserves its final
 * counts up front so the arrays grow once per level). The caller links every one.
 */
export function appendSlots(mesh: HalfedgeMesh, vertices: number, edges: number, faces: number): FirstIds {
  const first = { vertex: mesh.vertexSlots, edge: mesh.edgeSlots, face: mesh.faceSlots };
  mesh.reserve({ vertices: first.vertex + vertices, edges: first.edge + edges, faces: first.face + faces });
  mesh.vertexSlots += vertices;
  mesh.edgeSlots += edges;
  mesh.faceSlots += faces;
  mesh.vDeleted.fill(0, first.vertex, mesh.vertexSlots);
  mesh.eDeleted.fill(0, first.edge, mesh.edgeSlots);
  mesh.fDeleted.fill(0, first.face, mesh.faceSlots);
  return first;
}

/**
 * Splits each edge of `edges` (or every edge, in id order) into `pieces` edges of equal length,
 * inserting `pieces − 1` vertices.
 *
 * Ids: the first piece keeps the edge's id and runs from the origin `a` of its even halfedge `2e`;
 * for the `i`-th listed edge, the new vertices (from `a` towards the other end `b`) are
 * `V + (pieces − 1)·i + 0, 1, …` and the other pieces (after the first) are edges
 * `E + (pieces − 1)·i + 0, 1, …`, where V and E are the counts before the split. Each piece's even
 * halfedge runs from `a` towards `b`, as `2e` did.
 *
 * ```
 *   before:  a ───── 2e ──────► b      after (2 pieces):  a ── 2e ──► m ── 2e' ──► b
 *            a ◄──── 2e+1 ───── b                         a ◄─ 2e+1 ─ m ◄─ 2e'+1 ─ b
 * ```
 * `2e + 1` had to change its origin to `m`: its twin `2e` now ends at `m`, and twins run opposite.
 *
 * Every face whose edges were split afterwards starts (`fHalfedge`) at a new vertex, which is where
 * `cutCorners` and `fanFaces` begin their walk.
 *
 * The new vertices are put evenly along their edges (`placeOnEdges`), unless `blendedInPlace`
 * says the caller has already written their blended attributes (see `stencil.ts`) where they end.
 */
export function splitEdges(mesh: HalfedgeMesh, edges: Int32Array | 'all', pieces: number, blendedInPlace = false): void {
  const V = mesh.vertexSlots;
  const E = mesh.edgeSlots;
  const list = edges === 'all' ? null : edges;
  const count = list === null ? E : list.length;
  const edgeAt = (i: number) => (list === null ? i : list[i]);
  const perEdge = pieces - 1;
  const added = perEdge * count;
  appendSlots(mesh, added, added, 0);
  placeOnEdges(mesh, count, edgeAt, pieces, V, blendedInPlace);

  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  // where each old edge is in the list (-1: not split), to find the pieces of a neighbour
  const order = list === null ? null : new Int32Array(E).fill(-1);
  if (order !== null) for (let i = 0; i < count; i++) order[edgeAt(i)] = i;
  const isSplit = (g: number) => order === null || order[g >> 1] >= 0;
  // old halfedge g: the piece that now starts where g started / ends where g ended. Those differ
  // from g only for an odd / even g of a split edge: the last piece of the i-th listed edge is
  // edge E + perEdge·i + perEdge − 1.
  const firstPieceOf = (g: number) => {
    if ((g & 1) === 0 || !isSplit(g)) return g;
    const i = order === null ? g >> 1 : order[g >> 1];
    return 2 * (E + perEdge * i + perEdge - 1) + 1;
  };
  const lastPieceOf = (g: number) => {
    if ((g & 1) === 1 || !isSplit(g)) return g;
    const i = order === null ? g >> 1 : order[g >> 1];
    return 2 * (E + perEdge * i + perEdge - 1);
  };
  // each iteration reads only the old pointers of its own two halfedges (a neighbour that is split
  // too links itself), so the arrays can be rewritten in place
  for (let i = 0; i < count; i++) {
    const h = 2 * edgeAt(i);
    const t = h + 1;
    const hNext = heNext[h];
    const hPrev = hePrev[h];
    const tNext = heNext[t];
    const tPrev = hePrev[t];
    const b = heVertex[t];
    const hFace = heFace[h];
    const tFace = heFace[t];

    // walk from a to b: `forward` is the even halfedge of the piece before new vertex m
    let forward = h;
    for (let p = 0; p < perEdge; p++) {
      const m = V + perEdge * i + p;
      const next = 2 * (E + perEdge * i + p); // even halfedge of the piece after m
      const back = forward ^ 1; // the piece before m, run backwards: it starts at m now
      heVertex[next] = m;
      heFace[next] = hFace;
      heNext[forward] = next;
      hePrev[next] = forward;
      heVertex[back] = m;
      heFace[next + 1] = tFace;
      heNext[next + 1] = back;
      hePrev[back] = next + 1;
      // boundary vertex? its halfedge must be the outgoing boundary one
      vHalfedge[m] = tFace === -1 ? back : next;
      forward = next;
    }
    const bOut = forward ^ 1; // the last piece, run backwards, starts at b
    heVertex[bOut] = b;

    // splice the two chains into the loops around them
    heNext[forward] = firstPieceOf(hNext);
    hePrev[h] = lastPieceOf(hPrev);
    heNext[t] = firstPieceOf(tNext);
    hePrev[bOut] = lastPieceOf(tPrev);
    if (!isSplit(hNext)) hePrev[hNext] = forward;
    if (!isSplit(tPrev)) heNext[tPrev] = bOut;
    // start each face at a new vertex
    if (hFace !== -1) fHalfedge[hFace] = heNext[h];
    if (tFace !== -1) fHalfedge[tFace] = t;
  }
  // an old vertex that left by the odd halfedge of a split edge now leaves by its last piece: one
  // pass in vertex order (asking at each edge whether its far end left by it reads at random)
  for (let v = 0; v < V; v++) {
    const h = vHalfedge[v];
    if (h < 0 || (h & 1) === 0 || !isSplit(h)) continue;
    vHalfedge[v] = firstPieceOf(h);
  }
}

/**
 * Puts the new vertices of `splitEdges` evenly along their edges (run before the split): blended
 * attributes are interpolated (unless `blendedInPlace`), the others copied from the edge's first end.
 */
function placeOnEdges(mesh: HalfedgeMesh, count: number, edgeAt: (i: number) => number, pieces: number, firstVertex: number, blendedInPlace: boolean): void {
  const { heVertex } = mesh;
  for (const attribute of mesh.vertexAttributes) {
    const { data, itemSize: n } = attribute;
    const blend = isBlended(attribute);
    if (blend && blendedInPlace) continue;
    for (let i = 0; i < count; i++) {
      const a = heVertex[2 * edgeAt(i)];
      const b = heVertex[2 * edgeAt(i) + 1];
      for (let p = 1; p < pieces; p++) {
        const m = firstVertex + (pieces - 1) * i + p - 1;
        if (!blend) {
          copyItem(data, n, m, a);
          continue;
        }
        const t = p / pieces;
        data[3 * m] = (1 - t) * data[3 * a] + t * data[3 * b];
        data[3 * m + 1] = (1 - t) * data[3 * a + 1] + t * data[3 * b + 1];
        data[3 * m + 2] = (1 - t) * data[3 * a + 2] + t * data[3 * b + 2];
      }
    }
  }
}

/**
 * Cuts the three corners off every face, after `splitEdges` split every edge of a triangle mesh in
 * two: each face is then a hexagon whose corners alternate between edge points `m` and old
 * vertices, starting (`fHalfedge`) at an edge point.
 * ```
 *            c                          c
 *           / \                        / \             the middle triangle keeps the face id f;
 *         m2   m1          →         m2───m1           the corner triangle after m_i (at b, c
 *         /     \                    / \ f / \         and a) is face F + 3f + i
 *        a ──m0── b                 a ──m0─── b
 * ```
 * New edge `E + 3f + i` joins `m_i` and `m_(i+1)`: its even halfedge runs `m_i → m_(i+1)` inside the
 * middle triangle, its odd one back along the corner triangle.
 */
export function cutCorners(mesh: HalfedgeMesh): void {
  const F = mesh.faceSlots;
  const first = appendSlots(mesh, 0, 3 * F, 3 * F);
  const E = first.edge;
  const { heNext, hePrev, heVertex, heFace, fHalfedge } = mesh;
  const copyFaceAttributes = mesh.faceAttributes.size > 0;

  for (let f = 0; f < F; f++) {
    const firstEdge = E + 3 * f;
    let g = fHalfedge[f]; // m_i → corner i
    for (let i = 0; i < 3; i++) {
      const gOut = heNext[g]; // corner i → m_(i+1)
      const gNext = heNext[gOut]; // m_(i+1) → corner i+1
      const inner = 2 * (firstEdge + i); // m_i → m_(i+1), in the middle triangle
      const outer = inner + 1; // m_(i+1) → m_i, closes the corner triangle
      const corner = F + 3 * f + i;
      heVertex[inner] = heVertex[g];
      heVertex[outer] = heVertex[gNext];
      heNext[gOut] = outer;
      hePrev[outer] = gOut;
      heNext[outer] = g;
      hePrev[g] = outer;
      heFace[g] = corner;
      heFace[gOut] = corner;
      heFace[outer] = corner;
      fHalfedge[corner] = g;
      heFace[inner] = f;
      heNext[inner] = i < 2 ? inner + 2 : 2 * firstEdge;
      hePrev[inner] = i > 0 ? inner - 2 : 2 * firstEdge + 4;
      if (copyFaceAttributes) mesh.faceAttributes.copy(corner, f);
      g = gNext;
    }
    fHalfedge[f] = 2 * firstEdge;
  }
}

/**
 * Adds one vertex per listed face (or every face, in id order) at the mean of its corners (vertex
 * `V + i` for the i-th face), not yet joined to anything: an isolated vertex, which a valid mesh
 * may hold. Only corners numbered below `oldVertices` count: a face whose sides this level has
 * already split keeps the centre of the face it was. A blended attribute (see `stencil.ts`) is
 * left alone when `blendedInPlace` says the caller has already written it there (`faceCentroids`);
 * the others take the value of the face's first corner.
 */
export function addFacePoints(mesh: HalfedgeMesh, faces: Int32Array | 'all', oldVertices = Infinity, blendedInPlace = false): number {
  const count = faces === 'all' ? mesh.faceSlots : faces.length;
  const faceAt = (i: number) => (faces === 'all' ? i : faces[i]);
  const { vertex: V } = appendSlots(mesh, count, 0, 0);
  mesh.vHalfedge.fill(-1, V, V + count);
  const { heVertex, fHalfedge } = mesh;
  for (const attribute of mesh.vertexAttributes) {
    if (isBlended(attribute)) {
      if (!blendedInPlace) faceCentroids(mesh, faces, attribute.data, attribute.data, V, oldVertices);
      continue;
    }
    const { data, itemSize: n } = attribute;
    for (let i = 0; i < count; i++) copyItem(data, n, V + i, heVertex[fHalfedge[faceAt(i)]]);
  }
  return V;
}

/**
 * Joins the point `firstCentre + i` to the corners of the i-th listed face (or of face i, for
 * every face): with `stride` 1 to every corner (a triangle becomes three triangles), with `stride`
 * 2 to every other corner, starting at the face's halfedge (after `splitEdges`, the edge points: a
 * split n-gon becomes n quads).
 * ```
 *   stride 2:   v ── m1 ── w            v ── m1 ── w
 *               │          │            │    │     │
 *               m0   c     m2     →     m0 ─ c ─── m2
 *               │          │            │    │     │
 *               u ── m3 ── x            u ── m3 ── x
 * ```
 * Each spoke is a new edge whose even halfedge leaves the centre, numbered face after face; the
 * piece of the face after its first spoke keeps the face id, the others are new faces, in order.
 */
export function fanFaces(mesh: HalfedgeMesh, faces: Int32Array | 'all', firstCentre: number, stride: number): FirstIds {
  const count = faces === 'all' ? mesh.faceSlots : faces.length;
  const faceAt = (i: number) => (faces === 'all' ? i : faces[i]);
  const spokes = cornersOf(mesh, faces) / stride;
  const first = appendSlots(mesh, 0, spokes, spokes - count);
  fanRange(mesh, { faceAt, begin: 0, end: count, spoke: 0 }, first, firstCentre, stride);
  return first;
}

/** The listed faces `begin … end − 1` of a fan, the first of them with spoke number `spoke` (the spokes of the faces before). */
export interface FanRange {
  faceAt: (i: number) => number;
  begin: number;
  end: number;
  spoke: number;
}

/**
 * `fanFaces` for a range of its faces, in slots already appended from `first` on. Ranges write
 * disjoint slots (a face's own halfedges, its spokes and its pieces), so two threads may fan two
 * ranges at once (see `shared-fan.ts`).
 */
export function fanRange(mesh: HalfedgeMesh, { faceAt, begin, end, spoke }: FanRange, first: FirstIds, firstCentre: number, stride: number): void {
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = mesh;
  const copyFaceAttributes = mesh.faceAttributes.size > 0;
  for (let i = begin; i < end; i++) {
    const f = faceAt(i);
    const centre = firstCentre + i;
    const firstSpoke = 2 * (first.edge + spoke);
    const start = fHalfedge[f];
    let g = start;
    do {
      const piece = g === start ? f : first.face + spoke - i - 1;
      const out = 2 * (first.edge + spoke); // centre → this corner
      heVertex[out] = centre;
      heVertex[out + 1] = heVertex[g];
      heFace[out] = piece;
      heNext[out] = g;
      hePrev[g] = out;
      // the face's own halfedges from this corner to the next one joined
      let last = g;
      heFace[g] = piece;
      for (let s = 1; s < stride; s++) {
        last = heNext[last];
        heFace[last] = piece;
      }
      g = heNext[last];
      const back = g === start ? firstSpoke + 1 : out + 3; // next corner → centre
      heNext[last] = back;
      hePrev[back] = last;
      heNext[back] = out;
      hePrev[out] = back;
      heFace[back] = piece;
      fHalfedge[piece] = out;
      if (copyFaceAttributes && piece !== f) mesh.faceAttributes.copy(piece, f);
      spoke++;
    } while (g !== start);
    vHalfedge[centre] = firstSpoke;
  }
}

/** The number of halfedges inside the listed faces (or all faces): the sum of their degrees. */
function cornersOf(mesh: HalfedgeMesh, faces: Int32Array | 'all'): number {
  let corners = 0;
  if (faces === 'all') {
    const { heFace } = mesh;
    const halfedges = mesh.halfedgeSlots;
    for (let h = 0; h < halfedges; h++) if (heFace[h] !== -1) corners++;
  } else {
    for (const f of faces) corners += mesh.faceDegree(f);
  }
  return corners;
}

/** Element `dst` takes the `n` values of element `src`. */
function copyItem(data: AttributeArray, n: number, dst: number, src: number): void {
  for (let c = 0; c < n; c++) data[n * dst + c] = data[n * src + c];
}
