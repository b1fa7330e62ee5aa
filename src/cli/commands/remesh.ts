/** `remesh IN OUT [--target L] [--iterations N]`: isotropic remeshing, triangles of one edge length. */
import type { HalfedgeMesh } from '../../core/mesh.js';
import { cannotRemesh, remesh, type RemeshingOptions } from '../../core/remeshing/index.js';
import { loadMesh, parseOptions, saveMesh, UsageError } from '../io.js';
import type { Command } from './index.js';

export interface RemeshArguments {
  input: string;
  output: string;
  options: RemeshingOptions;
}

/**
 * Reads the command line of `remesh`: the target edge length (default: the input's mean edge
 * length) and the iterations (default 3).
 * @throws UsageError for a length that is not a number > 0, iterations that are not a whole
 *   number ≥ 1, or not two files.
 */
export function parseRemeshArguments(args: string[]): RemeshArguments {
  const { values, positionals } = parseOptions(args, { target: { type: 'string' }, iterations: { type: 'string' } }, 2);
  const options: RemeshingOptions = {};
  if (values.target !== undefined) {
    const text = values.target;
    const target = text.trim() === '' ? NaN : Number(text);
    if (!(target > 0 && target < Infinity)) throw new UsageError(`--target must be a number > 0, not '${text}'`);
    options.targetEdgeLength = target;
  }
  if (values.iterations !== undefined) {
    if (!/^[1-9][0-9]*$/.test(values.iterations)) throw new UsageError(`--iterations must be a whole number ≥ 1, not '${values.iterations}'`);
    options.iterations = Number(values.iterations);
  }
  return { input: positionals[0]!, output: positionals[1]!, options };
}

/** Remeshes a loaded mesh (compacted, ready for a file): null when done, else the sentence saying why remeshing does not apply. */
export function remeshLoadedMesh(mesh: HalfedgeMesh, options: RemeshingOptions): string | null {
  const reason = cannotRemesh(mesh, options);
  if (reason === null) remesh(mesh, options);
  return reason;
}

export const remeshCommand: Command = {
  usage: 'remesh IN OUT [--target L] [--iterations N]',
  summary: 'isotropic remeshing: triangles with edges of length L (default the mean edge length), N iterations (default 3)',
  async run(args, reading) {
    const { input, output, options } = parseRemeshArguments(args);
    const { mesh } = await loadMesh(input, reading);
    const reason = remeshLoadedMesh(mesh, options);
    if (reason !== null) {
      console.error(`halfedge-lab: ${reason}`);
      return 2;
    }
    await saveMesh(mesh, output);
    return 0;
  },
};
