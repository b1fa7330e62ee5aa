import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { cutCommand, cutForFile, parseCutArguments, parsePlane } from '../../src/cli/commands/cut.js';
import { loadMesh, UsageError } from '../../src/cli/io.js';
import { signedVolume } from '../../src/core/geometry.js';
import { cube } from '../../src/core/shapes.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';
import { meshOf } from './helpers.js';

describe('cut command line', () => {
  it('reads the plane as four numbers', async () => {
    expect(parsePlane('0,0,1,-0.5')).toEqual([0, 0, 1, -0.5]);
    expect(parsePlane(' 1e-3, 2 ,3,4')).toEqual([0.001, 2, 3, 4]);
  });

  it('refuses a plane that is not four numbers, or has no direction', async () => {
    expect(() => parsePlane('1,2,3')).toThrow(UsageError);
    expect(() => parsePlane('1,2,3')).toThrow("--plane takes four numbers a,b,c,d, not '1,2,3'");
    expect(() => parsePlane('1,x,0,0')).toThrow("--plane: 'x' (b) is not a number");
    expect(() => parsePlane('1,,0,0')).toThrow("--plane: '' (b) is not a number");
    expect(() => parsePlane('0,0,0,1')).toThrow('a, b and c are all 0');
  });

  it('reads the files, the side to keep and whether to cap', async () => {
    expect(parseCutArguments(['in.ply', 'out.obj', '--plane', '0,0,1,0', '--keep', 'below', '--no-cap'])).toEqual({
      input: 'in.ply',
      output: 'out.obj',
      plane: [0, 0, 1, 0],
      keep: 'below',
      cap: false,
    });
    expect(parseCutArguments(['a.off', 'b.off', '--plane', '1,0,0,0'])).toMatchObject({ keep: 'both', cap: true });
  });

  it('refuses a missing plane, an unknown side and a missing file', async () => {
    expect(() => parseCutArguments(['a.off', 'b.off'])).toThrow('cut needs --plane a,b,c,d');
    expect(() => parseCutArguments(['a.off', 'b.off', '--plane', '0,0,1,0', '--keep', 'left'])).toThrow(
      "--keep takes above, below or both, not 'left'",
    );
    expect(() => parseCutArguments(['a.off', '--plane', '0,0,1,0'])).toThrow(UsageError);
  });

  it('cuts and compacts a mesh, ready for a file', async () => {
    const mesh = meshOf(cube());
    cutForFile(mesh, { plane: [0, 0, 1, -0.5], keep: 'below', cap: true });
    expect(mesh.isCompact).toBe(true);
    expect(validate(mesh)).toEqual([]);
    expect([mesh.nVertices, mesh.nFaces, meshStats(mesh).closed]).toEqual([8, 7, true]);
    expect(signedVolume(mesh)).toBeCloseTo(0.5, 14);
  });

  describe('from file to file', () => {
    const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-cut-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('writes the half below z = 0.5 of a cube, capped', async () => {
      const input = join(dir, 'cube.off');
      const output = join(dir, 'half.off');
      writeFileSync(input, 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n');
      expect(await cutCommand.run([input, output, '--plane', '0,0,1,-0.5', '--keep', 'below'])).toBe(0);
      const { mesh } = await loadMesh(output);
      expect(meshStats(mesh).closed).toBe(true);
      expect(signedVolume(mesh)).toBeCloseTo(0.5, 12);
    });
  });
});
