import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it, vi } from 'vitest';
import { parseSmoothArguments, smoothCommand, smoothLoadedMesh } from '../../src/cli/commands/smooth.js';
import { loadMesh, UsageError } from '../../src/cli/io.js';
import { signedVolume } from '../../src/core/geometry.js';
import { writeMesh } from '../../src/core/io/index.js';
import { cube, uvSphere } from '../../src/core/shapes.js';
import { addNoise, meshOf } from './helpers.js';

describe('smooth IN OUT [--method M] [--iterations N] [--lambda X] [--mu X] [--boundary B]', () => {
  it('reads the files and options, with Taubin and the library defaults when not given', async () => {
    expect(parseSmoothArguments(['in.ply', 'out.obj'])).toEqual({
      input: 'in.ply',
      output: 'out.obj',
      options: { method: 'taubin', iterations: 10, lambda: 0.5, mu: -0.53, boundary: 'fixed' },
    });
    const args = ['a.off', 'b.off', '--method', 'cotan', '--iterations', '3', '--lambda', '0.25', '--mu=-0.3', '--boundary', 'smooth'];
    expect(parseSmoothArguments(args).options).toEqual({ method: 'cotan', iterations: 3, lambda: 0.25, mu: -0.3, boundary: 'smooth' });
  });

  it.each([
    [['a.off', 'b.off', '--method', 'gauss'], "--method takes laplacian, cotan, taubin, not 'gauss'"],
    [['a.off', 'b.off', '--iterations', '0'], "--iterations must be a whole number ≥ 1, not '0'"],
    [['a.off', 'b.off', '--iterations', '2.5'], "not '2.5'"],
    [['a.off', 'b.off', '--lambda', 'half'], "--lambda takes a number, not 'half'"],
    [['a.off', 'b.off', '--mu', ''], "--mu takes a number, not ''"],
    [['a.off', 'b.off', '--mu', '-0.6'], "To specify an option argument starting with a dash use '--mu=-XYZ'"],
    [['a.off', 'b.off', '--boundary', 'free'], "--boundary takes fixed or smooth, not 'free'"],
    [['a.off'], 'expected 2 file argument(s), got 1'],
    [['a.off', 'b.off', '--steps', '3'], 'steps'],
  ])('rejects %j with a usage error', (args, message) => {
    expect(() => parseSmoothArguments(args)).toThrow(UsageError);
    expect(() => parseSmoothArguments(args)).toThrow(message);
  });

  it('says in one sentence why the cotangent method does not apply to quads, and changes nothing', async () => {
    const mesh = meshOf(cube());
    const before = mesh.positions.slice();
    expect(smoothLoadedMesh(mesh, { method: 'cotan' })).toMatch(/^cotangent smoothing needs triangles; f0 is a quad\./);
    expect(mesh.positions).toEqual(before);
  });

  describe('from file to file', () => {
    const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-smooth-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('writes a smoother sphere with the same connectivity', async () => {
      const noisy = meshOf(uvSphere(12, 24));
      addNoise(noisy, 5, 0.03);
      const input = join(dir, 'noisy.ply');
      const output = join(dir, 'smooth.off');
      writeFileSync(input, writeMesh(noisy, 'ply'));
      expect(await smoothCommand.run([input, output, '--method', 'taubin', '--iterations', '20'])).toBe(0);
      const { mesh } = await loadMesh(output);
      expect([mesh.nVertices, mesh.nFaces]).toEqual([noisy.nVertices, noisy.nFaces]);
      expect(mesh.heVertex).toEqual(noisy.heVertex);
      const spread = (m: typeof mesh) => {
        const radii = [...m.vertices()].map((v) => Math.hypot(...m.position(v)));
        return Math.max(...radii) - Math.min(...radii);
      };
      expect(spread(mesh)).toBeLessThan(spread(noisy) / 2);
      expect(Math.abs(signedVolume(mesh) / signedVolume(noisy) - 1)).toBeLessThan(0.05);
    });

    it('prints the reason on one line and exits with status 2 when the method does not apply', async () => {
      const input = join(dir, 'cube.off');
      const output = join(dir, 'never.off');
      writeFileSync(input, writeMesh(meshOf(cube()), 'off'));
      const stderr = vi.spyOn(console, 'error').mockImplementation(() => {});
      expect(await smoothCommand.run([input, output, '--method', 'cotan'])).toBe(2);
      expect(stderr.mock.calls).toEqual([
        ['halfedge-lab: cotangent smoothing needs triangles; f0 is a quad. Use the uniform Laplacian or Taubin, or triangulate the mesh first.'],
      ]);
      stderr.mockRestore();
      await expect(loadMesh(output)).rejects.toThrow(UsageError);
    });
  });
});
