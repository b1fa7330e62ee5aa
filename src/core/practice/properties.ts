/**
 * Grading by properties, for the operations with no single right answer (isotropic remeshing,
 * simplification): two correct solutions split, collapse and flip in different orders and end on
 * different meshes, so the result is checked for what the operation promises instead of being
 * compared with the library's, one property after another, and the first that fails is said:
 *
 * ```
 *   triangles ─► same topology ─► target reached ─► near the input
 *   (every face)  (per component:   (edge lengths,     (both ways, within a share
 *                  χ and holes)      or face count)     of the input's size)
 * ```
 */
import { boundingBox } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import { NearestTriangle } from '../remeshing/nearest-triangle.js';
import { meanEdgeLength } from '../remeshing/remesher.js';
import { meshStats } from '../stats.js';
import { needsTriangles } from '../triangles.js';
import type { ExerciseInput } from './exercise.js';

/**
 * What an exercise graded by properties asks of the result, beside a valid mesh of triangles with
 * the input's topology. The input names the target (`targetEdgeLength` or `faces`).
 */
export interface ResultBounds {
  /**
   * At least this share of the edges is within 4/5 … 4/3 of the input's `targetEdgeLength` (the
   * band isotropic remeshing splits and collapses toward).
   */
  shareNearTarget?: number;
  /** At most the input's `faces` faces, and at least this share of that many. */
  shareOfTargetFaces?: number;
  /**
   * Every vertex of the result within this distance of the input surface, and every vertex of the
   * input within it of the result, as a share of the input's bounding-box diagonal.
   */
  maxDistance: number;
}

/** Null when `yours` (from `input`, the fixture's mesh) has every property `bounds` asks for, else the first it lacks. */
export function checkProperties(yours: HalfedgeMesh, before: HalfedgeMesh, input: ExerciseInput | undefined, bounds: ResultBounds): string | null {
  return needsTriangles(yours, 'the result') ?? sameTopology(yours, before) ?? targetReached(yours, input, bounds) ?? nearTheInput(yours, before, bounds.maxDistance);
}

/** Null when both meshes have the same components, each with the same Euler characteristic and number of holes. */
function sameTopology(yours: HalfedgeMesh, before: HalfedgeMesh): string | null {
  const shapes = (mesh: HalfedgeMesh) =>
    meshStats(mesh)
      .componentDetails.map((c) => `χ = ${c.eulerCharacteristic} with ${c.boundaryLoops} boundary loop${c.boundaryLoops === 1 ? '' : 's'}`)
      .sort();
  const [mine, theirs] = [shapes(yours), shapes(before)];
  if (mine.length !== theirs.length) return `the result has ${mine.length} component${mine.length === 1 ? '' : 's'}; the input has ${theirs.length}: remeshing keeps the topology`;
  const differs = mine.findIndex((shape, i) => shape !== theirs[i]);
  return differs === -1 ? null : `the topology changed: a component of the result has ${mine[differs]}, where the input's has ${theirs[differs]}`;
}

function targetReached(yours: HalfedgeMesh, input: ExerciseInput | undefined, bounds: ResultBounds): string | null {
  const named = typeof input === 'object' && !Array.isArray(input) ? (input as { readonly [name: string]: number }) : {};
  if (bounds.shareNearTarget !== undefined) {
    const L = named.targetEdgeLength;
    let near = 0;
    for (const e of yours.edges()) {
      const length = edgeLength(yours, e);
      if (length >= (4 / 5) * L && length <= (4 / 3) * L) near++;
    }
    const share = near / Math.max(1, yours.nEdges);
    if (share < bounds.shareNearTarget) {
      return `${percent(share)} of your ${yours.nEdges} edges are within 4/5 … 4/3 of the target length ${L}; at least ${percent(bounds.shareNearTarget)} must be`;
    }
  }
  if (bounds.shareOfTargetFaces !== undefined) {
    const target = named.faces;
    const least = Math.ceil(bounds.shareOfTargetFaces * target);
    if (yours.nFaces > target || yours.nFaces < least) return `your mesh has ${yours.nFaces} faces; the target is ${target} (from ${least} up to ${target} pass)`;
  }
  return null;
}

/** Null when each surface is within `maxDistance` (a share of the input's diagonal) of the other. */
function nearTheInput(yours: HalfedgeMesh, before: HalfedgeMesh, maxDistance: number): string | null {
  const box = boundingBox(before)!;
  const diagonal = Math.hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]);
  const bound = maxDistance * diagonal;
  const farthest = (from: HalfedgeMesh, to: HalfedgeMesh) => {
    // cells about as large as the edges keep a few triangles in each (see NearestTriangle)
    const surface = new NearestTriangle(to, meanEdgeLength(to));
    let worst = { vertex: -1, distance: 0 };
    for (const v of from.vertices()) {
      const [x, y, z] = from.position(v);
      const distance = Math.sqrt(surface.nearest(x, y, z, -1));
      if (distance > worst.distance) worst = { vertex: v, distance };
    }
    return worst;
  };
  const away = farthest(yours, before);
  if (away.distance > bound) return `your v${away.vertex} is ${away.distance.toPrecision(3)} from the input surface; at most ${bound.toPrecision(3)} is allowed (${percent(maxDistance)} of its size)`;
  const uncovered = farthest(before, yours);
  if (uncovered.distance > bound) return `the input's v${uncovered.vertex} is ${uncovered.distance.toPrecision(3)} from your surface; at most ${bound.toPrecision(3)} is allowed (${percent(maxDistance)} of its size): part of the shape is lost`;
  return null;
}

function edgeLength(mesh: HalfedgeMesh, e: number): number {
  const [a, b] = [mesh.position(mesh.heVertex[2 * e]), mesh.position(mesh.heVertex[2 * e + 1])];
  return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

function percent(share: number): string {
  return `${Math.round(share * 100)} %`;
}
