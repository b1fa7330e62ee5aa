/**
 * Smoothing: move every vertex towards the mean of its neighbours, again and again, so that noise
 * (bumps one or two edges wide) fades while the connectivity stays exactly as it was.
 *
 * | method      | weights (see `laplacian.ts`)                    | one iteration                        |
 * |-------------|-------------------------------------------------|--------------------------------------|
 * | `laplacian` | uniform                                         | a step λ towards the mean            |
 * | `cotan`     | cotangent, from the current shape (triangles)   | a step λ towards the mean            |
 * | `taubin`    | uniform                                         | a step λ > 0, then a step μ < −λ     |
 *
 * A Laplacian step is a low-pass filter, but not a perfect one: it also damps the low frequencies a
 * little, so a closed surface shrinks with every step (a sphere smoothed long enough collapses to a
 * point). Taubin (1995) follows each shrinking step λ with an inflating step μ slightly stronger
 * than λ: the pair damps high frequencies (noise) as before, but passes the low ones (the shape,
 * the volume) almost unchanged. The defaults are λ = 0.5 and μ = −0.53.
 *
 * Cotangent weights are defined on triangles; on a mesh with other polygons `cannotSmooth` refuses
 * the `cotan` method (uniform weights work on any polygon mesh: their neighbours are those along
 * the edges).
 *
 * Phases: one per iteration ("uniform step 3 of 10"); Taubin yields its two steps as two phases,
 * "shrink" and "inflate", so a student sees the surface contract and recover. Each phase lists
 * the vertices it may move and, as `values.vertices`, how far each one moved.
 *
 * @example
 *   smooth(mesh, { method: 'taubin', iterations: 20 });                // straight through
 *   for (const phase of smoothing(mesh, { method: 'cotan' })) show(phase); // step by step
 */
import { InvalidInputError, TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation, Phase } from '../change/operation.js';
import { ChangeRecorder } from '../change/recorder.js';
import { type BoundaryRule, LaplacianSmoother } from './laplacian.js';
import { needsTriangles } from '../triangles.js';

export type { BoundaryRule } from './laplacian.js';

export type SmoothingMethod = 'laplacian' | 'cotan' | 'taubin';

export const smoothingMethods: readonly SmoothingMethod[] = ['laplacian', 'cotan', 'taubin'];

export interface SmoothingOptions {
  method: SmoothingMethod;
  /** Iterations (default 10); a Taubin iteration is a λ step and a μ step. */
  iterations?: number;
  /** The step towards the mean: 0 stays, 1 goes all the way (default 0.5). */
  lambda?: number;
  /** Taubin's inflating step, negative and a little larger than λ in size (default −0.53). */
  mu?: number;
  /** Boundary vertices stay (`fixed`, the default) or follow the boundary curve (`smooth`). */
  boundary?: BoundaryRule;
}

/** The options with their defaults filled in and checked. */
interface SmoothingSettings {
  method: SmoothingMethod;
  iterations: number;
  lambda: number;
  mu: number;
  boundary: BoundaryRule;
}

/**
 * Null when `options.method` applies to `mesh`, else a sentence saying why not: only `cotan`
 * needs something of the mesh (triangles).
 * @example cannotSmooth(buildMesh(cube()).mesh, { method: 'cotan' })
 *   // "cotangent smoothing needs triangles; f0 is a quad. Use the uniform Laplacian or Taubin, or triangulate the mesh first."
 * @throws InvalidInputError for an unknown method or boundary rule, iterations that are not a
 *   whole number ≥ 0, or a λ or μ that is not a finite number.
 */
export function cannotSmooth(mesh: HalfedgeMesh, options: SmoothingOptions): string | null {
  const { method } = settingsOf(options);
  if (method !== 'cotan') return null;
  const reason = needsTriangles(mesh, 'cotangent smoothing');
  return reason && `${reason} Use the uniform Laplacian or Taubin, or triangulate the mesh first.`;
}

/**
 * Smoothing as a steppable operation that moves the vertices of `mesh` in place (see above for
 * the phases).
 * @example runOperation(smoothing(mesh, { method: 'laplacian', iterations: 3, boundary: 'smooth' }));
 * @throws TopologyError with the `cannotSmooth` sentence when the method does not apply (nothing
 *   is changed); InvalidInputError for bad options (as `cannotSmooth`).
 */
