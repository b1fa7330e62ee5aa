/**
 * The history of meshes a session went through, kept small. Each entry stores either the whole
 * mesh or, when that is much smaller, only what differs from the entry before it: a local edit
 * touches a handful of pointers, smoothing only positions, so their entries cost a fraction of a
 * mesh, while a subdivision or a cut (which change everything) keeps its whole mesh.
 *
 * The current entry's mesh is always at hand; going back or forward rebuilds the entry from the
 * nearest whole mesh before it and the differences after that. Meshes handed to `push` are owned
 * by the history from then on and never changed: every operation works on a copy.
 */
import { type AttributeArray, type HalfedgeMesh } from '../core/index.js';

/** The arrays of a mesh a difference is taken of, by name (attributes as `v:name`, `h:name`, …). */
type ArrayMap = Map<string, AttributeArray | Int32Array | Uint8Array>;

/** One array's change: every value (`dense`), or the values at some indices (`sparse`). */
type ArrayChange =
  | { dense: AttributeArray | Int32Array | Uint8Array }
  | { indices: Int32Array; values: Float64Array };

interface MeshDelta {
  slots: { vertices: number; edges: number; faces: number };
  arrays: Map<string, ArrayChange>;
  bytes: number;
}

export interface HistoryEntry<Info> {
  label: string;
  info: Info;
  vertices: number;
  faces: number;
}

interface Stored<Info> extends HistoryEntry<Info> {
  /** The whole mesh, or null when `delta` (from the entry before) says how to rebuild it. */
  mesh: HalfedgeMesh | null;
  delta: MeshDelta | null;
}

/** An entry keeps a difference instead of its mesh when the difference is below this share of it. */
const DELTA_SHARE = 0.5;

export class History<Info> {
  private entries: Stored<Info>[] = [];
  private index = -1;
  /** The mesh of the current entry (kept whole even when the entry stores a difference). */
  private current: HalfedgeMesh | null = null;

  get position(): number {
    return this.index;
  }

  get length(): number {
    return this.entries.length;
  }

  items(): HistoryEntry<Info>[] {
    return this.entries.map(({ label, info, vertices, faces }) => ({ label, info, vertices, faces }));
  }

  entry(): HistoryEntry<Info> | null {
    return this.entries[this.index] ?? null;
  }

  mesh(): HalfedgeMesh | null {
    return this.current;
  }

  /** Adds `mesh` after the current entry (dropping any entries that were undone). */
  push(label: string, mesh: HalfedgeMesh, info: Info): void {
    this.entries.length = this.index + 1;
    mesh.trim(); // the history keeps it for good: no room to grow
    const previous = this.current;
    const delta = previous ? difference(previous, mesh, DELTA_SHARE * meshBytes(mesh)) : null;
    if (previous && delta) shareUnchanged(previous, mesh, delta);
    const small = delta !== null;
    this.entries.push({ label, info, vertices: mesh.nVertices, faces: mesh.nFaces, mesh: small ? null : mesh, delta: small ? delta : null });
    this.index = this.entries.length - 1;
    this.current = mesh;
  }

  /** Makes entry `index` the current one. */
  moveTo(index: number): void {
    if (!Number.isInteger(index) || index < 0 || index >= this.entries.length) {
      throw new RangeError(`the history has entries 0..${this.entries.length - 1}, not ${index}`);
    }
    if (index === this.index) return;
    this.index = index;
    this.current = this.rebuild(index);
  }

  /** Bytes the history holds: whole meshes, differences and the current mesh, each array once. */
  bytes(): number {
    const counted = new Set<ArrayBufferLike>();
    let total = 0;
    const count = (array: { buffer: ArrayBufferLike; byteLength: number }) => {
      if (counted.has(array.buffer)) return;
      counted.add(array.buffer);
      total += array.buffer.byteLength;
    };
    for (const mesh of [...this.entries.map((entry) => entry.mesh), this.current]) {
      if (mesh) for (const array of arraysOf(mesh).values()) count(array);
    }
    for (const { delta } of this.entries) {
      for (const change of delta?.arrays.values() ?? []) {
        if ('dense' in change) count(change.dense);
        else [change.indices, change.values].forEach(count);
      }
    }
    return total;
  }

  private rebuild(index: number): HalfedgeMesh {
    let base = index;
    while (!this.entries[base]!.mesh) base--;
    // a whole mesh is never changed: rebuild on a copy when differences follow
    const mesh = base === index ? this.entries[base]!.mesh! : this.entries[base]!.mesh!.clone();
    for (let i = base + 1; i <= index; i++) apply(mesh, this.entries[i]!.delta!);
    return mesh;
  }
}

