/**
 * The assignment's local operations as the app asks for them: each edit kind through the session
 * (a history entry, a patch of the page's copy, undo back to the mesh before), with the element
 * keys `window.halfedgeLab.edit` takes, and a kind there is no edit of refused by name.
 */
import { describe, expect, it } from 'vitest';
import { cube, faceCentroid, grid, type PolygonSoup, writeSoup } from '../../src/index.js';
import { meshContents } from '../core/contents.js';
import { loadFile } from '../../src/workers/load.js';
import type { EditRequest } from '../../src/workers/operations.js';
import { EditingSession } from '../../src/workers/session.js';
import { edgeBetween } from '../edits/helpers.js';
import { pageSession } from './page-session.js';

async function sessionOn(soup: PolygonSoup) {
  const session = new EditingSession();
  session.adopt(await loadFile(writeSoup(soup, 'off'), 'shape.off'));
  return pageSession(session);
}

/** V, E, F of a page snapshot. */
const counts = (s: { stats: { vertices: number; edges: number; faces: number } }) => [s.stats.vertices, s.stats.edges, s.stats.faces];

describe('the assignment’s edits in the session', () => {
  const cases: Array<{ request: EditRequest; label: string; counts: number[] }> = [
    // a cube's face: four new vertices, a ring of four quads
    { request: { kind: 'extrude-face', face: 0 }, label: 'extrude f0', counts: [12, 20, 10] },
    // a cube corner: three new corners on its three edges, a triangle in its place
    { request: { kind: 'bevel-vertex', vertex: 0 }, label: 'bevel v0', counts: [10, 15, 7] },
    // a cube edge: its two ends opened into two corners each, a quad in its place
    { request: { kind: 'bevel-edge', edge: 0 }, label: 'bevel e0', counts: [10, 15, 7] },
    { request: { kind: 'dissolve-edge', edge: 0 }, label: 'dissolve e0', counts: [8, 11, 5] },
    { request: { kind: 'collapse-face', face: 0 }, label: 'collapse f0', counts: [5, 8, 5] },
    { request: { kind: 'make-boundary', face: 0 }, label: 'make f0 a hole', counts: [8, 12, 5] },
  ];
  for (const { request, label, counts: expected } of cases) {
    it(`${request.kind} on a cube: ${label}, valid, patched, undone`, async () => {
      const page = await sessionOn(cube());
      const before = meshContents(page.snapshot().mesh);
      const after = page.edit(request);
      expect(after.problems).toEqual([]);
      expect(counts(after)).toEqual(expected);
      expect(after.history.items.at(-1)!.label).toBe(label);
      expect(page.patched.at(-1)).toBe(true);
      expect(meshContents(page.undo().mesh)).toEqual(before);
    });
  }

  it('dissolves a vertex inside a grid into one face of its four quads', async () => {
    const page = await sessionOn(grid(2, 2, true));
    const after = page.edit({ kind: 'dissolve-vertex', vertex: 4 });
    expect(after.problems).toEqual([]);
    expect(counts(after)).toEqual([8, 8, 1]);
  });

  it('welds the two free ends of a strip of quads into a ring', async () => {
    const page = await sessionOn(grid(3, 1, true));
    const mesh = page.snapshot().mesh;
    const after = page.edit({ kind: 'weld-edges', edges: [edgeBetween(mesh, 0, 4), edgeBetween(mesh, 3, 7)] });
    expect(after.problems).toEqual([]);
    expect([...counts(after), after.stats.boundaryLoops]).toEqual([6, 9, 3, 2]);
  });

  it('refuses an edit that does not apply with its sentence, and a kind there is no edit of by name', async () => {
    const page = await sessionOn(cube());
    expect(() => page.edit({ kind: 'bevel-edge', edge: 0, amount: 2 })).toThrow(/amount = 2 is not between 0 and 1/);
    expect(() => page.edit({ kind: 'weld-edges', edges: [0, 1] })).toThrow(/boundary/);
    expect(() => page.edit({ kind: 'no-such-edit' } as unknown as EditRequest)).toThrow("there is no edit 'no-such-edit'");
    expect(() => page.edit({ kind: 'constructor' } as unknown as EditRequest)).toThrow("there is no edit 'constructor'");
    expect(page.snapshot().history.items).toHaveLength(1);
  });

  it('moves an extruded face half its mean side out by default, and as far as asked', async () => {
    for (const [offset, distance] of [[undefined, 0.5], [2, 2]] as const) {
      const page = await sessionOn(cube()); // a unit cube: sides of 1
      const before = faceCentroid(page.snapshot().mesh, 0);
      const after = faceCentroid(page.edit({ kind: 'extrude-face', face: 0, offset }).mesh, 0);
      expect(Math.hypot(after[0] - before[0], after[1] - before[1], after[2] - before[2])).toBeCloseTo(distance, 12);
    }
  });
});
