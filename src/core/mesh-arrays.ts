/**
 * The schema of a mesh's own arrays: their names, the kind of element that owns each entry, what
 * an entry points to, and the value a new element starts with. Everything that treats the mesh as
 * a set of arrays (growing, trimming, compacting and copying it, serializing it, recording and
 * undoing changes) loops over this one list instead of naming the nine arrays by hand.
 *
 * The length of an array follows its owner's slot count: `vertexSlots`, `2 × edgeSlots` for
 * halfedges, `edgeSlots`, `faceSlots`. Attributes follow the same rule through their set
 * (`attributeSetOf`).
 */
import type { AttributeSet } from './attributes.js';
import type { HalfedgeMesh, MeshCapacity } from './mesh.js';

export type ElementKind = 'vertex' | 'halfedge' | 'edge' | 'face';

export type MeshArrayName = 'heNext' | 'hePrev' | 'heVertex' | 'heFace' | 'vHalfedge' | 'fHalfedge' | 'vDeleted' | 'eDeleted' | 'fDeleted';

export interface MeshArraySpec {
  name: MeshArrayName;
  owner: ElementKind;
  /** The kind of element an entry names (renumbered by compaction), or null for a flag. */
  refers: ElementKind | null;
  /** How the pointer diff calls it (null: a flag, which the diff does not list). */
  field: 'next' | 'prev' | 'origin' | 'face' | 'halfedge' | null;
  type: Int32ArrayConstructor | Uint8ArrayConstructor;
  /** What a new element holds until it is wired: -1 ("none") for pointers, 0 for flags. */
  initial: number;
}

export const meshArrays: readonly MeshArraySpec[] = [
  { name: 'heNext', owner: 'halfedge', refers: 'halfedge', field: 'next', type: Int32Array, initial: -1 },
  { name: 'hePrev', owner: 'halfedge', refers: 'halfedge', field: 'prev', type: Int32Array, initial: -1 },
  { name: 'heVertex', owner: 'halfedge', refers: 'vertex', field: 'origin', type: Int32Array, initial: -1 },
  { name: 'heFace', owner: 'halfedge', refers: 'face', field: 'face', type: Int32Array, initial: -1 },
  { name: 'vHalfedge', owner: 'vertex', refers: 'halfedge', field: 'halfedge', type: Int32Array, initial: -1 },
  { name: 'fHalfedge', owner: 'face', refers: 'halfedge', field: 'halfedge', type: Int32Array, initial: -1 },
  { name: 'vDeleted', owner: 'vertex', refers: null, field: null, type: Uint8Array, initial: 0 },
  { name: 'eDeleted', owner: 'edge', refers: null, field: null, type: Uint8Array, initial: 0 },
  { name: 'fDeleted', owner: 'face', refers: null, field: null, type: Uint8Array, initial: 0 },
];

/** Position of each array in `meshArrays`, for compact records of writes. */
export const meshArrayIndex = Object.fromEntries(meshArrays.map((spec, i) => [spec.name, i])) as Record<MeshArrayName, number>;

export const elementKinds: readonly ElementKind[] = ['vertex', 'halfedge', 'edge', 'face'];

/** Slot counts, as a mesh, its `slotState` or a copy of its pointers hold them. */
export interface SlotCounts {
  vertexSlots: number;
  edgeSlots: number;
  faceSlots: number;
}

/** Slots of a kind in use (deleted ones included): halfedges are two per edge slot. */
export function slotCount(counts: SlotCounts, kind: ElementKind): number {
  switch (kind) {
    case 'vertex':
      return counts.vertexSlots;
    case 'halfedge':
      return 2 * counts.edgeSlots;
    case 'edge':
      return counts.edgeSlots;
    case 'face':
      return counts.faceSlots;
  }
}

/** Entries per kind for a count of vertices, edges and faces: halfedges are two per edge. */
export function lengthsByKind({ vertices, edges, faces }: MeshCapacity): Record<ElementKind, number> {
  return { vertex: vertices, halfedge: 2 * edges, edge: edges, face: faces };
}

/** How many entries of each kind a set of mesh arrays has room for (a mesh's, or a serialized mesh's). */
export function roomByKind(arrays: Pick<HalfedgeMesh, 'vHalfedge' | 'heNext' | 'eDeleted' | 'fHalfedge'>): Record<ElementKind, number> {
  return { vertex: arrays.vHalfedge.length, halfedge: arrays.heNext.length, edge: arrays.eDeleted.length, face: arrays.fHalfedge.length };
}

export function attributeSetOf(mesh: HalfedgeMesh, kind: ElementKind): AttributeSet {
  switch (kind) {
    case 'vertex':
      return mesh.vertexAttributes;
    case 'halfedge':
      return mesh.halfedgeAttributes;
    case 'edge':
      return mesh.edgeAttributes;
    case 'face':
      return mesh.faceAttributes;
  }
}

/** Bytes the mesh's arrays and attributes take, at their capacity. */
export function meshByteLength(mesh: HalfedgeMesh): number {
  let bytes = 0;
  for (const { name } of meshArrays) bytes += mesh[name].byteLength;
  for (const kind of elementKinds) for (const { data } of attributeSetOf(mesh, kind)) bytes += data.byteLength;
  return bytes;
}

/** Replaces an array (growth, trimming, compaction, adopting a serialized one). */
export function setMeshArray(mesh: HalfedgeMesh, name: MeshArrayName, array: Int32Array | Uint8Array): void {
  (mesh as unknown as Record<MeshArrayName, Int32Array | Uint8Array>)[name] = array;
}
