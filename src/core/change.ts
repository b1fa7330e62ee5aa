/**
 * The change record: what an edit or a phase changed in a mesh, written down by the code that made
 * the change, never found by comparing copies. It can be applied forwards (to the mesh as it was
 * before, giving the mesh after) and backwards, so it serves as the undo entry, as the patch the
 * page applies to its own copy of the mesh, and as the pointer diff the app draws.
 *
 * ```
 *   slots     before { V 8, E 18, F 12 }  →  after { V 9, E 21, F 14 }   (created: the new slots)
 *   pointers  heNext[14]: 15 → 40,  vHalfedge[3]: 6 → 41,  eDeleted[7]: 0 → 1, …
 *   values    position of v8: (0,0,0) → (0.5, 0.5, 0);  positions of v0 … v7 (a range), …
 * ```
 *
 * Writes to the mesh's own arrays (`meshArrays`) are listed one entry per field, old → new; the
 * values of attributes (positions among them) per element, or for a whole range of elements at
 * once (a smoothing step moves every vertex).
 */
import type { AttributeArray } from './attributes.js';
import { DIFF_LISTED, type PointerChange, type PointerDiff } from './diff.js';
import type { HalfedgeMesh, SlotState } from './mesh.js';
import { attributeSetOf, type ElementKind, elementKinds, meshArrays, slotCount } from './mesh-arrays.js';

export interface ChangeRecord {
  before: SlotState;
  after: SlotState;
  /** Writes to the mesh's own arrays: `meshArrays[array[i]]` at `index[i]`, `old[i]` → `new[i]`. */
  pointers: { array: Uint8Array; index: Int32Array; old: Int32Array; new: Int32Array };
  /** Attribute values, old → new, for the elements listed (or the range `start … start + count - 1`). */
  values: ValueChange[];
}

export interface ValueChange {
  kind: ElementKind;
  name: string;
  itemSize: number;
  /** Element ids, or null for the range starting at `start` (as many elements as `old` holds). */
  index: Int32Array | null;
  start: number;
  old: AttributeArray;
  new: AttributeArray;
}

/** Bytes the record holds. */
export function changeBytes(record: ChangeRecord): number {
  const { array, index, old, new: now } = record.pointers;
  let bytes = array.byteLength + index.byteLength + old.byteLength + now.byteLength;
  for (const value of record.values) bytes += (value.index?.byteLength ?? 0) + value.old.byteLength + value.new.byteLength;
  return bytes;
}

