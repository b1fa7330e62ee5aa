/**
 * The one way a change record is written: as the change happens, by the code that makes it. Before
 * a write, the writer tells the recorder what it is about to overwrite, and the recorder keeps the
 * value from before (only the first time):
 *
 * ```
 *   field(next, 14)          before one write (an edit, through PointerWriter)
 *   element(vertex, 8)       before writing any attribute value of one element
 *   valueRange(vertex, 0, V) before moving many vertices at once (a smoothing step, a stencil)
 *   wholeMesh()              before a step that rewires the whole mesh (a subdivision step)
 *   record()                 the record: every field and value that really changed, old → new
 * ```
 *
 * An edit remembers field by field. A subdivision step rewires every face with index arithmetic,
 * where a call per write would cost more than the write: it declares the whole mesh once, which
 * keeps a copy of every pointer array, and `record()` keeps of it only what changed (the fields
 * one by one when they are few, else the range from the first changed to the last), with every
 * slot the step brought into use, values included.
 */
import type { AttributeArray } from '../attributes.js';
import type { HalfedgeMesh, SlotState } from '../mesh.js';
import { attributeSetOf, type ElementKind, elementKinds, meshArrays, slotCount } from '../mesh-arrays.js';
import { type ChangeRecord, ownerOrder, type PointerRange, type ValueChange } from './record.js';

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

/** A range of one array changed in more than this share of its fields is listed whole. */
const RANGE_SHARE = 1 / 4;

export class ChangeRecorder {
  private readonly before: SlotState;
  /** `16 · index + array` → the value before the first write. */
  private readonly fields = new Map<number, number>();
  /** `4 · id + kind` → every attribute value of that element before the first write. */
  private readonly elements = new Map<number, number[]>();
  /** Attribute values of element ranges before a bulk write (`valueRange`). */
  private readonly valueRanges: { kind: ElementKind; start: number; old: AttributeArray[] }[] = [];
  /** Every pointer array's slots in use, before a step that may rewrite any of them (`wholeMesh`). */
  private whole: (Int32Array | Uint8Array)[] | null = null;
  /** The fields in the order first written, while `inWriteOrder` follows the mesh. */
  private readonly order: number[] | null;

  constructor(readonly mesh: HalfedgeMesh) {
    this.before = mesh.slotState;
    this.order = writeOrders.get(mesh) ?? null;
  }

  /** Call before writing `mesh[meshArrays[array].name][index]`. */
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

  /** Call before writing attribute values of the elements `start … end − 1` of a kind at once (existing ones). */
  valueRange(kind: ElementKind, start: number, end: number): void {
    const old = [...attributeSetOf(this.mesh, kind)].map(({ data, itemSize }) => data.slice(start * itemSize, end * itemSize));
    this.valueRanges.push({ kind, start, old });
  }

  /**
   * Call before a step that may rewrite any pointer or flag of the mesh and bring any number of
   * slots into use, writing their values too (a topology step of a subdivision level). Costs a
   * copy of the pointer arrays, and `record()` a pass over them.
   */
  wholeMesh(): void {
    this.whole = meshArrays.map((spec) => this.mesh[spec.name].slice(0, slotCount(this.before, spec.owner)));
  }

  /** The record so far: fields and values that really changed, in the order `diffPointers` uses. */
  record(): ChangeRecord {
    const ranges = this.whole ? this.wholeMeshRanges(this.whole) : [];
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
    return { before: this.before, after: mesh.slotState, pointers, ranges, values: [...this.elementChanges(), ...this.rangeChanges()] };
  }

  /**
   * What a whole-mesh step changed: per array, the fields of existing slots that changed (as
   * `fields` entries when few, else one range) and every slot brought into use.
   */
  private wholeMeshRanges(whole: (Int32Array | Uint8Array)[]): PointerRange[] {
    const ranges: PointerRange[] = [];
    meshArrays.forEach((spec, array) => {
      const old = whole[array];
      const now = this.mesh[spec.name];
      let first = -1;
      let last = -1;
      let changed = 0;
      for (let i = 0; i < old.length; i++) {
        if (old[i] === now[i]) continue;
        if (first < 0) first = i;
        last = i;
        changed++;
      }
      if (changed > RANGE_SHARE * (last - first + 1)) {
        ranges.push({ array, start: first, old: old.slice(first, last + 1), new: now.slice(first, last + 1) });
      } else if (changed > 0) {
        for (let i = first; i <= last; i++) if (old[i] !== now[i]) this.fields.set(16 * i + array, old[i]);
      }
      const end = slotCount(this.mesh, spec.owner);
      if (end > old.length) ranges.push({ array, start: old.length, old: null, new: now.slice(old.length, end) });
    });
    return ranges;
  }

  /** The values of the elements written one by one that changed. */
  private elementChanges(): ValueChange[] {
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

  /** The values of ranges written at once that changed, and (after a whole-mesh step) those of the slots brought into use. */
  private rangeChanges(): ValueChange[] {
    const changes: ValueChange[] = [];
    for (const { kind, start, old } of this.valueRanges) {
      [...attributeSetOf(this.mesh, kind)].forEach(({ name, itemSize, data }, i) => {
        const now = data.slice(start * itemSize, start * itemSize + old[i].length);
        if (now.some((value, k) => !Object.is(value, old[i][k]))) changes.push({ kind, name, itemSize, index: null, start, old: old[i], new: now });
      });
    }
    if (!this.whole) return changes;
    for (const kind of elementKinds) {
      const from = slotCount(this.before, kind);
      const to = slotCount(this.mesh, kind);
      if (to <= from) continue;
      for (const { name, itemSize, data } of attributeSetOf(this.mesh, kind)) {
        changes.push({ kind, name, itemSize, index: null, start: from, old: null, new: data.slice(from * itemSize, to * itemSize) });
      }
    }
    return changes;
  }
}
