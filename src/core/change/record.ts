/**
 * The change record: what an edit or a phase changed in a mesh, written down by the code that made
 * the change (`ChangeRecorder`), never found by comparing copies. It can be applied forwards (to
 * the mesh as it was before, giving the mesh after) and backwards, so it serves as the undo entry,
 * as the patch the page applies to its own copy of the mesh, as the pointer diff the app draws
 * and as the trace of a practice run.
 *
 * ```
 *   slots     before { V 8, E 18, F 12 }  →  after { V 9, E 21, F 14 }   (created: the new slots)
 *   pointers  heNext[14]: 15 → 40,  vHalfedge[3]: 6 → 41,  eDeleted[7]: 0 → 1, …
 *   ranges    hePrev[0 … 71]: (72 values) → (72 values);  heNext[72 … 143]: (new slots) → (72 values)
 *   values    position of v8: (0,0,0) → (0.5, 0.5, 0);  positions of v0 … v7 (a range), …
 * ```
 *
 * An edit's writes to the mesh's own arrays (`meshArrays`) are listed one entry per field, old →
 * new. A phase that rewrites most of an array (a subdivision step rewires every face) lists it as
 * a range instead, one copy before and one after, and the slots it brings into use as ranges
 * without a copy before. Attribute values (positions among them) go per element, or for a whole
 * range of elements at once (a smoothing step moves every vertex).
 */
import type { AttributeArray } from '../attributes.js';
import { DIFF_LISTED, type PointerChange, type PointerDiff } from './diff.js';
import type { HalfedgeMesh, SlotState } from '../mesh.js';
import { attributeSetOf, type ElementKind, type MeshArraySpec, meshArrays, slotCount } from '../mesh-arrays.js';

export interface ChangeRecord {
  before: SlotState;
  after: SlotState;
  /** Writes to single fields of the mesh's own arrays: `meshArrays[array[i]]` at `index[i]`, `old[i]` → `new[i]`. */
  pointers: { array: Uint8Array; index: Int32Array; old: Int32Array; new: Int32Array };
  /** Writes to whole ranges of one array; no field is both here and in `pointers`. */
  ranges: PointerRange[];
  /** Attribute values, old → new, for the elements listed (or the range `start … start + count - 1`). */
  values: ValueChange[];
}

/** The values of `meshArrays[array]` from `start` on, as many as `new` holds. */
export interface PointerRange {
  array: number;
  start: number;
  /** The values before, or null for slots the change brings into use (they held the array's initial value). */
  old: Int32Array | Uint8Array | null;
  new: Int32Array | Uint8Array;
}

export interface ValueChange {
  kind: ElementKind;
  name: string;
  itemSize: number;
  /** Element ids, or null for the range starting at `start` (as many elements as `new` holds). */
  index: Int32Array | null;
  start: number;
  /** The values before, or null (a range only) for slots the change brings into use. */
  old: AttributeArray | null;
  new: AttributeArray;
}

/**
 * Calls `visit` for every field the record writes, indexed entries first, then the ranges' fields
 * whose value changed (a slot brought into use starting from the array's initial value).
 */
export function forEachPointerWrite(record: ChangeRecord, visit: (array: number, index: number, old: number, now: number) => void): void {
  const { array, index, old, new: now } = record.pointers;
  for (let i = 0; i < array.length; i++) visit(array[i], index[i], old[i], now[i]);
  for (const range of record.ranges) {
    const initial = meshArrays[range.array].initial;
    for (let i = 0; i < range.new.length; i++) {
      const before = range.old ? range.old[i] : initial;
      if (before !== range.new[i]) visit(range.array, range.start + i, before, range.new[i]);
    }
  }
}

/** Bytes the record holds. */
export function changeBytes(record: ChangeRecord): number {
  return changeArrays(record).reduce((sum, a) => sum + a.byteLength, 0);
}

/** The record's typed arrays, for a transfer list. */
export function changeBuffers(record: ChangeRecord): ArrayBuffer[] {
  return [...new Set(changeArrays(record).map((a) => a.buffer as ArrayBuffer))];
}

function changeArrays(record: ChangeRecord): ArrayBufferView[] {
  const { array, index, old, new: now } = record.pointers;
  const arrays: ArrayBufferView[] = [array, index, old, now];
  for (const range of record.ranges) arrays.push(...(range.old ? [range.old] : []), range.new);
  for (const value of record.values) arrays.push(...(value.index ? [value.index] : []), ...(value.old ? [value.old] : []), value.new);
  return arrays;
}

