import { describe, expect, it, vi } from 'vitest';
import { cube, type HalfedgeMesh, tetrahedron } from '../../src/index.js';
import { parseSubdivideArguments, subdivideCommand, subdivideLoadedMesh } from '../../src/cli/commands/subdivide.js';
import { loadMesh, saveMesh, UsageError } from '../../src/cli/io.js';
import { meshArrays, meshOf } from './helpers.js';

// the command's logic without files: loading hands over a built cube, saving is recorded
vi.mock('../../src/cli/io.js', async (importOriginal) => ({
  ...(await importOriginal<typeof import('../../src/cli/io.js')>()),
  loadMesh: vi.fn(),
  saveMesh: vi.fn(),
}));

describe('subdivide SCHEME IN OUT [--levels N]', () => {
  it('reads the scheme, the files and the levels (1 when not given)', async () => {
    expect(parseSubdivideArguments(['loop', 'in.ply', 'out.ply'])).toEqual({ scheme: 'loop', input: 'in.ply', output: 'out.ply', levels: 1 });
    expect(parseSubdivideArguments(['sqrt3', 'a.off', 'b.obj', '--levels', '3']).levels).toBe(3);
  });

  it.each([
    [['doo-sabin', 'in.ply', 'out.ply'], /unknown subdivision scheme 'doo-sabin': use loop, catmull-clark, butterfly, sqrt3/],
    [['loop', 'in.ply', 'out.ply', '--levels', '0'], /--levels must be a whole number ≥ 1, not '0'/],
    [['loop', 'in.ply', 'out.ply', '--levels', '1.5'], /not '1.5'/],
    [['loop', 'in.ply', 'out.ply', '--levels', 'two'], /not 'two'/],
    [['loop', 'in.ply'], /expected 3 file argument/],
    [['loop', 'in.ply', 'out.ply', '--level', '2'], /level/],
  ])('rejects %j with a usage error', (args, message) => {
    expect(() => parseSubdivideArguments(args)).toThrow(UsageError);
    expect(() => parseSubdivideArguments(args)).toThrow(message);
  });

  it('subdivides a loaded mesh, or says in one sentence why the scheme does not apply', async () => {
    const quads = meshOf(cube());
    const before = meshArrays(quads);
    expect(subdivideLoadedMesh(quads, 'loop', 1)).toBe('Loop subdivision needs triangles; f0 is a quad. Triangulate the mesh first.');
    expect(meshArrays(quads)).toEqual(before);
    expect(subdivideLoadedMesh(quads, 'catmull-clark', 2)).toBeNull();
    expect(quads.nFaces).toBe(6 * 4 * 4);
  });

  it('runs: load, subdivide, save; exit status 0', async () => {
    vi.mocked(loadMesh).mockResolvedValue({ mesh: meshOf(tetrahedron()) } as Awaited<ReturnType<typeof loadMesh>>);
    expect(await subdivideCommand.run(['butterfly', 'in.ply', 'out.ply', '--levels', '2'], { weldTolerance: 0.5 })).toBe(0);
    expect(loadMesh).toHaveBeenCalledWith('in.ply', { weldTolerance: 0.5 });
    const [saved, path] = vi.mocked(saveMesh).mock.lastCall as [HalfedgeMesh, string];
    expect([saved.nFaces, path]).toEqual([4 * 16, 'out.ply']);
  });

  it('prints the reason on one line and exits with status 2 when the scheme does not apply', async () => {
    vi.mocked(loadMesh).mockResolvedValue({ mesh: meshOf(cube()) } as Awaited<ReturnType<typeof loadMesh>>);
    vi.mocked(saveMesh).mockClear();
    const stderr = vi.spyOn(console, 'error').mockImplementation(() => {});
    expect(await subdivideCommand.run(['sqrt3', 'cube.off', 'out.off'])).toBe(2);
    expect(stderr.mock.calls).toEqual([['halfedge-lab: √3 subdivision needs triangles; f0 is a quad. Triangulate the mesh first.']]);
    expect(saveMesh).not.toHaveBeenCalled();
    stderr.mockRestore();
  });
});
