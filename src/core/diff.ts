/**
 * The pointer diff: which `next`, `prev`, `origin`, `face` (of halfedges) and `halfedge` (of
 * vertices and faces) fields differ between two states of a mesh, old → new. The app shows it
 * after every step ("what did this stage rewire?"), and the tests check that each local edit
 * reports exactly the changes this comparison finds.
 */
import type { HalfedgeMesh } from './mesh.js';
import { type ElementKind, type MeshArrayName, meshArrays, slotCount } from './mesh-arrays.js';

export type PointerField = 'next' | 'prev' | 'origin' | 'face' | 'halfedge';

export interface PointerChange {
  element: 'halfedge' | 'vertex' | 'face';
  id: number;
  field: PointerField;
  /** -1 when the element did not exist before (or the field was unset). */
  before: number;
  /** -1 when the element no longer exists (or the field is unset). */
  after: number;
}

export interface PointerDiff {
  changes: PointerChange[];
  /** All changes found; `changes` stops at the limit. */
  total: number;
}

/** The part of a mesh the pointer diff reads: its arrays and slot counts (a mesh, or a `pointerCopy` of one). */
export type MeshPointers = Pick<HalfedgeMesh, MeshArrayName | 'vertexSlots' | 'edgeSlots' | 'faceSlots'>;

/** A copy of a mesh's own arrays, without its attributes: what a diff needs of the mesh before a change. */
export function pointerCopy(mesh: HalfedgeMesh): MeshPointers {
  const copy = { vertexSlots: mesh.vertexSlots, edgeSlots: mesh.edgeSlots, faceSlots: mesh.faceSlots } as MeshPointers;
  for (const { name, owner } of meshArrays) (copy as Record<MeshArrayName, Int32Array | Uint8Array>)[name] = mesh[name].slice(0, slotCount(mesh, owner));
  return copy;
}

/**
 * Compares every pointer of two meshes, element by element (ids are compared as they are: an
 * element that exists on one side only counts as changing from or to -1). Deleted elements
 * count as absent. The comparison is the check of change records, and what shows the work of a
 * phase that rewires the whole mesh (a subdivision step), where recording each write would cost more.
 */
export function diffPointers(before: MeshPointers, after: MeshPointers, limit = 10_000): PointerDiff {
  const changes: PointerChange[] = [];
  let total = 0;
  const deleted: Record<string, (mesh: MeshPointers) => Uint8Array> = {
    halfedge: (mesh) => mesh.eDeleted,
    vertex: (mesh) => mesh.vDeleted,
    face: (mesh) => mesh.fDeleted,
  };
  const live = (mesh: MeshPointers, kind: ElementKind, id: number) =>
    id < slotCount(mesh, kind) && deleted[kind](mesh)[kind === 'halfedge' ? id >> 1 : id] === 0;
  // halfedges (next, prev, origin, face of each in turn), then vertices, then faces: as an edit reports them
  for (const kind of ['halfedge', 'vertex', 'face'] as const) {
    const fields = meshArrays.filter((spec) => spec.owner === kind && spec.field);
    const count = Math.max(slotCount(before, kind), slotCount(after, kind));
    for (let id = 0; id < count; id++) {
      const inBefore = live(before, kind, id);
      const inAfter = live(after, kind, id);
      if (!inBefore && !inAfter) continue;
      for (const { name, field } of fields) {
        const a = inBefore ? before[name][id] : -1;
        const b = inAfter ? after[name][id] : -1;
        if (a === b) continue;
        total++;
        if (changes.length < limit) changes.push({ element: kind, id, field: field!, before: a, after: b });
      }
    }
  }
  return { changes, total };
}
