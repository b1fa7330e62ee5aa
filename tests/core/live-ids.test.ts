/**
 * The live ids brought up to date from a change equal those listed afresh: after every edit of
 * random sequences (which create and delete elements) and after its undo, for every kind; and
 * rows and ids map to each other as a plain list of the live ids would.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { applyChange, buildMesh, collapseEdge, type HalfedgeMesh, invertChange, isLive, type ListedKind, LiveIds, slotCount } from '../../src/index.js';
import { editSequences, runEdits } from './edit-sequences.js';
import { edgeBetween, square } from '../edits/helpers.js';

const SEED = 20261125;
const kinds: ListedKind[] = ['vertex', 'face', 'halfedge'];

/** The live ids, one by one. */
function plainList(mesh: HalfedgeMesh, kind: ListedKind): number[] {
  const ids: number[] = [];
  for (let id = 0; id < slotCount(mesh, kind); id++) if (isLive(mesh, kind, id)) ids.push(id);
  return ids;
}

describe('LiveIds', () => {
  it('maps rows to ids and back as the plain list does, with deleted ids between', () => {
    const mesh = buildMesh(square()).mesh;
    collapseEdge(mesh, edgeBetween(mesh, 0, 1));
    for (const kind of kinds) {
      const list = plainList(mesh, kind);
      const live = LiveIds.of(mesh, kind);
      expect(live.dead.length, kind).toBeGreaterThan(0);
      expect(live.count).toBe(list.length);
      expect(list.map((_, row) => live.idAt(row))).toEqual(list);
      for (let id = -1; id <= slotCount(mesh, kind); id++) expect(live.rowOf(id), `${kind} ${id}`).toBe(list.indexOf(id));
    }
  });
});

describe(`LiveIds.after (seed ${SEED})`, () => {
  it('lists what a fresh pass lists, after every edit of random sequences and after its undo', () => {
    let edits = 0;
    let withDead = 0;
    fc.assert(
      fc.property(editSequences, (sequence) => {
        // each kind's list as a table holds it, brought up to date edit by edit
        const held = new Map<ListedKind, LiveIds>();
        edits += runEdits(sequence, (mesh, record, step) => {
          for (const kind of kinds) {
            if (!held.has(kind)) {
              // the first edit: the list of the start mesh
              applyChange(mesh, record, 'backward');
              held.set(kind, LiveIds.of(mesh, kind));
              applyChange(mesh, record, 'forward');
            }
            const before = held.get(kind)!;
            const after = before.after(mesh, kind, record);
            expect(after, `${step}: ${kind}s`).toEqual(LiveIds.of(mesh, kind));
            if (after.dead.length > 0) withDead++;

            applyChange(mesh, record, 'backward');
            expect(after.after(mesh, kind, invertChange(record)), `${step}, undone: ${kind}s`).toEqual(before);
            applyChange(mesh, record, 'forward');
            held.set(kind, after);
          }
        });
      }),
      { seed: SEED, numRuns: 200 },
    );
    expect(edits).toBeGreaterThan(500);
    expect(withDead).toBeGreaterThan(100);
  });
});
