/**
 * The command line under fuzz: mutated files through `stats --json` and `convert` end with status
 * 0, or 2 and one line on stderr that names the file, the format and the place — never an
 * internal error (status 3) with a stack trace.
 */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { builtInSamples, mutatedSample } from '../../fuzz/readers.js';
import { commands } from '../../src/cli/commands/index.js';
import { reportFailure } from '../../src/cli/io.js';

const SEED = 20261125;
const FILES = 150;
const directory = mkdtempSync(join(tmpdir(), 'halfedge-lab-cli-fuzz-'));
afterAll(() => rmSync(directory, { recursive: true, force: true }));

/** Runs a command in this process as `main` does; its status and what it wrote to stderr. */
async function cli(name: string, args: string[], errors: string[]): Promise<number> {
  errors.length = 0;
  try {
    return await commands[name]!.run(args);
  } catch (error) {
    return reportFailure(error);
  }
}

describe(`the command line on ${FILES} mutated files (seed ${SEED})`, () => {
  const errors: string[] = [];
  beforeEach(() => {
    vi.spyOn(console, 'log').mockImplementation(() => {});
    vi.spyOn(console, 'error').mockImplementation((...parts: unknown[]) => void errors.push(parts.join(' ')));
  });
  afterEach(() => vi.restoreAllMocks());

  it('exits 0, or 2 with one located line on stderr, for stats and convert', async () => {
    // the text and binary mesh formats the command line reads (not halfedge JSON, which it writes)
    const samples = builtInSamples().filter((s) => !s.name.endsWith('.json'));
    const outcomes: string[] = [];
    let refused = 0;
    for (let index = 0; index < FILES; index++) {
      const { sample, bytes } = mutatedSample(samples, SEED, index);
      const file = join(directory, `${index}-${sample}`);
      writeFileSync(file, bytes);
      for (const args of [['stats', file, '--json'], ['convert', file, join(directory, `${index}.off`)]] as const) {
        const status = await cli(args[0], args.slice(1), errors);
        if (status === 2) {
          refused++;
          const located = errors.length === 1 && errors[0]!.startsWith(`halfedge-lab: ${file}: `) && /^halfedge-lab: \S+: (ply|off|obj|stl): /.test(errors[0]!);
          if (!located) outcomes.push(`${args.join(' ')}: status 2 with ${JSON.stringify(errors)}`);
        } else if (status !== 0) {
          outcomes.push(`${args.join(' ')}: status ${status}: ${errors.join(' | ').slice(0, 300)}`);
        }
      }
    }
    expect(outcomes).toEqual([]);
    expect(refused).toBeGreaterThan(FILES / 2);
  });
});
