/**
 * Linear subdivision: Catmull-Clark's topology (a vertex in every face and on every edge, a face of
 * n sides cut into n quads) with the points placed by plain averages, so the surface keeps its
 * shape exactly and only its faces get smaller:
 * - face point: the centroid of the face's corners (the mean of its vertices);
 * - edge point: the midpoint of the edge;
 * - old vertices stay where they are.
 * ```
 *     v ─────── w          v ── e ── w
 *     │         │          │    │    │
 *     │    f    │    →     e ── f ── e        every new point on the old face: a flat quad
 *     │         │          │    │    │        stays flat, a bent one keeps its corners
 *     u ─────── x          u ── e ── x
 * ```
 * It is the first half of Catmull-Clark without its smoothing: comparing the two levels side by
 * side shows what the stencils do. The phases and the counts are Catmull-Clark's (see
 * `catmull-clark.ts`) without "move the old vertices": add face points · split every edge at its
 * midpoint · connect the face points; V' = V + E + F, E' = 2E + C, F' = C, where C = Σ face degrees.
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { addFacePointsPhase, catmullClarkLevel, connectFacePointsPhase, splitAtEdgePoints } from './catmull-clark.js';
import { levelOperation, type SchemeLevel } from './level.js';

/**
 * One level of linear subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(linearSubdivision(mesh)); // every face a quad, the shape unchanged
 */
export function linearSubdivision(mesh: HalfedgeMesh): Operation {
  return levelOperation(mesh, linearLevel);
}

/** A level of linear subdivision, for `level.ts` to run: Catmull-Clark's face points and topology, edge midpoints. */
export const linearLevel: SchemeLevel = {
  scheme: 'linear',
  counts: catmullClarkLevel.counts,
  facePoints: catmullClarkLevel.facePoints,
  edgePoints: edgeMidpoints,
  phases: [
    addFacePointsPhase,
    {
      name: 'split every edge at its edge point',
      explanation:
        'Each edge gets a new vertex at its midpoint: linear subdivision averages, it does not smooth. ' +
        'Every face now has twice as many sides, its corners alternating between old vertices and edge points.',
      topology: splitAtEdgePoints,
    },
    connectFacePointsPhase,
  ],
};

/** Puts the point of each edge e at the edge's midpoint, written to `out` as the values of vertex `first + e`. */
function edgeMidpoints(mesh: HalfedgeMesh, x: ArrayLike<number>, out: Float64Array | Float32Array, first: number): void {
  const { heVertex } = mesh;
  const E = mesh.edgeSlots;
  for (let e = 0; e < E; e++) {
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const m = 3 * (first + e);
    out[m] = (x[a] + x[b]) / 2;
    out[m + 1] = (x[a + 1] + x[b + 1]) / 2;
    out[m + 2] = (x[a + 2] + x[b + 2]) / 2;
  }
}