export function smoothing(mesh: HalfedgeMesh, options: SmoothingOptions): Operation {
  requireApplicable(mesh, options);
  const settings = settingsOf(options);
  // prepared here rather than in the first phase, so that stepping costs only the steps
  const smoother = new LaplacianSmoother(mesh, settings.boundary);
  return smoothingPhases(smoother, settings, true);
}

/**
 * Smooths `mesh` in place, straight through.
 * @example smooth(mesh, { method: 'taubin', iterations: 50, lambda: 0.6, mu: -0.63 });
 * @throws as `smoothing`.
 */
export function smooth(mesh: HalfedgeMesh, options: SmoothingOptions): void {
  requireApplicable(mesh, options);
  const settings = settingsOf(options);
  const phases = smoothingPhases(new LaplacianSmoother(mesh, settings.boundary), settings, false);
  while (!phases.next().done) {
    // straight through: the phases matter only when stepping
  }
}

/** The phases; `recording` false (a run straight through) leaves out their records and values. */
function* smoothingPhases(smoother: LaplacianSmoother, settings: SmoothingSettings, recording: boolean): Operation {
  const { method, iterations, lambda, mu } = settings;
  const { mesh } = smoother;

  /** One Laplacian step of size `step`, as a phase. */
  const stepPhase = (step: number, name: string, explanation: string): Phase => {
    if (!recording) {
      smoother.step(step);
      return { name, explanation };
    }
    const distances = new Float32Array(mesh.vertexSlots);
    const recorder = new ChangeRecorder(mesh);
    recorder.valueRange('vertex', 0, mesh.vertexSlots);
    smoother.step(step, distances);
    return { name, explanation, change: recorder.record(), values: { vertices: distances } };
  };

  for (let i = 1; i <= iterations; i++) {
    if (method === 'taubin') {
      yield stepPhase(
        lambda,
        `shrink ${i} of ${iterations} (λ = ${lambda})`,
        `Every vertex moves a fraction λ = ${lambda} of the way towards the average of its neighbours, which smooths the noise but also shrinks the surface. ` +
          'The inflating step that follows undoes the shrinking and keeps the smoothing.',
      );
      yield stepPhase(
        mu,
        `inflate ${i} of ${iterations} (μ = ${mu})`,
        `Every vertex moves away from the average of its neighbours by μ = ${mu}, a step a little larger than λ, the other way. ` +
          'Together the two steps damp the short wiggles (noise) but let the overall shape and its volume through nearly unchanged.',
      );
    } else if (method === 'cotan') {
      smoother.useCotangentWeights();
      yield stepPhase(
        lambda,
        `cotangent step ${i} of ${iterations}`,
        `Every vertex moves a fraction λ = ${lambda} of the way towards a weighted average of its neighbours, each edge weighing (cot α + cot β)/2 from the two angles facing it. ` +
          'These weights follow the shape, not the triangulation: a flat patch stays put, and on a curved one vertices move along the normal instead of sliding over the surface.',
      );
    } else {
      yield stepPhase(
        lambda,
        `uniform step ${i} of ${iterations}`,
        `Every vertex moves a fraction λ = ${lambda} of the way towards the plain average of its neighbours, all at once from the old positions. ` +
          'Noise fades quickly, but the whole surface also shrinks a little at every step.',
      );
    }
  }
}

function requireApplicable(mesh: HalfedgeMesh, options: SmoothingOptions): void {
  const reason = cannotSmooth(mesh, options);
  if (reason !== null) throw new TopologyError(reason);
}

/** Fills in the defaults and checks every option. */
function settingsOf(options: SmoothingOptions): SmoothingSettings {
  const { method, iterations = 10, lambda = 0.5, mu = -0.53, boundary = 'fixed' } = options;
  if (!smoothingMethods.includes(method)) {
    throw new InvalidInputError(`unknown smoothing method '${String(method)}': use ${smoothingMethods.join(', ')}`);
  }
  if (!Number.isInteger(iterations) || iterations < 0) {
    throw new InvalidInputError(`smoothing: iterations must be a whole number ≥ 0, not ${iterations}`);
  }
  for (const [name, value] of [
    ['lambda', lambda],
    ['mu', mu],
  ] as const) {
    if (!Number.isFinite(value)) throw new InvalidInputError(`smoothing: ${name} must be a finite number, not ${value}`);
  }
  if (boundary !== 'fixed' && boundary !== 'smooth') {
    throw new InvalidInputError(`smoothing: boundary must be 'fixed' or 'smooth', not '${String(boundary)}'`);
  }
  return { method, iterations, lambda, mu, boundary };
}
