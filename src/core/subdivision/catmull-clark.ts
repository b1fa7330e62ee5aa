/**
 * Catmull-Clark subdivision (Edwin Catmull and Jim Clark, 1978), for any polygons: a face of n
 * sides becomes n quads, so after one level every face is a quad; repeated levels converge to a
 * bicubic B-spline surface where every vertex has four neighbours.
 * ```
 *     v ─────── w          v ── e ── w
 *     │         │          │    │    │
 *     │    f    │    →     e ── f ── e        f: face point, e: edge points, v, w: old vertices
 *     │         │          │    │    │
 *     u ─────── x          u ── e ── x
 * ```
 * The rules, all from the old mesh:
 * - face point: the mean of the face's corners;
 * - edge point: the mean of the edge's two ends and the two face points beside it;
 * - old vertex P with n edges: (F + 2R + (n − 3)·P) / n, where F is the mean of the n face points
 *   around it and R the mean of the midpoints of its n edges.
 * On the boundary the rules become the cubic B-spline of the boundary polygon: an edge point is
 * the midpoint, a vertex takes 3/4 of itself and 1/8 of its two boundary neighbours, and a corner
 * of valence 2 stays where it is.
 *
 * Phases: add face points · split every edge at its edge point · connect the face points ·
 * move the old vertices. Counts after one level: V' = V + E + F, E' = 2E + C, F' = C, where
 * C = Σ face degrees (the halfedges that have a face; 2E on a closed mesh).
 *
 * Linear subdivision (`linear.ts`) is this topology with plain averages for the points: the level
 * below takes the rule that places them (`QuadRule`).
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../operation.js';
import { compactAtOnce, startLevel } from './preconditions.js';
import { blendedAttributes, moveOldVertices, neighbourSums, storeValues } from './stencil.js';
import { growForLevel, handOver, noIds, type TopologyStep } from './helper-thread.js';
import { prepareSharedFan, sharedFanWork } from './shared-fan.js';
import { addFacePoints, addFacePointSlots, fanFaces, placeFacePoints, range, splitEdges } from './topology.js';

/**
 * One level of Catmull-Clark subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(catmullClark(mesh)); // every face a quad
 */
export function catmullClark(mesh: HalfedgeMesh): Operation {
  compactAtOnce(mesh);
  return catmullClarkLevel(mesh, true);
}

/** The phases of one level; `listIds` false leaves the phases' id lists out (a run straight through). */
export function catmullClarkLevel(mesh: HalfedgeMesh, listIds: boolean): Operation {
  return quadLevel(mesh, listIds, catmullClarkRule);
}

/**
 * Where a level of Catmull-Clark's topology puts its points: Catmull-Clark's stencils, or plain
 * averages (linear subdivision, `linear.ts`). The face points are the mean of their face's corners
 * in both; the topology and its phases are the same.
 */
export interface QuadRule {
  /** Puts the point of each edge e at vertex `firstEdgePoint + e`, the face points being at `firstFacePoint + f`. */
  placeEdgePoints(mesh: HalfedgeMesh, x: Float64Array | Float32Array, E: number, firstFacePoint: number, firstEdgePoint: number): void;
  /** What the phase that splits the edges tells a student about where the edge points go. */
  splitExplanation: string;
  /** The new places of the old vertices (three numbers each), or null when they stay where they are. */
  vertexPoints: ((mesh: HalfedgeMesh, x: ArrayLike<number>, firstFacePoint: number) => Float64Array) | null;
  /** What the phase that moves the old vertices tells a student (with `vertexPoints`). */
  moveExplanation: string;
}

const catmullClarkRule: QuadRule = {
  placeEdgePoints,
  splitExplanation:
    'Each edge gets a new vertex at the mean of its two ends and the two face points beside it (the midpoint, on the boundary). ' +
    'Every face now has twice as many sides, its corners alternating between old vertices and edge points.',
  vertexPoints: catmullClarkVertexPoints,
  moveExplanation:
    'Each old vertex P with n edges moves to (F + 2R + (n − 3)P) / n, ' +
    'where F averages the face points around it and R the midpoints of its old edges. ' +
    'Boundary vertices follow the boundary curve instead (3/4 of themselves, 1/8 of each boundary neighbour), and corners stay put.',
};

/**
 * One level of Catmull-Clark's topology with the points placed by `rule`: add face points, split
 * every edge at its edge point, connect the face points, and (when the rule moves them) move the
 * old vertices.
 */
