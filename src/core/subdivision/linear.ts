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
import type { Operation } from '../operation.js';
import { quadLevel, type QuadRule } from './catmull-clark.js';
import { compactAtOnce } from './preconditions.js';

/**
 * One level of linear subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(linearSubdivision(mesh)); // every face a quad, the shape unchanged
 */
export function linearSubdivision(mesh: HalfedgeMesh): Operation {
  compactAtOnce(mesh);
  return linearLevel(mesh, true);
}

/** The phases of one level; `listIds` false leaves the phases' id lists out (a run straight through). */
export function linearLevel(mesh: HalfedgeMesh, listIds: boolean): Operation {
  return quadLevel(mesh, listIds, linearRule);
}

const linearRule: QuadRule = {
  placeEdgePoints: placeMidpoints,
  splitExplanation:
    'Each edge gets a new vertex at its midpoint: linear subdivision averages, it does not smooth. ' +
    'Every face now has twice as many sides, its corners alternating between old vertices and edge points.',
  vertexPoints: null,
  moveExplanation: '',
};

/** Puts the point of each edge e (vertex `firstEdgePoint + e`) at the edge's midpoint. */
function placeMidpoints(mesh: HalfedgeMesh, x: Float64Array | Float32Array, E: number, _firstFacePoint: number, firstEdgePoint: number): void {
  const { heVertex } = mesh;
  for (let e = 0; e < E; e++) {
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const m = 3 * (firstEdgePoint + e);
    x[m] = (x[a] + x[b]) / 2;
    x[m + 1] = (x[a + 1] + x[b + 1]) / 2;
    x[m + 2] = (x[a + 2] + x[b + 2]) / 2;
  }
}
