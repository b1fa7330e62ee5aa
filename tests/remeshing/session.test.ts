/** Remeshing and linear subdivision in the app's session: started by request, stepped phase by phase, checked, labelled. */
import { describe, expect, it } from 'vitest';
import { buildMesh, cube, TopologyError, uvSphere, writeSoup } from '../../src/index.js';
import { loadFile } from '../../src/workers/load.js';
import { cannotStart, operationLabel } from '../../src/workers/operations.js';
import { EditingSession } from '../../src/workers/session.js';
import { pageSession } from '../workers/page-session.js';

async function sessionOn(bytes: Uint8Array, name: string) {
  const session = new EditingSession();
  session.adopt(await loadFile(bytes, name));
  return pageSession(session);
}

describe('remeshing in the session', () => {
  it('steps four phases an iteration, each valid, and joins the history under its label', async () => {
    const page = await sessionOn(writeSoup(uvSphere(10, 16), 'off'), 'sphere.off');
    expect(page.snapshot().unavailable.remesh).toBeNull();
    const request = { kind: 'remesh', options: { iterations: 2 } } as const;
    expect(page.start(request).stepping).toEqual({ label: 'isotropic remeshing, 2 iterations', phases: 0, total: 8 });
    const names: string[] = [];
    for (let i = 0; i < 8; i++) {
      const snapshot = page.step();
      names.push(snapshot.phase!.name);
      expect(snapshot.problems, snapshot.phase!.name).toEqual([]);
    }
    expect(names[0]).toBe('split long edges (iteration 1 of 2)');
    expect(names[7]).toBe('smooth and project (iteration 2 of 2)');
    const done = page.snapshot();
    expect(done.stepping).toBeNull();
    expect(done.history.items.map((item) => item.label)).toEqual(['open sphere.off', 'isotropic remeshing, 2 iterations']);
    expect(done.stats).toMatchObject({ closed: true, genus: 0 });
  });

  it('names the target length in its label, and refuses quads with the reason', async () => {
    expect(operationLabel({ kind: 'remesh', options: { targetEdgeLength: 0.0123456, iterations: 1 } })).toBe('isotropic remeshing to edges of 0.01235, 1 iteration');
    const page = await sessionOn(writeSoup(cube(), 'off'), 'cube.off');
    const reason = 'remeshing needs triangles; f0 is a quad. Triangulate the mesh first.';
    expect(page.snapshot().unavailable.remesh).toBe(reason);
    expect(() => page.start({ kind: 'remesh', options: {} })).toThrow(new TopologyError(reason));
  });
});

describe('linear subdivision in the session', () => {
  it('starts as { kind: subdivide, scheme: linear } and steps its three phases', async () => {
    const page = await sessionOn(writeSoup(cube(), 'off'), 'cube.off');
    expect(page.snapshot().unavailable.linear).toBeNull();
    expect(cannotStart(buildMesh(cube()).mesh, { kind: 'subdivide', scheme: 'linear' })).toBeNull();
    expect(page.start({ kind: 'subdivide', scheme: 'linear' }).stepping).toMatchObject({ label: 'linear subdivision', total: 3 });
    for (let i = 0; i < 3; i++) expect(page.step().problems).toEqual([]);
    const done = page.snapshot();
    expect(done.stepping).toBeNull();
    expect(done.stats).toMatchObject({ vertices: 26, faces: 24 });
  });
});