export function* quadLevel(mesh: HalfedgeMesh, listIds: boolean, rule: QuadRule): Operation {
  startLevel(mesh);
  const V = mesh.vertexSlots;
  const E = mesh.edgeSlots;
  const F = mesh.faceSlots;
  const attributes = blendedAttributes(mesh);

  // reserve memory: one quad per face corner, at most one corner per halfedge (exactly so when
  // the mesh is closed; memory reserved and never written costs nothing). Straight through, a
  // helper thread (when there is one) does the topology steps after the face points in the new
  // arrays while this one works out the new positions from the old ones, then joins the helper in
  // connecting the face points
  const { helper, old } = growForLevel(mesh, listIds, { vertices: V + F + E, edges: 4 * E, faces: 2 * E });

  // compute face vertices (vertex V + f for face f). With a helper, only their slots are added
  // before it takes the arrays over, and their places after, from the old face loops
  const facePoints = helper === null ? addFacePoints(mesh, 'all', listIds) : (addFacePointSlots(mesh, F), noIds);
  const handed = handOver(helper, mesh, 'catmull-clark', V, sharedFanWork);
  if (helper !== null) placeFacePoints(old, 'all', V);
  yield {
    name: 'add face points',
    explanation:
      'Each face gets a new point at the mean of its corners, not yet joined to anything. ' +
      'A vertex without edges is allowed in a halfedge mesh: its halfedge is simply -1 until the points are connected.',
    ...facePoints,
  };

  // the old vertices move last, by a rule that reads their old edges and faces: compute it now
  const vertexPoints = rule.vertexPoints === null ? null : attributes.map((a) => rule.vertexPoints!(old, a.data, V));

  // split edges at their edge points (vertex V + F + e for edge e), placed first while each edge
  // still joins its two ends
  for (const a of attributes) rule.placeEdgePoints(old, a.data, E, V, V + F);
  const step = handed.take(catmullClarkSteps, listIds);
  yield { name: 'split every edge at its edge point', explanation: rule.splitExplanation, ...step(0) };

  // split faces
  yield {
    name: 'connect the face points',
    explanation:
      'Each face point is joined to the edge points around it, cutting a face of n sides into n quads. ' +
      'From now on every face is a quad, whatever the mesh started with.',
    ...step(1),
  };

  // move the old vertices
  if (vertexPoints === null) return;
  storeValues(attributes, vertexPoints, 0);
  yield { name: 'move the old vertices', explanation: rule.moveExplanation, moved: { vertices: range(listIds, 0, V) } };
}

/** The topology of a level after the face points, step by step: split every edge, connect the face points (vertex V + f for face f). */
export const catmullClarkSteps: readonly TopologyStep[] = [
  (mesh, listIds) => splitEdges(mesh, 'all', 2, listIds, true),
  (mesh, listIds, V, fanWork) => {
    if (fanWork === undefined) return fanFaces(mesh, 'all', V, 2, listIds);
    prepareSharedFan(mesh, V, fanWork);
    return noIds;
  },
];

/**
 * Puts the point of each edge e (vertex `firstEdgePoint + e`, in room reserved beyond the vertices
 * in use) at the mean of the edge's two ends and the two face points beside it (vertex
 * `firstFacePoint + f` for face f), or at its midpoint on the boundary.
 */
function placeEdgePoints(mesh: HalfedgeMesh, x: Float64Array | Float32Array, E: number, firstFacePoint: number, firstEdgePoint: number): void {
  const { heFace, heVertex } = mesh;
  for (let e = 0; e < E; e++) {
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const f0 = heFace[2 * e];
    const f1 = heFace[2 * e + 1];
    const m = 3 * (firstEdgePoint + e);
    // boundary edge: the midpoint is the edge point
    if (f0 === -1 || f1 === -1) {
      x[m] = (x[a] + x[b]) / 2;
      x[m + 1] = (x[a + 1] + x[b + 1]) / 2;
      x[m + 2] = (x[a + 2] + x[b + 2]) / 2;
      continue;
    }
    const p = 3 * (firstFacePoint + f0);
    const q = 3 * (firstFacePoint + f1);
    x[m] = ((x[a] + x[b]) / 2 + (x[p] + x[q]) / 2) / 2;
    x[m + 1] = ((x[a + 1] + x[b + 1]) / 2 + (x[p + 1] + x[q + 1]) / 2) / 2;
    x[m + 2] = ((x[a + 2] + x[b + 2]) / 2 + (x[p + 2] + x[q + 2]) / 2) / 2;
  }
}

/**
 * The new place of each old vertex (vertices `0 … firstFacePoint − 1`), three numbers per vertex,
 * read from the old mesh and the face points (vertex `firstFacePoint + f` for face f). For an interior vertex with n edges to
 * neighbours Q_i and n faces with points F_i, (F + 2R + (n − 3)P)/n expands to
 * (ΣQ_i + ΣF_i)/n² + (n − 2)/n · P: both sums are gathered in one pass over the edges.
 */
function catmullClarkVertexPoints(mesh: HalfedgeMesh, x: ArrayLike<number>, firstFacePoint: number): Float64Array {
  const sums = neighbourSums(mesh, x, firstFacePoint, firstFacePoint);
  return moveOldVertices(mesh, x, firstFacePoint, sums, (n) => ({ self: (n - 2) / n, ring: 1 / (n * n) }));
}
