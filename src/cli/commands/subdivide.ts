import { cannotSubdivide, subdivide, type SubdivisionScheme, subdivisionSchemes } from '../../core/subdivision/index.js';
import type { HalfedgeMesh } from '../../index.js';
import { loadMesh, parseOptions, saveMesh, UsageError } from '../io.js';
import type { Command } from './index.js';

export interface SubdivideArguments {
  scheme: SubdivisionScheme;
  input: string;
  output: string;
  levels: number;
}

/**
 * Reads `SCHEME IN OUT [--levels N]`.
 * @throws UsageError for a scheme that is not one of `subdivisionSchemes`, or levels that are not a
 * whole number ≥ 1.
 */
export function parseSubdivideArguments(args: string[]): SubdivideArguments {
  const { values, positionals } = parseOptions(args, { levels: { type: 'string' } }, 3);
  const [scheme, input, output] = positionals as [string, string, string];
  if (!(subdivisionSchemes as readonly string[]).includes(scheme)) {
    throw new UsageError(`unknown subdivision scheme '${scheme}': use ${subdivisionSchemes.join(', ')}`);
  }
  const levels = values.levels ?? '1';
  if (!/^[1-9][0-9]*$/.test(levels)) throw new UsageError(`--levels must be a whole number ≥ 1, not '${levels}'`);
  return { scheme: scheme as SubdivisionScheme, input, output, levels: Number(levels) };
}

/** Subdivides a loaded mesh in place: null when done, else the sentence saying why the scheme does not apply. */
export function subdivideLoadedMesh(mesh: HalfedgeMesh, scheme: SubdivisionScheme, levels: number): string | null {
  const reason = cannotSubdivide(mesh, scheme);
  if (reason === null) subdivide(mesh, scheme, levels);
  return reason;
}

export const subdivideCommand: Command = {
  usage: 'subdivide SCHEME IN OUT [--levels N]',
  summary: `refine by Loop, Catmull-Clark, Butterfly, √3 or linear subdivision (SCHEME: ${subdivisionSchemes.join(', ')})`,
  async run(args, reading) {
    const { scheme, input, output, levels } = parseSubdivideArguments(args);
    const { mesh } = await loadMesh(input, reading);
    const reason = subdivideLoadedMesh(mesh, scheme, levels);
    if (reason !== null) {
      console.error(`halfedge-lab: ${reason}`);
      return 2;
    }
    await saveMesh(mesh, output);
    return 0;
  },
};
