/**
 * A stepped phase reaches the page as an edit does: as a patch (its record and render writes), or,
 * when it rewrites most of the mesh (a subdivision phase), as the whole mesh transferred, with its
 * counts read off its record at once and the full checks after. Either way the page's copy equals
 * the session's mesh (fingerprint) and draws what a fresh layout draws, and the pointer diff shown
 * is the record's.
 */
import { describe, expect, it } from 'vitest';
import { diffPointers, meshFingerprint, seededRandom, torus, uvSphere, writeSoup } from '../../src/index.js';
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
  it.each(requests)('reaches the page as a patch or, rewriting most of the mesh, whole with its counts, every phase of %s', async (_, request) => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(uvSphere(16, 24), 'off'), 'sphere.off'));
    const page = pageSession(session);
    page.start(request);
    let before = page.page.mesh!.clone();
    let previous: string | undefined;
    const patched: boolean[] = [];
    for (let phase = 1; ; phase++) {
      const shown = page.step();
      const name = `phase ${phase}: ${shown.phase?.name}`;
      patched.push(page.patched.at(-1)!);
      expect(meshFingerprint(shown.mesh), name).toBe(session.fingerprint());
      expect(drawn(shown.render), name).toEqual(drawn(new RenderLayout().full(shown.mesh)));
      // the counts read off the record, then the full pass (the page session asks for it at once)
      expect(page.counted.at(-1), name).toBe(true);
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
    // a subdivision phase that rewires every face comes whole; a phase that writes less, a patch
    if (request.kind === 'subdivide') expect(patched.some((p) => !p), 'a subdivision phase came whole').toBe(true);
    expect(patched.some(Boolean), 'a phase came as a patch').toBe(true);
  });
});

describe('a step that moves thousands of vertices of a quad mesh', () => {
  it('redraws the quads whose diagonal changed, and draws what a fresh layout draws', async () => {
    // 5,120 quads crumpled by noise: smoothing them out turns thousands of diagonals the other way
    const soup = torus(80, 64);
    const random = seededRandom(20261128);
    for (let i = 0; i < soup.positions.length; i++) soup.positions[i] += 0.1 * (random() - 0.5);
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(soup, 'off'), 'torus.off'));
    const page = pageSession(session);
    page.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 3 } });
    for (let step = 1; step <= 3; step++) {
      const shown = page.step();
      expect(page.patched.at(-1), `step ${step}`).toBe(true);
      expect(meshFingerprint(shown.mesh), `step ${step}`).toBe(session.fingerprint());
      expect(drawn(shown.render), `step ${step}`).toEqual(drawn(new RenderLayout().full(shown.mesh)));
    }
  });
});