/**
 * Turns the mesh as it was before the change into the mesh after it (`forward`), or back.
 * The mesh must be in the state the record starts from; it is changed in place.
 */
export function applyChange(mesh: HalfedgeMesh, record: ChangeRecord, direction: 'forward' | 'backward'): void {
  const forward = direction === 'forward';
  const from = forward ? record.before : record.after;
  const to = forward ? record.after : record.before;
  mesh.makeRoom({ vertices: to.vertexSlots, edges: to.edgeSlots, faces: to.faceSlots });
  // slots coming into use start as a new element does, before the record's writes land on them
  for (const spec of meshArrays) mesh[spec.name].fill(spec.initial, slotCount(from, spec.owner), slotCount(to, spec.owner));
  const { array, index, old, new: now } = record.pointers;
  const values = forward ? now : old;
  for (let i = 0; i < array.length; i++) mesh[meshArrays[array[i]].name][index[i]] = values[i];
  // a range without values before covers slots that going backwards gives up: nothing to write
  for (const range of record.ranges) {
    const source = forward ? range.new : range.old;
    if (source) mesh[meshArrays[range.array].name].set(source, range.start);
  }
  for (const change of record.values) {
    const source = forward ? change.new : change.old;
    if (!source) continue;
    const data = attributeSetOf(mesh, change.kind).get(change.name)!.data;
    const { itemSize } = change;
    if (!change.index) data.set(source, change.start * itemSize);
    else {
      // item by item: a view of the source for each element would cost more than the copy
      for (let i = 0; i < change.index.length; i++) {
        const at = change.index[i] * itemSize;
        for (let k = 0; k < itemSize; k++) data[at + k] = source[i * itemSize + k];
      }
    }
  }
  mesh.slotState = to;
}

/** diffPointers lists halfedges first, then vertices, then faces (flags after them all): a record's order too. */
export const ownerOrder: Record<ElementKind, number> = { halfedge: 0, vertex: 1, face: 2, edge: 3 };

/**
 * The pointer fields the record changes, as `diffPointers` lists them (by kind, then id, then
 * field; flags left out): all counted, the first `limit` listed. A range of millions of fields
 * costs a pass to count and at most `limit` of its entries to list.
 */
export function pointerDiffOf(record: ChangeRecord, limit = DIFF_LISTED): PointerDiff {
  const { array, index, old, new: now } = record.pointers;
  const candidates: PointerChange[] = [];
  let total = 0;
  // indexed entries come sorted (see ChangeRecorder.record) and each range by id: the first
  // `limit` of each kind from each source hold the first `limit` of all
  const listed = [0, 0, 0];
  for (let i = 0; i < array.length; i++) {
    const spec = meshArrays[array[i]];
    if (!spec.field || old[i] === now[i]) continue;
    total++;
    if (listed[ownerOrder[spec.owner]]++ < limit) candidates.push(pointerChange(spec, index[i], old[i], now[i]));
  }
  // a range may hold millions of fields: counted in a plain loop, the first `limit` taken
  for (const { array, start, old, new: now } of record.ranges) {
    const spec = meshArrays[array];
    if (!spec.field) continue;
    let listedHere = 0;
    for (let i = 0; i < now.length; i++) {
      const before = old ? old[i] : spec.initial;
      if (before === now[i]) continue;
      total++;
      if (listedHere++ < limit) candidates.push(pointerChange(spec, start + i, before, now[i]));
    }
  }
  const fieldOrder = (change: PointerChange) => meshArrays.findIndex((spec) => spec.owner === change.element && spec.field === change.field);
  candidates.sort((p, q) => ownerOrder[p.element] - ownerOrder[q.element] || p.id - q.id || fieldOrder(p) - fieldOrder(q));
  return { changes: candidates.slice(0, limit), total };
}

function pointerChange(spec: MeshArraySpec, id: number, before: number, after: number): PointerChange {
  return { element: spec.owner as PointerChange['element'], id, field: spec.field!, before, after };
}

/**
 * A change that moved vertices only: every position from `oldPositions` (a copy the record keeps,
 * not copied again) to the mesh's own.
 */
