/** `smooth IN OUT [--method laplacian|cotan|taubin] [--iterations N] [--lambda X] [--mu X] [--boundary fixed|smooth]` */
import type { HalfedgeMesh } from '../../core/mesh.js';
import {
  type BoundaryRule,
  cannotSmooth,
  smooth,
  type SmoothingMethod,
  smoothingMethods,
  type SmoothingOptions,
} from '../../core/smoothing/index.js';
import { loadMesh, parseOptions, saveMesh, UsageError } from '../io.js';
import type { Command } from './index.js';

export interface SmoothArguments {
  input: string;
  output: string;
  options: Required<SmoothingOptions>;
}

/**
 * Reads the command line of `smooth`. The method defaults to Taubin (it keeps the volume), the
 * rest to the library's defaults: 10 iterations, λ = 0.5, μ = −0.53, a fixed boundary. A negative
 * value goes after an equals sign (`--mu=-0.6`), or it would read as an option.
 * @throws UsageError for an unknown method or boundary rule, iterations that are not a whole
 *   number ≥ 1, a λ or μ that is not a number, or not two files.
 */
export function parseSmoothArguments(args: string[]): SmoothArguments {
  const { values, positionals } = parseOptions(
    args,
    { method: { type: 'string' }, iterations: { type: 'string' }, lambda: { type: 'string' }, mu: { type: 'string' }, boundary: { type: 'string' } },
    2,
  );
  const method = values.method ?? 'taubin';
  if (!(smoothingMethods as readonly string[]).includes(method)) {
    throw new UsageError(`--method takes ${smoothingMethods.join(', ')}, not '${method}'`);
  }
  const iterations = values.iterations ?? '10';
  if (!/^[1-9][0-9]*$/.test(iterations)) throw new UsageError(`--iterations must be a whole number ≥ 1, not '${iterations}'`);
  const boundary = values.boundary ?? 'fixed';
  if (boundary !== 'fixed' && boundary !== 'smooth') throw new UsageError(`--boundary takes fixed or smooth, not '${boundary}'`);
  return {
    input: positionals[0]!,
    output: positionals[1]!,
    options: {
      method: method as SmoothingMethod,
      iterations: Number(iterations),
      lambda: parseNumber('--lambda', values.lambda ?? '0.5'),
      mu: parseNumber('--mu', values.mu ?? '-0.53'),
      boundary: boundary as BoundaryRule,
    },
  };
}

function parseNumber(flag: string, text: string): number {
  const value = text.trim() === '' ? NaN : Number(text);
  if (!Number.isFinite(value)) throw new UsageError(`${flag} takes a number, not '${text}'`);
  return value;
}

/** Smooths a loaded mesh in place: null when done, else the sentence saying why the method does not apply. */
export function smoothLoadedMesh(mesh: HalfedgeMesh, options: SmoothingOptions): string | null {
  const reason = cannotSmooth(mesh, options);
  if (reason === null) smooth(mesh, options);
  return reason;
}

export const smoothCommand: Command = {
  usage: 'smooth IN OUT [--method laplacian|cotan|taubin] [--iterations N] [--lambda X] [--mu X] [--boundary fixed|smooth]',
  summary: 'move each vertex towards its neighbours (default Taubin λ|μ, which keeps the volume)',
  async run(args, reading) {
    const { input, output, options } = parseSmoothArguments(args);
    const { mesh } = await loadMesh(input, reading);
    const reason = smoothLoadedMesh(mesh, options);
    if (reason !== null) {
      console.error(`halfedge-lab: ${reason}`);
      return 2;
    }
    await saveMesh(mesh, output);
    return 0;
  },
};
