import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { parseRemeshArguments, remeshCommand, remeshLoadedMesh } from '../../src/cli/commands/remesh.js';
import { commands } from '../../src/cli/commands/index.js';
import { loadMesh, UsageError } from '../../src/cli/io.js';
import { buildMesh } from '../../src/core/build.js';
import { writeMesh } from '../../src/core/io/index.js';
import { meanEdgeLength } from '../../src/core/remeshing/index.js';
import { cube, uvSphere } from '../../src/core/shapes.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';

describe('remesh IN OUT [--target L] [--iterations N]', () => {
  it('is a command of the CLI', () => {
    expect(commands.remesh).toBe(remeshCommand);
  });

  it('reads the files, the target length and the iterations, each optional', () => {
    expect(parseRemeshArguments(['in.ply', 'out.obj'])).toEqual({ input: 'in.ply', output: 'out.obj', options: {} });
    expect(parseRemeshArguments(['a.off', 'b.off', '--target', '0.02', '--iterations', '5']).options).toEqual({ targetEdgeLength: 0.02, iterations: 5 });
    expect(parseRemeshArguments(['a.off', 'b.off', '--target=1e-3']).options).toEqual({ targetEdgeLength: 0.001 });
  });

  it.each([
    [['a.off', 'b.off', '--target', '0'], "--target must be a number > 0, not '0'"],
    [['a.off', 'b.off', '--target=-1'], "--target must be a number > 0, not '-1'"],
    [['a.off', 'b.off', '--target', 'fine'], "not 'fine'"],
    [['a.off', 'b.off', '--iterations', '0'], "--iterations must be a whole number ≥ 1, not '0'"],
    [['a.off', 'b.off', '--iterations', '2.5'], "not '2.5'"],
    [['a.off', '--target', '1'], 'expected 2 file argument(s), got 1'],
    [['a.off', 'b.off', '--length', '1'], 'length'],
  ])('rejects %j with a usage error', (args, message) => {
    expect(() => parseRemeshArguments(args)).toThrow(UsageError);
    expect(() => parseRemeshArguments(args)).toThrow(message);
  });

  it('remeshes and compacts a mesh, ready for a file', () => {
    const { mesh } = buildMesh(uvSphere(10, 16));
    const target = meanEdgeLength(mesh) / 2;
    const faces = mesh.nFaces;
    expect(remeshLoadedMesh(mesh, { targetEdgeLength: target })).toBeNull();
    expect(mesh.isCompact).toBe(true);
    expect(validate(mesh)).toEqual([]);
    expect(mesh.nFaces).toBeGreaterThan(2 * faces);
  });

  describe('from file to file', () => {
    const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-remesh-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('writes a closed sphere of even triangles', async () => {
      const input = join(dir, 'sphere.ply');
      const output = join(dir, 'even.obj');
      writeFileSync(input, writeMesh(buildMesh(uvSphere(12, 16)).mesh, 'ply-binary'));
      expect(await remeshCommand.run([input, output, '--iterations', '2'])).toBe(0);
      const { mesh, report } = await loadMesh(output);
      expect(report.repairs).toEqual([]);
      expect(validate(mesh)).toEqual([]);
      expect(meshStats(mesh)).toMatchObject({ closed: true, eulerCharacteristic: 2 });
    });

    it('prints the reason on one line and exits with status 2 on quads', async () => {
      const input = join(dir, 'cube.off');
      writeFileSync(input, writeMesh(buildMesh(cube()).mesh, 'off'));
      const stderr = vi.spyOn(console, 'error').mockImplementation(() => {});
      expect(await remeshCommand.run([input, join(dir, 'never.off')])).toBe(2);
      expect(stderr.mock.calls).toEqual([['halfedge-lab: remeshing needs triangles; f0 is a quad. Triangulate the mesh first.']]);
      stderr.mockRestore();
    });
  });
});
