import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import * as library from '../../src/index.js';
import { subdivideCommand } from '../../src/cli/commands/subdivide.js';

// the file readers and writers come from src/core/io; until the library exports them, skip
const hasFiles = 'readMesh' in library && 'writeMesh' in library;

describe.skipIf(!hasFiles)('subdivide on real files', () => {
  it('writes an OFF cube after two levels of Catmull-Clark: 96 quads', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'subdivide-'));
    try {
      const input = join(dir, 'cube.off');
      const output = join(dir, 'smooth.off');
      const corners = '0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n';
      const faces = '4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n';
      writeFileSync(input, `OFF\n8 6 12\n${corners}${faces}`);
      expect(await subdivideCommand.run(['catmull-clark', input, output, '--levels', '2'])).toBe(0);
      const counts = readFileSync(output, 'utf8').split('\n').find((line) => /^\d+ \d+ \d+/.test(line));
      expect(counts?.split(' ').slice(0, 2)).toEqual(['98', '96']);
    } finally {
      rmSync(dir, { recursive: true });
    }
  });
});
