/** `decimate IN OUT --faces N [--max-error D]`: fewer triangles, by quadric error edge collapse. */
import { cannotDecimate, decimate, type DecimationOptions } from '../../core/decimation/index.js';
import type { HalfedgeMesh } from '../../core/mesh.js';
import { loadMesh, parseOptions, saveMesh, UsageError } from '../io.js';
import type { Command } from './index.js';

export interface DecimateArguments {
  input: string;
  output: string;
  options: DecimationOptions;
}

/**
 * Reads the command line of `decimate`: at least one of `--faces` (the triangles to keep) and
 * `--max-error` (the largest error allowed, in the mesh's units).
 * @throws UsageError for neither, a face count that is not a whole number ≥ 0, an error that is
 *   not a number ≥ 0, or not two files.
 */
export function parseDecimateArguments(args: string[]): DecimateArguments {
  const { values, positionals } = parseOptions(args, { faces: { type: 'string' }, 'max-error': { type: 'string' } }, 2);
  if (values.faces === undefined && values['max-error'] === undefined) {
    throw new UsageError('decimate needs --faces N (the triangles to keep), or --max-error D');
  }
  const options: DecimationOptions = {};
  if (values.faces !== undefined) {
    if (!/^[0-9]+$/.test(values.faces)) throw new UsageError(`--faces must be a whole number ≥ 0, not '${values.faces}'`);
    options.targetFaces = Number(values.faces);
  }
  if (values['max-error'] !== undefined) {
    const text = values['max-error'];
    const maxError = text.trim() === '' ? NaN : Number(text);
    if (!(maxError >= 0 && maxError < Infinity)) throw new UsageError(`--max-error must be a number ≥ 0, not '${text}'`);
    options.maxError = maxError;
  }
  return { input: positionals[0]!, output: positionals[1]!, options };
}

/**
 * Decimates a loaded mesh and compacts it (files have no room for deleted slots): null when done,
 * else the sentence saying why decimation does not apply.
 */
export function decimateLoadedMesh(mesh: HalfedgeMesh, options: DecimationOptions): string | null {
  const reason = cannotDecimate(mesh, options);
  if (reason !== null) return reason;
  decimate(mesh, options);
  mesh.compact();
  return null;
}

export const decimateCommand: Command = {
  usage: 'decimate IN OUT --faces N [--max-error D]',
  summary: 'collapse edges by quadric error down to N triangles (or until the error passes D)',
  async run(args, reading) {
    const { input, output, options } = parseDecimateArguments(args);
    const { mesh } = await loadMesh(input, reading);
    const reason = decimateLoadedMesh(mesh, options);
    if (reason !== null) {
      console.error(`halfedge-lab: ${reason}`);
      return 2;
    }
    await saveMesh(mesh, output);
    return 0;
  },
};
