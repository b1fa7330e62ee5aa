import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { decimateCommand, decimateLoadedMesh, parseDecimateArguments } from '../../src/cli/commands/decimate.js';
import { loadMesh, UsageError } from '../../src/cli/io.js';
import { writeMesh } from '../../src/core/io/index.js';
import { cube, uvSphere } from '../../src/core/shapes.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';
import { meshOf } from './helpers.js';

describe('decimate IN OUT --faces N [--max-error D]', () => {
  it('reads the files, the face count and the error limit', async () => {
    expect(parseDecimateArguments(['in.ply', 'out.obj', '--faces', '500'])).toEqual({
      input: 'in.ply',
      output: 'out.obj',
      options: { targetFaces: 500 },
    });
    expect(parseDecimateArguments(['a.off', 'b.off', '--max-error', '1e-3']).options).toEqual({ maxError: 0.001 });
    expect(parseDecimateArguments(['a.off', 'b.off', '--faces', '0', '--max-error', '0.5']).options).toEqual({ targetFaces: 0, maxError: 0.5 });
  });

  it.each([
    [['a.off', 'b.off'], 'decimate needs --faces N (the triangles to keep), or --max-error D'],
    [['a.off', 'b.off', '--faces=-3'], "--faces must be a whole number ≥ 0, not '-3'"],
    [['a.off', 'b.off', '--faces', '1e3'], "not '1e3'"],
    [['a.off', 'b.off', '--faces', 'many'], "not 'many'"],
    [['a.off', 'b.off', '--max-error=-1'], "--max-error must be a number ≥ 0, not '-1'"],
    [['a.off', 'b.off', '--max-error', 'small'], "not 'small'"],
    [['a.off', '--faces', '10'], 'expected 2 file argument(s), got 1'],
    [['a.off', 'b.off', '--triangles', '10'], 'triangles'],
  ])('rejects %j with a usage error', (args, message) => {
    expect(() => parseDecimateArguments(args)).toThrow(UsageError);
    expect(() => parseDecimateArguments(args)).toThrow(message);
  });

  it('decimates and compacts a mesh, ready for a file', async () => {
    const mesh = meshOf(uvSphere(10, 16));
    expect(decimateLoadedMesh(mesh, { targetFaces: 40 })).toBeNull();
    expect(mesh.isCompact).toBe(true);
    expect(validate(mesh)).toEqual([]);
    expect([mesh.nVertices, mesh.nFaces]).toEqual([22, 40]);
  });

  describe('from file to file', () => {
    const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-decimate-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('writes a sphere of 100 triangles, closed, from one of 480', async () => {
      const input = join(dir, 'sphere.ply');
      const output = join(dir, 'coarse.obj');
      writeFileSync(input, writeMesh(meshOf(uvSphere(16, 16)), 'ply-binary'));
      expect(await decimateCommand.run([input, output, '--faces', '100'])).toBe(0);
      const { mesh, report } = await loadMesh(output);
      expect(report.repairs).toEqual([]);
      expect(mesh.nFaces).toBe(100);
      expect(meshStats(mesh)).toMatchObject({ closed: true, eulerCharacteristic: 2 });
    });

    it('prints the reason on one line and exits with status 2 on quads', async () => {
      const input = join(dir, 'cube.off');
      writeFileSync(input, writeMesh(meshOf(cube()), 'off'));
      const stderr = vi.spyOn(console, 'error').mockImplementation(() => {});
      expect(await decimateCommand.run([input, join(dir, 'never.off'), '--faces', '4'])).toBe(2);
      expect(stderr.mock.calls).toEqual([['halfedge-lab: decimation needs triangles; f0 is a quad. Triangulate the mesh first.']]);
      stderr.mockRestore();
    });
  });
});
