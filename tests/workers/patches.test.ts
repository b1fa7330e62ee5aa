/**
 * The page's copy, patched by snapshots, against the session's own mesh: after every step of a
 * random mix of edits, undos, redos, jumps and operation phases, the copy has the same fingerprint
 * (every array equal) and its render buffers draw what a fresh layout of the mesh draws; and it
 * says truly when its live ids stay as they were.
 */
import { describe, expect, it } from 'vitest';
import { meshFingerprint, seededRandom, torus, uvSphere, writeSoup } from '../../src/index.js';
import { loadFile } from '../../src/workers/load.js';
import type { PageSnapshot } from '../../src/workers/page-copy.js';
import { RenderLayout } from '../../src/workers/render.js';
import { EditingSession } from '../../src/workers/session.js';
import { drawn } from './drawn.js';
import { pageSession, randomEdit } from './page-session.js';

describe('the page copy, patched', () => {
  it.each([
    ['a sphere of triangles', () => writeSoup(uvSphere(12, 16), 'off')],
    ['a torus of quads', () => writeSoup(torus(8, 6), 'off')],
  ])('stays equal to the session’s mesh through random edits, undos, redos and phases (%s)', async (_, file) => {
    const random = seededRandom(20261125);
    const editsPatched: boolean[] = [];
    const startsPatched: boolean[] = [];
    const smoothingPatched: boolean[] = [];
    const session = new EditingSession();
    session.adopt(await loadFile(file(), 'model.off'));
    const page = pageSession(session);
    let listed: { idsVersion: number; ids: string } | null = null;
    let kept = 0;
    const check = (shown: PageSnapshot, step: string) => {
      expect(meshFingerprint(shown.mesh), step).toBe(session.fingerprint());
      expect(drawn(shown.render), step).toEqual(drawn(new RenderLayout().full(shown.mesh)));
      // the same idsVersion promises the same live ids (the record tables then keep their rows)
      const ids = JSON.stringify([[...shown.mesh.vertices()], [...shown.mesh.edges()], [...shown.mesh.faces()]]);
      if (listed?.idsVersion === shown.idsVersion) {
        expect(ids, step).toBe(listed.ids);
        kept++;
      }
      listed = { idsVersion: shown.idsVersion, ids };
    };
    for (let i = 0; i < 120; i++) {
      const roll = random();
      const mesh = page.page.mesh!;
      const request = randomEdit(mesh, random);
      if (roll < 0.55 && request) {
        check(page.edit(request), `${i}: ${JSON.stringify(request)}`);
        editsPatched.push(page.patched.at(-1)!);
      }
      else if (roll < 0.7) check(page.undo(), `${i}: undo`);
      else if (roll < 0.8) check(page.redo(), `${i}: redo`);
      else if (roll < 0.85) check(page.jump(Math.floor(random() * page.snapshot().history.items.length)), `${i}: jump`);
      else if (roll < 0.95) {
        check(page.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 2 } }), `${i}: smooth`);
        check(page.step(), `${i}: smoothing step`);
        smoothingPatched.push(page.patched.at(-1)!);
        check(random() < 0.5 ? page.cancel() : page.step(), `${i}: smoothing cancelled or done`);
        // nothing has changed at the start: an empty patch, not the whole mesh again
        startsPatched.push(page.patched.at(-3)!);
      } else {
        // a subdivision compacts its copy first: the page gets the renumbered mesh whole when there was something to compact
        const compact = mesh.isCompact;
        check(page.start({ kind: 'subdivide', scheme: 'catmull-clark' }), `${i}: subdivide`);
        if (compact) startsPatched.push(page.patched.at(-1)!);
        else expect(page.patched.at(-1), `${i}: a renumbered start`).toBe(false);
        check(page.step(), `${i}: first phase`);
        check(page.cancel(), `${i}: cancelled`);
      }
    }
    // every edit reached the page as a patch: an edit costs what it changes
    expect(editsPatched.length).toBeGreaterThan(30);
    expect(editsPatched.every(Boolean)).toBe(true);
    expect(startsPatched.length).toBeGreaterThan(5);
    expect(startsPatched.every(Boolean)).toBe(true);
    // a smoothing step moves every vertex: on quads too it is a patch (every face's triangles in one range)
    expect(smoothingPatched.length).toBeGreaterThan(3);
    expect(smoothingPatched.every(Boolean)).toBe(true);
    // flips, smoothing steps and starts keep the ids: the promise is not kept by never making it
    expect(kept).toBeGreaterThan(20);
  });
});
