/**
 * Random sequences of local edits on the fuzzer's start meshes (closed and open, a Möbius strip,
 * an annulus's hole), for properties that must hold after every edit and its undo.
 */
import fc from 'fast-check';
import { elementEdits, elementOf, shapes } from '../../fuzz/edits.js';
import { buildMesh } from '../../src/core/build.js';
import type { ChangeRecord } from '../../src/core/change/record.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';

export interface EditSequence {
  shape: string;
  /** Each an edit and which live element it picks (modulo their count). */
  edits: Array<[(typeof elementEdits)[number], number]>;
}

export const editSequences: fc.Arbitrary<EditSequence> = fc.record({
  shape: fc.constantFrom(...Object.keys(shapes)),
  edits: fc.array(fc.tuple(fc.constantFrom(...elementEdits), fc.nat()), { minLength: 1, maxLength: 15 }),
});

/**
 * Builds the start mesh and runs the edits that apply, calling `after(mesh, record, step)` after
 * each (`step` names it, for failure messages); returns how many applied.
 */
export function runEdits({ shape, edits }: EditSequence, after: (mesh: HalfedgeMesh, record: ChangeRecord, step: string) => void): number {
  const { mesh } = buildMesh(shapes[shape]());
  let applied = 0;
  for (const [{ name, on, can, edit }, k] of edits) {
    const id = elementOf(mesh, on, k);
    if (id === -1 || can(mesh, id) !== null) continue;
    const { record } = edit(mesh, id);
    applied++;
    after(mesh, record!, `${shape}: ${name} ${on}${id} (edit ${applied})`);
  }
  return applied;
}
