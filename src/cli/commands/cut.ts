/** `cut IN OUT --plane a,b,c,d [--keep above|below|both] [--no-cap]`: cut a mesh with a plane. */
import { cutMesh, type KeepSide } from '../../core/cut/index.js';
import type { HalfedgeMesh } from '../../core/mesh.js';
import type { Phase } from '../../core/change/operation.js';
import { loadMesh, parseOptions, saveMesh, UsageError } from '../io.js';
import type { Command } from './index.js';

export interface CutArguments {
  input: string;
  output: string;
  plane: [number, number, number, number];
  keep: KeepSide;
  cap: boolean;
}

/**
 * Reads the command line of `cut`.
 * @throws UsageError for a missing or malformed `--plane`, an unknown `--keep`, or not two files.
 */
export function parseCutArguments(args: string[]): CutArguments {
  const { values, positionals } = parseOptions(
    args,
    { plane: { type: 'string' }, keep: { type: 'string' }, 'no-cap': { type: 'boolean' } },
    2,
  );
  if (values.plane === undefined) throw new UsageError('cut needs --plane a,b,c,d (the plane a·x + b·y + c·z + d = 0)');
  const keep = values.keep ?? 'both';
  if (keep !== 'above' && keep !== 'below' && keep !== 'both') {
    throw new UsageError(`--keep takes above, below or both, not '${keep}'`);
  }
  return { input: positionals[0]!, output: positionals[1]!, plane: parsePlane(values.plane), keep, cap: !values['no-cap'] };
}

/**
 * `a,b,c,d` → the four numbers.
 * @throws UsageError when there are not four numbers, or (a, b, c) is zero.
 */
export function parsePlane(text: string): [number, number, number, number] {
  const parts = text.split(',');
  if (parts.length !== 4) throw new UsageError(`--plane takes four numbers a,b,c,d, not '${text}'`);
  const numbers = parts.map((part) => (part.trim() === '' ? NaN : Number(part)));
  const bad = numbers.findIndex((x) => !Number.isFinite(x));
  if (bad !== -1) throw new UsageError(`--plane: '${parts[bad]}' (${'abcd'[bad]}) is not a number`);
  if (numbers[0] === 0 && numbers[1] === 0 && numbers[2] === 0) {
    throw new UsageError('--plane: a, b and c are all 0, so the plane has no direction');
  }
  return numbers as [number, number, number, number];
}

/** Cuts `mesh` as asked and compacts it (files have no room for deleted slots); returns the phases. */
export function cutForFile(mesh: HalfedgeMesh, { plane, keep, cap }: Pick<CutArguments, 'plane' | 'keep' | 'cap'>): Phase[] {
  const phases = cutMesh(mesh, plane, { keep, cap });
  mesh.compact();
  return phases;
}

export const cutCommand: Command = {
  usage: 'cut IN OUT --plane a,b,c,d [--keep above|below|both] [--no-cap]',
  summary: 'cut with the plane a·x + b·y + c·z + d = 0 (above: > 0), keep a side, cap the cut',
  async run(args, reading) {
    const options = parseCutArguments(args);
    const { mesh } = await loadMesh(options.input, reading);
    cutForFile(mesh, options);
    await saveMesh(mesh, options.output);
    return 0;
  },
};