function arraysOf(mesh: HalfedgeMesh): ArrayMap {
  const nH = mesh.halfedgeSlots;
  const arrays: ArrayMap = new Map<string, AttributeArray | Int32Array | Uint8Array>([
    ['heNext', mesh.heNext.subarray(0, nH)],
    ['hePrev', mesh.hePrev.subarray(0, nH)],
    ['heVertex', mesh.heVertex.subarray(0, nH)],
    ['heFace', mesh.heFace.subarray(0, nH)],
    ['vHalfedge', mesh.vHalfedge.subarray(0, mesh.vertexSlots)],
    ['fHalfedge', mesh.fHalfedge.subarray(0, mesh.faceSlots)],
    ['vDeleted', mesh.vDeleted.subarray(0, mesh.vertexSlots)],
    ['eDeleted', mesh.eDeleted.subarray(0, mesh.edgeSlots)],
    ['fDeleted', mesh.fDeleted.subarray(0, mesh.faceSlots)],
  ]);
  const sets = [
    ['v', mesh.vertexAttributes, mesh.vertexSlots],
    ['h', mesh.halfedgeAttributes, nH],
    ['e', mesh.edgeAttributes, mesh.edgeSlots],
    ['f', mesh.faceAttributes, mesh.faceSlots],
  ] as const;
  for (const [prefix, set, slots] of sets) {
    for (const { name, data, itemSize } of set) arrays.set(`${prefix}:${name}`, data.subarray(0, slots * itemSize));
  }
  return arrays;
}

function meshBytes(mesh: HalfedgeMesh): number {
  let bytes = 0;
  for (const array of arraysOf(mesh).values()) bytes += array.byteLength;
  return bytes;
}

/**
 * How `after` differs from `before`, array by array; null when the difference would take more
 * than `budget` bytes (then the whole mesh is the smaller record) or the attributes differ.
 */
function difference(before: HalfedgeMesh, after: HalfedgeMesh, budget: number): MeshDelta | null {
  const old = arraysOf(before);
  const now = arraysOf(after);
  if (old.size !== now.size || [...now.keys()].some((key) => !old.has(key))) return null;
  const arrays = new Map<string, ArrayChange>();
  let bytes = 0;
  for (const [key, array] of now) {
    const previous = old.get(key)!;
    const changed: number[] = [];
    const shared = Math.min(previous.length, array.length);
    for (let i = 0; i < shared && changed.length * 12 < array.byteLength; i++) {
      // Object.is: a NaN that stays NaN is no change, and -0 → 0 is one
      if (!Object.is(previous[i], array[i])) changed.push(i);
    }
    for (let i = shared; i < array.length && changed.length * 12 < array.byteLength; i++) changed.push(i);
    if (changed.length === 0 && previous.length === array.length) continue;
    const dense = changed.length * 12 >= array.byteLength;
    bytes += dense ? array.byteLength : 12 * changed.length;
    if (bytes > budget) return null;
    // a dense change is the new array itself, shared with `after` (which is never changed again)
    if (dense) arrays.set(key, { dense: array });
    else arrays.set(key, { indices: Int32Array.from(changed), values: Float64Array.from(changed, (i) => array[i]!) });
  }
  return { slots: { vertices: after.vertexSlots, edges: after.edgeSlots, faces: after.faceSlots }, arrays, bytes };
}

/**
 * Where `delta` found an array unchanged, `mesh` takes the previous mesh's array itself: the two
 * share it (neither is ever changed again), so smoothing costs the history its positions only.
 */
function shareUnchanged(previous: HalfedgeMesh, mesh: HalfedgeMesh, delta: MeshDelta): void {
  const sameSlots =
    previous.vertexSlots === mesh.vertexSlots && previous.edgeSlots === mesh.edgeSlots && previous.faceSlots === mesh.faceSlots;
  if (!sameSlots) return;
  const fields = ['heNext', 'hePrev', 'heVertex', 'heFace', 'vHalfedge', 'fHalfedge', 'vDeleted', 'eDeleted', 'fDeleted'] as const;
  for (const field of fields) {
    if (!delta.arrays.has(field)) (mesh as unknown as Record<string, unknown>)[field] = previous[field];
  }
  const sets = [
    ['v', previous.vertexAttributes, mesh.vertexAttributes],
    ['h', previous.halfedgeAttributes, mesh.halfedgeAttributes],
    ['e', previous.edgeAttributes, mesh.edgeAttributes],
    ['f', previous.faceAttributes, mesh.faceAttributes],
  ] as const;
  for (const [prefix, before, after] of sets) {
    for (const attribute of after) {
      if (!delta.arrays.has(`${prefix}:${attribute.name}`)) attribute.data = before.get(attribute.name)!.data;
    }
  }
}

/** Turns the entry before's mesh into this entry's, in place. */
function apply(mesh: HalfedgeMesh, delta: MeshDelta): void {
  const { vertices, edges, faces } = delta.slots;
  mesh.reserve({ vertices, edges, faces });
  mesh.vertexSlots = vertices;
  mesh.edgeSlots = edges;
  mesh.faceSlots = faces;
  const arrays = arraysOf(mesh);
  for (const [key, change] of delta.arrays) {
    const target = arrays.get(key)!;
    if ('dense' in change) target.set(change.dense);
    else for (let i = 0; i < change.indices.length; i++) target[change.indices[i]!] = change.values[i]!;
  }
  mesh.recountDeleted();
}
