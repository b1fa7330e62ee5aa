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
 * Linear subdivision (`linear.ts`) is this topology with plain averages for the points: it takes
 * the face points and the phases of the topology from here.
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { type LevelPhase, levelOperation, type SchemeLevel, type TopologyStep } from './level.js';
import { connectFacePoints } from './shared-fan.js';
import { faceCentroids, moveOldVertices, neighbourSums } from './stencil.js';
import { addFacePoints, splitEdges } from './topology.js';

/**
 * One level of Catmull-Clark subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(catmullClark(mesh)); // every face a quad
 */
export function catmullClark(mesh: HalfedgeMesh): Operation {
  return levelOperation(mesh, catmullClarkLevel);
}

/** The phase that adds the face points, already placed (see `level.ts`). */
export const addFacePointsPhase: LevelPhase = {
  name: 'add face points',
  explanation:
    'Each face gets a new point at the mean of its corners, not yet joined to anything. ' +
    'A vertex without edges is allowed in a halfedge mesh: its halfedge is simply -1 until the points are connected.',
  topology: (mesh) => void addFacePoints(mesh, 'all', Infinity, true),
};

/** Splits every edge at its edge point, already placed (vertex V + F + e for edge e). */
export const splitAtEdgePoints: TopologyStep = (mesh) => splitEdges(mesh, 'all', 2, true);

/** The phase that joins each face point to the edge points around it (vertex V + f for face f). */
export const connectFacePointsPhase: LevelPhase = {
  name: 'connect the face points',
  explanation:
    'Each face point is joined to the edge points around it, cutting a face of n sides into n quads. ' +
    'From now on every face is a quad, whatever the mesh started with.',
  topology: connectFacePoints,
};

/** A level of Catmull-Clark subdivision, for `level.ts` to run. */
export const catmullClarkLevel: SchemeLevel = {
  scheme: 'catmull-clark',
  // one quad per face corner, at most one corner per halfedge (exactly so when the mesh is closed;
  // memory reserved and never written costs nothing)
  counts: (V, E, F) => ({ vertices: V + F + E, edges: 4 * E, faces: 2 * E }),
  facePoints: (old, x, out, first) => faceCentroids(old, 'all', x, out, first),
  edgePoints: catmullClarkEdgePoints,
  vertexPoints: catmullClarkVertexPoints,
  phases: [
    addFacePointsPhase,
    {
      name: 'split every edge at its edge point',
      explanation:
        'Each edge gets a new vertex at the mean of its two ends and the two face points beside it (the midpoint, on the boundary). ' +
        'Every face now has twice as many sides, its corners alternating between old vertices and edge points.',
      topology: splitAtEdgePoints,
    },
    connectFacePointsPhase,
    {
      name: 'move the old vertices',
      explanation:
        'Each old vertex P with n edges moves to (F + 2R + (n − 3)P) / n, ' +
        'where F averages the face points around it and R the midpoints of its old edges. ' +
        'Boundary vertices follow the boundary curve instead (3/4 of themselves, 1/8 of each boundary neighbour), and corners stay put.',
      moves: 'old vertices',
    },
  ],
};

/**
 * The edge points: the point of each edge e at the mean of the edge's two ends and the two face
 * points beside it (vertex V + f for face f, already placed in `x`), or at its midpoint on the
 * boundary, written to `out` as the values of vertex `first + e`.
 */
function catmullClarkEdgePoints(mesh: HalfedgeMesh, x: ArrayLike<number>, out: Float64Array | Float32Array, first: number): void {
  const E = mesh.edgeSlots;
  const firstFacePoint = mesh.vertexSlots;
  const { heFace, heVertex } = mesh;
  for (let e = 0; e < E; e++) {
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const f0 = heFace[2 * e];
    const f1 = heFace[2 * e + 1];
    const m = 3 * (first + e);
    // boundary edge: the midpoint is the edge point
    if (f0 === -1 || f1 === -1) {
      out[m] = (x[a] + x[b]) / 2;
      out[m + 1] = (x[a + 1] + x[b + 1]) / 2;
      out[m + 2] = (x[a + 2] + x[b + 2]) / 2;
      continue;
    }
    const p = 3 * (firstFacePoint + f0);
    const q = 3 * (firstFacePoint + f1);
    out[m] = ((x[a] + x[b]) / 2 + (x[p] + x[q]) / 2) / 2;
    out[m + 1] = ((x[a + 1] + x[b + 1]) / 2 + (x[p + 1] + x[q + 1]) / 2) / 2;
    out[m + 2] = ((x[a + 2] + x[b + 2]) / 2 + (x[p + 2] + x[q + 2]) / 2) / 2;
  }
}

/**
 * The new place of each old vertex (vertices `0 … V − 1`), three numbers per vertex, read from the
 * old mesh and the face points (vertex V + f for face f). For an interior vertex with n edges to
 * neighbours Q_i and n faces with points F_i, (F + 2R + (n − 3)P)/n expands to
 * (ΣQ_i + ΣF_i)/n² + (n − 2)/n · P: both sums are gathered in one pass over the edges.
 */
function catmullClarkVertexPoints(mesh: HalfedgeMesh, x: ArrayLike<number>): Float64Array {
  const firstFacePoint = mesh.vertexSlots;
  const sums = neighbourSums(mesh, x, firstFacePoint, firstFacePoint);
  return moveOldVertices(mesh, x, firstFacePoint, sums, (n) => ({ self: (n - 2) / n, ring: 1 / (n * n) }));
}
