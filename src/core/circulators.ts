/**
 * Circulators: the walks every halfedge lecture draws on the blackboard, as generators.
 *
 * Around a face, follow `next`: the halfedges come counter-clockwise.
 * Around a vertex, the next outgoing halfedge counter-clockwise is `twin(prev(h))`:
 * ```
 *             twin(prev(h))
 *                  ▲
 *      prev(h) ╲   │  face(h)
 *               ╲  │
 *                ▼ v ───────► h
 * ```
 * Each walk is bounded by the number of halfedges and throws a `TopologyError` rather than loop
 * forever on a broken mesh.
 *
 * These read well and suit teaching code. Hot paths use the same walk as a plain loop over the
 * arrays, which is what the generators do inside:
 * ```ts
 * const { heNext, heVertex } = mesh;
 * let h = mesh.fHalfedge[f];
 * const start = h;
 * do { visit(heVertex[h]); h = heNext[h]; } while (h !== start);
 * ```
 */
import { TopologyError } from './errors.js';
import type { HalfedgeMesh } from './mesh.js';

/**
 * The halfedges of the cycle through `h` (a face, or a hole when `h` is a boundary halfedge).
 * @example for (const g of loopHalfedges(mesh, h)) console.log(mesh.origin(g));
 */
export function* loopHalfedges(mesh: HalfedgeMesh, h: number): Generator<number> {
  const { heNext } = mesh;
  const limit = mesh.halfedgeSlots;
  let g = h;
  let steps = 0;
  do {
    yield g;
    g = heNext[g];
    if (++steps > limit) throw new TopologyError(`the next cycle from h${h} does not close`);
  } while (g !== h);
}

/**
 * The halfedges of face `f`, counter-clockwise, starting at `faceHalfedge(f)`.
 * @example const degree = [...faceHalfedges(mesh, f)].length;
 */
export function faceHalfedges(mesh: HalfedgeMesh, f: number): Generator<number> {
  return loopHalfedges(mesh, mesh.fHalfedge[f]);
}

/**
 * The vertices of face `f`, counter-clockwise (each halfedge's origin).
 * @example const [a, b, c] = faceVertices(mesh, f);
 */
export function* faceVertices(mesh: HalfedgeMesh, f: number): Generator<number> {
  for (const h of faceHalfedges(mesh, f)) yield mesh.heVertex[h];
}

/**
 * The faces across each edge of `f`, counter-clockwise; -1 where the edge is on the boundary.
 * @example const onBoundary = [...faceAdjacentFaces(mesh, f)].includes(-1);
 */
export function* faceAdjacentFaces(mesh: HalfedgeMesh, f: number): Generator<number> {
  for (const h of faceHalfedges(mesh, f)) yield mesh.heFace[h ^ 1];
}

/**
 * The halfedges leaving `v`, counter-clockwise, starting at `vertexHalfedge(v)` (which is the
 * boundary halfedge on the boundary). Nothing for an isolated vertex.
 * @example for (const h of vertexOutgoingHalfedges(mesh, v)) console.log(mesh.target(h));
 */
export function* vertexOutgoingHalfedges(mesh: HalfedgeMesh, v: number): Generator<number> {
  const start = mesh.vHalfedge[v];
  if (start < 0) return;
  const { hePrev } = mesh;
  const limit = mesh.halfedgeSlots;
  let h = start;
  let steps = 0;
  do {
    yield h;
    h = hePrev[h] ^ 1;
    if (++steps > limit) throw new TopologyError(`the rotation around v${v} does not close`);
  } while (h !== start);
}

/**
 * The halfedges arriving at `v` (the twins of the outgoing ones), counter-clockwise.
 * @example for (const h of vertexIncomingHalfedges(mesh, v)) console.log(mesh.origin(h));
 */
export function* vertexIncomingHalfedges(mesh: HalfedgeMesh, v: number): Generator<number> {
  for (const h of vertexOutgoingHalfedges(mesh, v)) yield h ^ 1;
}

/**
 * The vertices joined to `v` by an edge (its one-ring), counter-clockwise.
 * @example const valence = [...vertexAdjacentVertices(mesh, v)].length;
 */
export function* vertexAdjacentVertices(mesh: HalfedgeMesh, v: number): Generator<number> {
  for (const h of vertexOutgoingHalfedges(mesh, v)) yield mesh.heVertex[h ^ 1];
}

/**
 * The faces around `v`, counter-clockwise (the hole of a boundary vertex is skipped).
 * @example let area = 0; for (const f of vertexAdjacentFaces(mesh, v)) area += faceArea(mesh, f);
 */
export function* vertexAdjacentFaces(mesh: HalfedgeMesh, v: number): Generator<number> {
  for (const h of vertexOutgoingHalfedges(mesh, v)) {
    const f = mesh.heFace[h];
    if (f !== -1) yield f;
  }
}

/**
 * One boundary halfedge per hole; walk the hole with `loopHalfedges`.
 * @example const holes = [...boundaryLoops(mesh)].map((h) => [...loopHalfedges(mesh, h)].length);
 */
export function* boundaryLoops(mesh: HalfedgeMesh): Generator<number> {
  const { heNext, heFace, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const seen = new Uint8Array(nH);
  for (let h = 0; h < nH; h++) {
    if (heFace[h] !== -1 || seen[h] || eDeleted[h >> 1]) continue;
    let g = h;
    let steps = 0;
    do {
      seen[g] = 1;
      g = heNext[g];
      if (++steps > nH) throw new TopologyError(`the boundary loop from h${h} does not close`);
    } while (g !== h);
    yield h;
  }
}
