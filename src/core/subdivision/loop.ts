/**
 * Loop subdivision (Charles Loop, 1987), for triangle meshes: each triangle becomes four, and
 * repeated levels converge to a smooth surface (a quartic box spline where every vertex has six
 * neighbours).
 * ```
 *          c                    c                      c
 *         / \                  / \                    / \
 *        /   \     split      m   m      cut the     m───m
 *       /     \    edges     /     \     corners    / \ / \
 *      a───────b    →       a───m───b      →       a───m───b
 * ```
 * The new points are placed by stencils, weighted sums over the old mesh:
 * - the point on edge ab (an *odd* vertex): 3/8 of a and b, 1/8 of the two opposite corners c, d;
 * - an old (*even*) vertex with n neighbours: (1 − nβ) of itself and β of each neighbour, with
 *   Loop's β = (1/n)(5/8 − (3/8 + ¼·cos(2π/n))²), which is 1/16 for n = 6.
 * On the boundary the stencils become the cubic B-spline of the boundary polygon: an edge point is
 * the midpoint, a vertex takes 3/4 of itself and 1/8 of its two boundary neighbours.
 *
 * Phases: split every edge · cut the corners · place the edge points · move the old vertices.
 * Counts after one level: V' = V + E, E' = 2E + 3F, F' = 4F.
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { levelOperation, type SchemeLevel, type TopologyStep } from './level.js';
import { moveOldVertices, neighbourSums } from './stencil.js';
import { cutCorners, splitEdges } from './topology.js';

/**
 * One level of Loop subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(loopSubdivision(mesh)); // F → 4F triangles
 * @throws TopologyError when a face is not a triangle (nothing is changed).
 */
export function loopSubdivision(mesh: HalfedgeMesh): Operation {
  return levelOperation(mesh, loopLevel);
}

/**
 * Loop's topology, which Butterfly shares: split every edge in two (run straight through, the
 * edge points are already where they end; stepped, they wait at the midpoints: see `level.ts`),
 * then cut the corners.
 */
export const splitEveryEdge: TopologyStep = (mesh, recording) => splitEdges(mesh, 'all', 2, !recording);
export const cutEveryCorner: TopologyStep = (mesh) => cutCorners(mesh);

/** A level of Loop subdivision, for `level.ts` to run: reserve, edge points, vertex points, split. */
export const loopLevel: SchemeLevel = {
  scheme: 'loop',
  counts: (V, E, F) => ({ vertices: V + E, edges: 2 * E + 3 * F, faces: 4 * F }),
  edgePoints: loopEdgePoints,
  vertexPoints: loopVertexPoints,
  phases: [
    {
      name: 'split every edge',
      explanation:
        'Each edge gets a new vertex at its midpoint, so every triangle becomes a hexagon whose corners alternate between old and new vertices. ' +
        'A halfedge mesh allows faces of any degree, so the mesh is still valid between the two steps of the refinement.',
      topology: splitEveryEdge,
    },
    {
      name: 'cut the corners',
      explanation:
        'Three new edges join the edge points of each face, cutting off its corners: one triangle becomes four similar ones. ' +
        'The mesh now has its final connectivity, but every point still sits on the old, flat triangles.',
      topology: cutEveryCorner,
    },
    {
      name: 'place the edge points',
      explanation:
        'Each edge point moves to 3/8 of the edge’s two ends plus 1/8 of the two corners facing the edge ' +
        '(on the boundary it stays at the midpoint). ' +
        'The weights come from the box spline that a regular triangle mesh converges to, and they use the old positions only.',
      moves: 'edge points',
    },
    {
      name: 'move the old vertices',
      explanation:
        'Each old vertex moves towards the average of its old neighbours, by Loop’s weight β that depends only on how many neighbours it has. ' +
        'Boundary vertices follow the boundary curve instead (3/4 of themselves, 1/8 of each boundary neighbour), so an open surface keeps its rim.',
      moves: 'old vertices',
    },
  ],
};

/**
 * The odd stencil: the new point of each edge e, three numbers per edge, written to `out` as the
 * values of vertex `first + e`.
 */
function loopEdgePoints(mesh: HalfedgeMesh, x: ArrayLike<number>, out: Float64Array | Float32Array, first: number): void {
  const { hePrev, heVertex, heFace } = mesh;
  const E = mesh.edgeSlots;
  for (let e = 0; e < E; e++) {
    const h = 2 * e;
    const t = h + 1;
    const o = 3 * (first + e);
    const a = 3 * heVertex[h];
    const b = 3 * heVertex[t];
    // boundary edge?
    if (heFace[h] === -1 || heFace[t] === -1) {
      out[o] = (x[a] + x[b]) / 2;
      out[o + 1] = (x[a + 1] + x[b + 1]) / 2;
      out[o + 2] = (x[a + 2] + x[b + 2]) / 2;
      continue;
    }
    // interior edge: the corner facing the edge in each triangle starts the halfedge before it
    const c = 3 * heVertex[hePrev[h]];
    const d = 3 * heVertex[hePrev[t]];
    out[o] = (3 / 8) * (x[a] + x[b]) + (1 / 8) * (x[c] + x[d]);
    out[o + 1] = (3 / 8) * (x[a + 1] + x[b + 1]) + (1 / 8) * (x[c + 1] + x[d + 1]);
    out[o + 2] = (3 / 8) * (x[a + 2] + x[b + 2]) + (1 / 8) * (x[c + 2] + x[d + 2]);
  }
}

/**
 * The even stencil: the new place of each old vertex, three numbers per vertex. An interior vertex
 * with n neighbours keeps 1 − nβ of itself and takes β of each neighbour.
 */
function loopVertexPoints(mesh: HalfedgeMesh, x: ArrayLike<number>): Float64Array {
  // sum the old neighbours of every vertex, edge by edge
  const sums = neighbourSums(mesh, x, mesh.vertexSlots);
  return moveOldVertices(mesh, x, mesh.vertexSlots, sums, (n) => {
    const beta = loopBeta(n);
    return { self: 1 - n * beta, ring: beta };
  });
}

/** Loop's weight of each neighbour of a vertex with `n` neighbours: (1/n)(5/8 − (3/8 + ¼·cos(2π/n))²). */
function loopBeta(n: number): number {
  const w = 3 / 8 + Math.cos((2 * Math.PI) / n) / 4;
  return (5 / 8 - w * w) / n;
}