/** The record's typed arrays, for a transfer list. */
export function changeBuffers(record: ChangeRecord): ArrayBuffer[] {
  const { array, index, old, new: now } = record.pointers;
  const arrays: ArrayBufferView[] = [array, index, old, now];
  for (const value of record.values) arrays.push(...(value.index ? [value.index] : []), value.old, value.new);
  return arrays.map((a) => a.buffer as ArrayBuffer);
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
  for (const change of record.values) {
    const data = attributeSetOf(mesh, change.kind).get(change.name)!.data;
    const source = forward ? change.new : change.old;
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

/** The pointer fields the record changes, as `diffPointers` lists them (flags left out). */
export function pointerDiffOf(record: ChangeRecord, limit = DIFF_LISTED): PointerDiff {
  const { array, index, old, new: now } = record.pointers;
  const changes: PointerChange[] = [];
  let total = 0;
  for (let i = 0; i < array.length; i++) {
    const spec = meshArrays[array[i]];
    if (!spec.field || old[i] === now[i]) continue;
    total++;
    if (changes.length < limit) {
      changes.push({ element: spec.owner as PointerChange['element'], id: index[i], field: spec.field, before: old[i], after: now[i] });
    }
  }
  return { changes, total };
}

/** diffPointers lists halfedges first, then vertices, then faces (flags after them all). */
const ownerOrder: Record<ElementKind, number> = { halfedge: 0, vertex: 1, face: 2, edge: 3 };

/** For each mesh whose edits are being followed by `inWriteOrder`, the fields they wrote so far. */
const writeOrders = new WeakMap<HalfedgeMesh, number[]>();

/**
 * Runs `run` (which edits `mesh`) and lists the fields its edits wrote, `16 · index + array`, in
 * the order they were first written (a record lists them by element instead), for a caller that
 * wants the edit's steps in order: the practice grader names the first pointer the library's
 * edit sets that a solution does not. Only writes an edit records are seen (a field written by
 * two edits in turn is listed twice); an operation that writes its arrays in bulk lists nothing.
 * @example const { value, fields } = inWriteOrder(mesh, () => flipEdge(mesh, e));
 */
export function inWriteOrder<T>(mesh: HalfedgeMesh, run: () => T): { value: T; fields: number[] } {
  const fields: number[] = [];
  writeOrders.set(mesh, fields);
  try {
    return { value: run(), fields };
  } finally {
    writeOrders.delete(mesh);
  }
}

/**
 * Writes a change record as the change happens: each field's value before its first write, each
 * element's attribute values before their first write, and the slot counts at the start. The
 * caller writes the mesh itself (through `PointerWriter`, which calls this first).
 */
export class ChangeRecorder {
  private readonly before: SlotState;
  /** `16 · index + array` → the value before the first write. */
  private readonly fields = new Map<number, number>();
  /** `4 · id + kind` → every attribute value of that element before the first write. */
  private readonly elements = new Map<number, number[]>();
  /** The fields in the order first written, while `inWriteOrder` follows the mesh. */
  private readonly order: number[] | null;

  constructor(readonly mesh: HalfedgeMesh) {
    this.before = mesh.slotState;
    this.order = writeOrders.get(mesh) ?? null;
  }

  /** Call before writing `mesh[array][index]`. */
  field(array: number, index: number): void {
    const key = 16 * index + array;
    if (this.fields.has(key)) return;
    this.fields.set(key, this.mesh[meshArrays[array].name][index]);
    this.order?.push(key);
  }

  /** Call before writing any attribute value (a position too) of element `id`. */
  element(kind: ElementKind, id: number): void {
    const key = 4 * id + elementKinds.indexOf(kind);
    if (this.elements.has(key)) return;
    const values: number[] = [];
    for (const { data, itemSize } of attributeSetOf(this.mesh, kind)) {
      for (let k = 0; k < itemSize; k++) values.push(data[id * itemSize + k]);
    }
    this.elements.set(key, values);
  }

  /** The record so far: fields and values that really changed, in the order `diffPointers` uses. */
  record(): ChangeRecord {
    const { mesh } = this;
    const keys = [...this.fields.keys()]
      .filter((key) => mesh[meshArrays[key % 16].name][Math.floor(key / 16)] !== this.fields.get(key))
      .sort((p, q) => ownerOrder[meshArrays[p % 16].owner] - ownerOrder[meshArrays[q % 16].owner] || p - q);
    const pointers = {
      array: new Uint8Array(keys.length),
      index: new Int32Array(keys.length),
      old: new Int32Array(keys.length),
      new: new Int32Array(keys.length),
    };
    keys.forEach((key, i) => {
      const array = key % 16;
      const index = Math.floor(key / 16);
      pointers.array[i] = array;
      pointers.index[i] = index;
      pointers.old[i] = this.fields.get(key)!;
      pointers.new[i] = mesh[meshArrays[array].name][index];
    });
    return { before: this.before, after: mesh.slotState, pointers, values: this.valueChanges() };
  }

  private valueChanges(): ValueChange[] {
    const changes: ValueChange[] = [];
    elementKinds.forEach((kind, kindIndex) => {
      const ids = [...this.elements.keys()].filter((key) => key % 4 === kindIndex).map((key) => (key - kindIndex) / 4);
      if (ids.length === 0) return;
      ids.sort((a, b) => a - b);
      let offset = 0;
      for (const { name, itemSize, data } of attributeSetOf(this.mesh, kind)) {
        const ArrayType = data.constructor as new (n: number) => AttributeArray;
        const old = new ArrayType(ids.length * itemSize);
        const now = new ArrayType(ids.length * itemSize);
        ids.forEach((id, i) => {
          const remembered = this.elements.get(4 * id + kindIndex)!;
          for (let k = 0; k < itemSize; k++) {
            old[i * itemSize + k] = remembered[offset + k];
            now[i * itemSize + k] = data[id * itemSize + k];
          }
        });
        offset += itemSize;
        if (old.some((value, i) => !Object.is(value, now[i]))) {
          changes.push({ kind, name, itemSize, index: Int32Array.from(ids), start: 0, old, new: now });
        }
      }
    });
    return changes;
  }
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
  return record.pointers.array.some((array) => meshArrays[array].refers === null);
}

/**
 * Whether the change only rewrites attribute values (a smoothing step moves vertices): no pointer
 * or flag written, no slot brought into use or given up, so everything that follows from the
 * connectivity alone (validity, components, genus) is as it was.
 */
export function onlyChangesValues(record: ChangeRecord): boolean {
  const { before, after } = record;
  return before.vertexSlots === after.vertexSlots && before.edgeSlots === after.edgeSlots && before.faceSlots === after.faceSlots && record.pointers.array.length === 0;
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
  const { array, index, old, new: now } = record.pointers;
  for (let i = 0; i < array.length; i++) {
    const { owner, refers } = meshArrays[array[i]];
    touch(owner, index[i]);
    if (refers) {
      touch(refers, old[i]);
      touch(refers, now[i]);
    }
  }
  for (const kind of ['vertex', 'halfedge', 'face'] as const) {
    const [from, to] = [slotCount(record.before, kind), slotCount(record.after, kind)].sort((a, b) => a - b);
    for (let id = from; id < to; id++) touch(kind, id);
  }
  const sorted = (set: Set<number>) => Int32Array.from(set).sort();
  return { vertices: sorted(ids.vertex), halfedges: sorted(ids.halfedge), faces: sorted(ids.face) };
}

/** The same change the other way round: applying it forwards undoes the original. */
export function invertChange(record: ChangeRecord): ChangeRecord {
  const { array, index, old, new: now } = record.pointers;
  return {
    before: record.after,
    after: record.before,
    pointers: { array, index, old: now, new: old },
    values: record.values.map((value) => ({ ...value, old: value.new, new: value.old })),
  };
}
