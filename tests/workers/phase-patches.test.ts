/**
 * A stepped phase reaches the page as a patch, like an edit: for every kind of stepped operation,
 * each phase's snapshot carries its record and render writes instead of the whole mesh, and the
 * page's copy, patched, equals the session's mesh (fingerprint) and draws what a fresh layout
 * draws, including the phases that grow the mesh past the room its buffers had. The shown phase
 * marks what the record says, and its pointer diff is the record's.
 */
import { describe, expect, it } from 'vitest';
import { diffPointers, meshFingerprint, torus, uvSphere, writeSoup } from '../../src/index.js';
import { loadFile } from '../../src/workers/load.js';
import type { OperationRequest } from '../../src/workers/operations.js';
import { RenderLayout } from '../../src/workers/render.js';
import { EditingSession } from '../../src/workers/session.js';
import { pageSession } from './page-session.js';
import { drawn } from './drawn.js';

const requests: Array<[string, OperationRequest]> = [
  ['Loop', { kind: 'subdivide', scheme: 'loop' }],
  ['Catmull-Clark', { kind: 'subdivide', scheme: 'catmull-clark' }],
  ['√3', { kind: 'subdivide', scheme: 'sqrt3' }],
  ['Butterfly', { kind: 'subdivide', scheme: 'butterfly' }],
  ['the cut', { kind: 'cut', plane: [0.3, 0.2, 1, 0.1], keep: 'below', cap: true }],
  ['decimation', { kind: 'decimate', options: { targetFaces: 200 } }],
  ['smoothing', { kind: 'smooth', options: { method: 'laplacian', iterations: 2 } }],
  ['remeshing', { kind: 'remesh', options: { iterations: 1 } }],
];

describe('a stepped phase', () => {
  it.each(requests)('reaches the page as a patch, every phase of %s', async (_, request) => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(uvSphere(16, 24), 'off'), 'sphere.off'));
    const page = pageSession(session);
    page.start(request);
    let before = page.page.mesh!.clone();
    let previous: string | undefined;
    for (let phase = 1; ; phase++) {
      const shown = page.step();
      const name = `phase ${phase}: ${shown.phase?.name}`;
      expect(page.patched.at(-1), name).toBe(true);
      expect(meshFingerprint(shown.mesh), name).toBe(session.fingerprint());
      expect(drawn(shown.render), name).toEqual(drawn(new RenderLayout().full(shown.mesh)));
      expect(shown.problems, name).toEqual([]);
      // the diff shown is the comparison of the meshes before and after the phase, up to its
      // limit; a step that finds the operation over (decimation with nothing left to collapse)
      // changes nothing and leaves the last phase on show
      const whole = diffPointers(before, shown.mesh, Infinity);
      const ending = !shown.stepping && shown.phase?.name === previous;
      expect(ending ? 0 : shown.diff!.total, name).toBe(whole.total);
      if (!ending) expect(shown.diff!.changes, name).toEqual(whole.changes.slice(0, shown.diff!.changes.length));
      before = shown.mesh.clone();
      previous = shown.phase?.name;
      if (!shown.stepping) break;
    }
  });

  it('grows the page’s buffers when a level outgrows them, two levels in a row', async () => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(torus(24, 16), 'off'), 'torus.off'));
    const page = pageSession(session);
    for (let level = 1; level <= 2; level++) {
      const before = page.start({ kind: 'subdivide', scheme: 'catmull-clark' }).render.positions;
      let shown;
      do {
        shown = page.step();
        expect(page.patched.at(-1)).toBe(true);
        expect(meshFingerprint(shown.mesh)).toBe(session.fingerprint());
        expect(drawn(shown.render)).toEqual(drawn(new RenderLayout().full(shown.mesh)));
      } while (shown.stepping);
      expect(shown.render.positions, `level ${level} grew the buffers`).not.toBe(before);
      expect(shown.render.positions.length).toBeGreaterThanOrEqual(3 * shown.mesh.vertexSlots);
    }
  });
});
