/**
 * The live ids of one kind of element, in increasing order: what a table of a mesh's records
 * lists, row by row. They are kept as the ids that are *not* live — a few after some edits — so
 * that after a change only the ids it touched are looked at, not every slot of a large mesh:
 *
 * ```
 *   slots 0 1 2 3 4 5 6      dead [2, 5]      rows: 0→0  1→1  2→3  3→4  4→6
 * ```
 */
import type { ChangeRecord } from './change/record.js';
import type { HalfedgeMesh } from './mesh.js';
import { meshArrays, slotCount } from './mesh-arrays.js';

/** The kinds with ids of their own in the mesh's arrays (an edge is its two halfedges). */
export type ListedKind = 'vertex' | 'face' | 'halfedge';

export function isLive(mesh: HalfedgeMesh, kind: ListedKind, id: number): boolean {
  if (kind === 'vertex') return mesh.vDeleted[id] === 0;
  if (kind === 'face') return mesh.fDeleted[id] === 0;
  return mesh.eDeleted[id >> 1] === 0;
}

export class LiveIds {
  private constructor(
    readonly slots: number,
    /** The ids below `slots` that are not live, in increasing order. */
    readonly dead: Int32Array,
  ) {}

  /** The live ids of `kind` in `mesh`: a pass over its deleted flags (none for a compact mesh). */
  static of(mesh: HalfedgeMesh, kind: ListedKind): LiveIds {
    const slots = slotCount(mesh, kind);
    if (mesh.isCompact) return new LiveIds(slots, new Int32Array(0));
    const deleted = kind === 'vertex' ? mesh.vDeleted : kind === 'face' ? mesh.fDeleted : mesh.eDeleted;
    // a halfedge is deleted with its edge
    const shift = kind === 'halfedge' ? 1 : 0;
    let count = 0;
    for (let id = 0; id < slots; id++) if (deleted[id >> shift] !== 0) count++;
    const dead = new Int32Array(count);
    for (let id = 0, at = 0; id < slots; id++) if (deleted[id >> shift] !== 0) dead[at++] = id;
    return new LiveIds(slots, dead);
  }

  /** How many ids are live: the rows of a table. */
  get count(): number {
    return this.slots - this.dead.length;
  }

  /** The id of row `row` (0 ≤ row < count): the row plus the dead ids before it. */
  idAt(row: number): number {
    // dead[i] − i, the rows before dead id i, never decreases: the last dead id at or below the row's place
    const { dead } = this;
    let lo = 0;
    let hi = dead.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (dead[mid] - mid <= row) lo = mid + 1;
      else hi = mid;
    }
    return row + lo;
  }

  /** The row of `id`, or -1 when it is not live. */
  rowOf(id: number): number {
    if (id < 0 || id >= this.slots) return -1;
    const before = lowerBound(this.dead, id, 0);
    return this.dead[before] === id ? -1 : id - before;
  }

  /**
   * The live ids of `kind` in `mesh` after `change`, which led to it from the mesh these were of.
   * Only the ids the change touched are looked at; the runs of dead ids between them are copied whole.
   */
  after(mesh: HalfedgeMesh, kind: ListedKind, change: ChangeRecord): LiveIds {
    // a change that wrote whole ranges (a phase) touched more than a pass over the flags costs
    if (change.ranges.length > 0) return LiveIds.of(mesh, kind);
    const { dead } = this;
    const touched = liveIdsTouched(change, kind);
    const slots = slotCount(mesh, kind);
    const out = new Int32Array(dead.length + touched.length);
    let n = 0;
    let from = 0;
    for (const id of touched) {
      const at = lowerBound(dead, id, from);
      out.set(dead.subarray(from, at), n);
      n += at - from;
      from = at < dead.length && dead[at] === id ? at + 1 : at;
      if (id < slots && !isLive(mesh, kind, id)) out[n++] = id;
    }
    out.set(dead.subarray(from), n);
    n += dead.length - from;
    return new LiveIds(slots, out.slice(0, n));
  }
}

/**
 * The ids of `kind` whose liveness the change may alter, in increasing order: those whose
 * deleted flag it writes (a halfedge through its edge's), and the slots it brings into use or
 * gives up.
 */
export function liveIdsTouched(change: ChangeRecord, kind: ListedKind): Int32Array {
  const flags = kind === 'vertex' ? 'vDeleted' : kind === 'face' ? 'fDeleted' : 'eDeleted';
  const ids: number[] = [];
  const push = (id: number) => (kind === 'halfedge' ? ids.push(2 * id, 2 * id + 1) : ids.push(id));
  const { array, index } = change.pointers;
  for (let i = 0; i < array.length; i++) if (meshArrays[array[i]].name === flags) push(index[i]);
  for (const range of change.ranges) {
    if (meshArrays[range.array].name !== flags || !range.old) continue;
    for (let i = 0; i < range.new.length; i++) if (range.old[i] !== range.new[i]) push(range.start + i);
  }
  const [low, high] = [slotCount(change.before, kind), slotCount(change.after, kind)].sort((a, b) => a - b);
  for (let id = low; id < high; id++) ids.push(id);
  const sorted = Int32Array.from(ids).sort();
  return sorted.filter((id, i) => i === 0 || sorted[i - 1] !== id);
}

/** The first index at or after `from` whose id is not below `id`. */
function lowerBound(ids: Int32Array, id: number, from: number): number {
  let lo = from;
  let hi = ids.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (ids[mid] < id) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}
