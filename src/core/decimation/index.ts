/**
 * Decimation by quadric error (Garland & Heckbert 1997): make a triangle mesh coarser by
 * collapsing edges, cheapest first, where the cost of a collapse is how far the merged vertex
 * would stand from the planes of the original triangles around it.
 * ```
 *        c                          c
 *      ╱   ╲                        │
 *    a ───── b      collapse      ──x──       x: the point the summed quadric of a and b
 *      ╲   ╱        a–b  ──►        │            likes best; two triangles fewer
 *        d                          d
 * ```
 * 1. Each vertex gets a *quadric* (`quadric.ts`): the sum of the squared-distance forms of the
 *    planes of its triangles, weighted by area. Summing two quadrics sums their planes, so after
 *    any number of collapses a vertex still "remembers" every original plane it stands for.
 * 2. Each edge a–b gets a planned collapse: the point x minimising (Q_a + Q_b)(x) (a 3×3 linear
 *    system; when that is ill-conditioned, the best of a, b and the midpoint) and its cost
 *    (Q_a + Q_b)(x).
 * 3. The cheapest edges are collapsed (`collapseEdge`), many per pass but no two sharing a
 *    vertex, unless that would break the surface or fold it over; each survivor takes Q_a + Q_b,
 *    so the edges around it now cost more, and are planned again for the next pass.
 * Boundaries stay where they are, and the passes are described in `collapses.ts`.
 *
 * Phases: "compute quadrics" (the quadrics; `values.vertices` is the cost of each
 * vertex's cheapest collapse, for a colour map, NaN where none is allowed), then batches of
 * collapses, each taking about `batchFraction` (10% unless said) of the faces left, until the target.
 * A batch carries its record (what it removed, the survivors it moved and rewired) and the new
 * cheapest costs. When stepping, collapsed elements are
 * only marked deleted, never compacted, so ids stay stable across phases and after the last one;
 * call `mesh.compact()` afterwards to drop the deleted slots. Straight through (`decimate`), the
 * mesh is renumbered for speed first.
 *
 * The target: the face count ends at `targetFaces`, or one fewer when the last collapse took two
 * triangles at once (inside a surface every collapse takes two). It ends higher only when no
 * allowed collapse is left: the mesh is as coarse as its topology allows (a closed surface of
 * genus 0 stops at 4 triangles, a tetrahedron), or every collapse left would fold the surface, or
 * exceed `maxError`.
 *
 * @example
 *   decimate(mesh, { targetFaces: 1000 });                       // straight through
 *   for (const phase of decimation(mesh, { targetFaces: 1000 })) show(phase);
 */
