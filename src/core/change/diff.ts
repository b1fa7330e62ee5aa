/**
 * The pointer diff: which `next`, `prev`, `origin`, `face` (of halfedges) and `halfedge` (of
 * vertices and faces) fields differ between two states of a mesh, old → new. The app shows it
 * after every step ("what did this stage rewire?"), read off the step's record (`pointerDiffOf`);
 * `diffPointers` finds it by comparing two meshes, the oracle the tests hold every record to.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { type MeshArrayName, type MeshArraySpec, meshArrays, slotCount } from '../mesh-arrays.js';

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

/** How many changes a diff lists (its `total` counts them all): enough to draw, not a copy of the mesh. */
export const DIFF_LISTED = 10_000;

export interface PointerDiff {
  changes: PointerChange[];
  /** All changes found; `changes` stops at the limit. */
  total: number;
}

/** The part of a mesh the pointer diff reads: its arrays and slot counts (a mesh, or a clone of one). */
export type MeshPointers = Pick<HalfedgeMesh, MeshArrayName | 'vertexSlots' | 'edgeSlots' | 'faceSlots'>;

/** The fields of each kind's pointers, in the order a diff lists them. */
const pointerArrays = Object.fromEntries(
  (['halfedge', 'vertex', 'face'] as const).map((kind) => [kind, meshArrays.filter((spec) => spec.owner === kind && spec.field)]),
) as Record<'halfedge' | 'vertex' | 'face', MeshArraySpec[]>;

const deletedArray = { halfedge: 'eDeleted', vertex: 'vDeleted', face: 'fDeleted' } as const;

/**
 * Compares every pointer of two meshes, element by element (ids are compared as they are: an
 * element that exists on one side only counts as changing from or to -1). Deleted elements
 * count as absent. The comparison is the check of change records.
 */
export function diffPointers(before: MeshPointers, after: MeshPointers, limit = DIFF_LISTED): PointerDiff {
  const changes: PointerChange[] = [];
  let total = 0;
  for (const kind of ['halfedge', 'vertex', 'face'] as const) {
    const specs = pointerArrays[kind];
    const old = specs.map((spec) => before[spec.name] as Int32Array);
    const now = specs.map((spec) => after[spec.name] as Int32Array);
    const beforeCount = slotCount(before, kind);
    const afterCount = slotCount(after, kind);
    const wasDeleted = before[deletedArray[kind]];
    const isDeleted = after[deletedArray[kind]];
    // a halfedge is deleted with its edge
    const shift = kind === 'halfedge' ? 1 : 0;
    const count = Math.max(beforeCount, afterCount);
    for (let id = 0; id < count; id++) {
      const inBefore = id < beforeCount && wasDeleted[id >> shift] === 0;
      const inAfter = id < afterCount && isDeleted[id >> shift] === 0;
      if (!inBefore && !inAfter) continue;
      for (let k = 0; k < specs.length; k++) {
        const a = inBefore ? old[k][id] : -1;
        const b = inAfter ? now[k][id] : -1;
        if (a === b) continue;
        total++;
        if (changes.length < limit) changes.push({ element: kind, id, field: specs[k].field!, before: a, after: b });
      }
    }
  }
  return { changes, total };
}
