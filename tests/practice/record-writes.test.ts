/**
 * A student's writes, replayed through the writer, become a change record like an edit's: applied
 * forwards it gives the mesh the writes leave, backwards the mesh they were given, and its pointer
 * diff is the net change a comparison finds. "Use my code" sends that record to the session, which
 * applies it as an edit: the page gets a patch, and undo takes it back.
 */
import { describe, expect, it } from 'vitest';
import { applyChange, buildMesh, diffPointers, grid, meshFingerprint, pointerDiffOf, validate, writeSoup } from '../../src/core/index.js';
import { recordWrites, replayWrites } from '../../src/core/practice/index.js';
import { loadFile } from '../../src/workers/load.js';
import { EditingSession } from '../../src/workers/session.js';
import { pageSession } from '../workers/page-session.js';
import { inProcess, solution } from './helpers.js';

describe('the record of a solution’s writes', () => {
  it.each([
    ['split-edge', 7],
    ['collapse-edge', 7],
    ['flip-edge', 12],
  ])('is the change the writes of the %s test solution make', async (exercise, edge) => {
    const mesh = buildMesh(grid(3, 3)).mesh;
    const [output] = await inProcess(solution(exercise), [{ mesh, input: edge }]);
    expect(output.error).toBeNull();
    expect(output.writes.length).toBeGreaterThan(0);
    const after = replayWrites(mesh.clone(), output.writes);
    const copy = mesh.clone();
    const record = recordWrites(copy, output.writes);
    expect(meshFingerprint(copy)).toBe(meshFingerprint(after));
    expect(pointerDiffOf(record, Infinity)).toEqual(diffPointers(mesh, after, Infinity));
    applyChange(copy, record, 'backward');
    expect(meshFingerprint(copy)).toBe(meshFingerprint(mesh));
  });

  it('is applied by the session as an edit: a patch for the page, taken back by undo', async () => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(grid(3, 3), 'off'), 'grid.off'));
    const page = pageSession(session);
    const before = page.snapshot();
    const opened = meshFingerprint(before.mesh);
    const [output] = await inProcess(solution('split-edge'), [{ mesh: before.mesh, input: 7 }]);
    const record = recordWrites(before.mesh.clone(), output.writes);
    const shown = page.solution(record, 'split e7 (your code)', 'split-edge');
    expect(page.patched.at(-1)).toBe(true);
    expect(meshFingerprint(shown.mesh)).toBe(session.fingerprint());
    expect(validate(shown.mesh)).toEqual([]);
    expect(shown.history.items.at(-1)).toMatchObject({ label: 'split e7 (your code)', source: { kind: 'solution', exercise: 'split-edge' } });
    expect(shown.diff!.total).toBe(pointerDiffOf(record, Infinity).total);
    const undone = page.undo();
    expect(page.patched.at(-1)).toBe(true);
    expect(meshFingerprint(undone.mesh)).toBe(opened);
  });

  it('is refused by the session when it was made on another mesh', async () => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(grid(3, 3), 'off'), 'grid.off'));
    const other = buildMesh(grid(4, 4)).mesh;
    const [output] = await inProcess(solution('split-edge'), [{ mesh: other, input: 7 }]);
    const record = recordWrites(other.clone(), output.writes);
    const fingerprint = session.fingerprint();
    expect(() => session.solution(record, 'split e7 (your code)', 'split-edge')).toThrow(/made on another mesh than the current one/);
    expect(session.fingerprint()).toBe(fingerprint);
  });
});