import { InvalidInputError, TopologyError } from '../errors.js';
import type { CompactionMaps, HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { ChangeRecorder } from '../change/recorder.js';
import { spatialOrder } from '../spatial-order.js';
import { needsTriangles } from '../triangles.js';
import { Decimator } from './collapses.js';

export interface DecimationOptions {
  /**
   * Faces to keep (default: half of them, or no limit when `maxError` is given). The result has
   * this many, or one fewer (see above).
   */
  targetFaces?: number;
  /**
   * Largest error allowed for a collapse, as a distance in the mesh's units: the root mean square
   * distance of the merged vertex from the planes of the original triangles it stands for
   * (weighted by area). Default: no limit.
   */
  maxError?: number;
  /**
   * Share of the faces left that one phase collapses, in (0, 1]: default 0.1 when stepping, and
   * 1 straight through, where there is nothing to show between phases (a phase ends after the
   * pass that reaches its share, so smaller phases mean more, smaller passes).
   */
  batchFraction?: number;
}

interface DecimationSettings {
  targetFaces: number;
  maxError: number;
  batchFraction: number;
}

/**
 * Null when decimation applies to `mesh`, else a sentence saying why not (it needs triangles).
 * @example cannotDecimate(buildMesh(cube()).mesh, {}) // "decimation needs triangles; f0 is a quad. Triangulate the mesh first."
 * @throws InvalidInputError for a target that is not a whole number ≥ 0, a `maxError` that is
 *   negative or not a number, or a `batchFraction` outside (0, 1].
 */
export function cannotDecimate(mesh: HalfedgeMesh, options: DecimationOptions = {}): string | null {
  settingsOf(mesh, options);
  const reason = needsTriangles(mesh, 'decimation');
  return reason && `${reason} Triangulate the mesh first.`;
}

/**
 * Decimation as a steppable operation that edits `mesh` in place (see above for the phases).
 * @example runOperation(decimation(mesh, { targetFaces: mesh.nFaces / 4 }));
 * @throws TopologyError with the `cannotDecimate` sentence when the mesh has other polygons than
 *   triangles (nothing is changed); InvalidInputError for bad options.
 */
export function decimation(mesh: HalfedgeMesh, options: DecimationOptions = {}): Operation {
  requireApplicable(mesh, options);
  return decimationPhases(mesh, settingsOf(mesh, options), true);
}

/**
 * Decimates `mesh` in place, straight through. The mesh is renumbered first (`spatialOrder`), so
 * that neighbours are near each other in memory: the collapses jump from place to place, and in
 * the order of a mesh refined level by level nearly every step would miss the cache. Returns that
 * renumbering, old id → new id. The deleted slots stay until `mesh.compact()`.
 * @example decimate(mesh, { maxError: 0.001 }); // every collapse that stays within 0.001
 * @throws as `decimation`.
 */
export function decimate(mesh: HalfedgeMesh, options: DecimationOptions = {}): CompactionMaps {
  requireApplicable(mesh, options);
  const settings = settingsOf(mesh, { ...options, batchFraction: options.batchFraction ?? 1 });
  const renumbering = spatialOrder(mesh);
  const phases = decimationPhases(mesh, settings, false);
  while (!phases.next().done) {
    // straight through: the phases matter only when stepping
  }
  return renumbering;
}

/** The phases; `recording` false leaves their records and values out (a run straight through). */
function* decimationPhases(mesh: HalfedgeMesh, settings: DecimationSettings, recording: boolean): Operation {
  const { targetFaces, batchFraction } = settings;

  // compute quadrics (the first pass plans every collapse)
  const decimator = new Decimator(mesh, settings.maxError);
  yield {
    name: 'compute quadrics',
    explanation:
      'Every vertex sums the planes of its triangles into a quadric, a 4×4 matrix that gives the squared distance of any point to all those planes at once, and each boundary edge adds a steep plane that holds the rim in place. ' +
      'Each edge then finds the point where the quadric of its two ends is smallest: that error is the cost of collapsing it, and the colours show the cheapest collapse at each vertex.',
    ...(recording ? { values: { vertices: decimator.cheapestCollapses() }, change: new ChangeRecorder(mesh).record() } : {}),
  };

  // collapse edges in batches, cheapest first
  while (mesh.nFaces > targetFaces && !decimator.exhausted) {
    const before = mesh.nFaces;
    const goal = Math.max(targetFaces, before - Math.max(1, Math.floor(batchFraction * before)));
    const recorder = recording ? new ChangeRecorder(mesh) : null;
    decimator.collapseUntil(goal, recorder);
    if (mesh.nFaces === before) break;
    yield {
      name: `collapse ${before - mesh.nFaces} faces (${mesh.nFaces} left)`,
      explanation:
        'The cheapest edges collapse, no two sharing a vertex, each merging its two ends into one vertex at its best point; the survivor sums both quadrics, and the edges around it get new costs. ' +
        'A collapse that would make the surface non-manifold (the link condition) or turn a triangle over is skipped, so the mesh stays a valid surface.',
      ...(recorder ? { change: recorder.record(), values: { vertices: decimator.cheapestCollapses() } } : {}),
    };
  }
}

function requireApplicable(mesh: HalfedgeMesh, options: DecimationOptions): void {
  const reason = cannotDecimate(mesh, options);
  if (reason !== null) throw new TopologyError(reason);
}

/** Fills in the defaults and checks every option. */
function settingsOf(mesh: HalfedgeMesh, options: DecimationOptions): DecimationSettings {
  const { maxError = Infinity, batchFraction = 0.1 } = options;
  const targetFaces = options.targetFaces ?? (options.maxError === undefined ? Math.floor(mesh.nFaces / 2) : 0);
  if (!Number.isInteger(targetFaces) || targetFaces < 0) {
    throw new InvalidInputError(`decimation: targetFaces must be a whole number ≥ 0, not ${targetFaces}`);
  }
  if (!(maxError >= 0)) throw new InvalidInputError(`decimation: maxError must be a number ≥ 0, not ${maxError}`);
  if (!(batchFraction > 0 && batchFraction <= 1)) {
    throw new InvalidInputError(`decimation: batchFraction must be in (0, 1], not ${batchFraction}`);
  }
  return { targetFaces, maxError, batchFraction };
}