export function positionsChange(mesh: HalfedgeMesh, oldPositions: Float64Array<ArrayBuffer>): ChangeRecord {
  const count = 3 * mesh.vertexSlots;
  return {
    ...noChange(mesh),
    values: [{ kind: 'vertex', name: 'position', itemSize: 3, index: null, start: 0, old: oldPositions.subarray(0, count), new: mesh.positions.slice(0, count) }],
  };
}

/** The record of a change that changed nothing (starting an operation, say): a patch as cheap as it gets. */
export function noChange(mesh: HalfedgeMesh): ChangeRecord {
  const state = mesh.slotState;
  return {
    before: state,
    after: state,
    pointers: { array: new Uint8Array(0), index: new Int32Array(0), old: new Int32Array(0), new: new Int32Array(0) },
    ranges: [],
    values: [],
  };
}

/**
 * Whether the change brings an element into use, deletes one or brings one back: whether the live
 * ids differ before and after it. A flip keeps them; a split adds some.
 */
export function changesLiveIds(record: ChangeRecord): boolean {
  const { before, after } = record;
  if (before.vertexSlots !== after.vertexSlots || before.edgeSlots !== after.edgeSlots || before.faceSlots !== after.faceSlots) return true;
  // the record lists a field only when its value changed: a flag listed is a flag that changed
  if (record.pointers.array.some((array) => meshArrays[array].refers === null)) return true;
  return record.ranges.some((range) => meshArrays[range.array].refers === null && range.new.some((flag, i) => flag !== range.old![i]));
}

/**
 * Whether the change only rewrites attribute values (a smoothing step moves vertices): no pointer
 * or flag written, no slot brought into use or given up, so everything that follows from the
 * connectivity alone (validity, components, genus) is as it was.
 */
export function onlyChangesValues(record: ChangeRecord): boolean {
  const { before, after } = record;
  return before.vertexSlots === after.vertexSlots && before.edgeSlots === after.edgeSlots && before.faceSlots === after.faceSlots && record.pointers.array.length === 0 && record.ranges.length === 0;
}

/** Elements by kind, each list in increasing order (an edge is listed as its two halfedges). */
export interface TouchedElements {
  vertices: Int32Array;
  halfedges: Int32Array;
  faces: Int32Array;
}

/**
 * The elements a change touches, for a check of what it may have broken (`validateAround`): each
 * element the record writes a pointer or a flag of, each element such a pointer names before and
 * after the write (a halfedge's old and new `next`, a vertex's old and new halfedge), and the
 * slots the change brings into use or gives up. Attribute values (positions) are left out: no
 * invariant reads them. The same in either direction, so it serves an undo as well.
 */
export function touchedElements(record: ChangeRecord): TouchedElements {
  const ids = { vertex: new Set<number>(), halfedge: new Set<number>(), face: new Set<number>() };
  const touch = (kind: ElementKind, id: number) => {
    if (id === -1) return;
    if (kind !== 'edge') ids[kind].add(id);
    else ids.halfedge.add(2 * id).add(2 * id + 1);
  };
  forEachPointerWrite(record, (array, index, old, now) => {
    const { owner, refers } = meshArrays[array];
    touch(owner, index);
    if (refers) {
      touch(refers, old);
      touch(refers, now);
    }
  });
  for (const kind of ['vertex', 'halfedge', 'face'] as const) {
    const [from, to] = [slotCount(record.before, kind), slotCount(record.after, kind)].sort((a, b) => a - b);
    for (let id = from; id < to; id++) touch(kind, id);
  }
  const sorted = (set: Set<number>) => Int32Array.from(set).sort();
  return { vertices: sorted(ids.vertex), halfedges: sorted(ids.halfedge), faces: sorted(ids.face) };
}

/**
 * The same change the other way round: applying it forwards undoes the original. What the
 * original wrote on slots it brought into use is left out, since undoing gives those slots up
 * (inverting twice does not give it back: the undo of an edit is the one inverse taken).
 */
export function invertChange(record: ChangeRecord): ChangeRecord {
  const { array, index, old, new: now } = record.pointers;
  return {
    before: record.after,
    after: record.before,
    pointers: { array, index, old: now, new: old },
    ranges: record.ranges.flatMap((range) => (range.old ? [{ ...range, old: range.new, new: range.old }] : [])),
    values: record.values.flatMap((value) => (value.old ? [{ ...value, old: value.new, new: value.old }] : [])),
  };
}
