/** The command line says what a reader dropped from a file that opens (a facet normal that was NaN). */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { stats } from '../../src/cli/commands/stats.js';
import { validateCommand } from '../../src/cli/commands/validate.js';

const dir = mkdtempSync(join(tmpdir(), 'cli-notes-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** An ASCII STL of two facets of a square, the second with a normal written as nan. */
function squareWithNanNormal(): string {
  const path = join(dir, 'square.stl');
  const facet = (normal: string, corners: string[]) => `facet normal ${normal}\nouter loop\n${corners.map((c) => `vertex ${c}\n`).join('')}endloop\nendfacet\n`;
  writeFileSync(path, `solid s\n${facet('0 0 1', ['0 0 0', '1 0 0', '0 1 0'])}${facet('nan nan nan', ['1 0 0', '1 1 0', '0 1 0'])}endsolid s\n`);
  return path;
}

/** What `run` printed, line by line, and its exit status. */
async function printed(run: () => number | Promise<number>): Promise<{ status: number; lines: string[] }> {
  const log = vi.spyOn(console, 'log').mockImplementation(() => {});
  try {
    const status = await run();
    return { status, lines: log.mock.calls.map((call) => String(call[0])) };
  } finally {
    log.mockRestore();
  }
}

describe('the command line on a file with a value it dropped', () => {
  it('stats prints the note naming the facet and where it was read', async () => {
    const { status, lines } = await printed(() => stats.run([squareWithNanNormal()], {}));
    expect(status).toBe(0);
    // the corners STL repeats for each facet, welded, are noted as well
    expect(lines.filter((line) => line.startsWith('note: '))).toEqual([
      'note: welded 6 STL corners into 4 vertices (2 merged)',
      "note: dropped 1 face normal that was NaN or infinite, computed again from the corners of its face (zero for a face without area); the first is face 1's (item 0), at line 9, column 14",
    ]);
  });

  it('validate prints the note too, and the mesh is still clean', async () => {
    const { status, lines } = await printed(() => validateCommand.run([squareWithNanNormal()], {}));
    expect(lines.some((line) => line.startsWith('note: dropped 1 face normal'))).toBe(true);
    expect(lines.at(-1)).toBe('ok: a clean, manifold, oriented mesh');
    expect(status).toBe(0);
  });
});
