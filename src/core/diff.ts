/**
 * The pointer diff: which `next`, `prev`, `origin`, `face` (of halfedges) and `halfedge` (of
 * vertices and faces) fields differ between two states of a mesh, old → new. The app shows it
 * after every step ("what did this stage rewire?"), and the tests check that each local edit
 * reports exactly the changes this comparison finds.
 */
import type { HalfedgeMesh } from './mesh.js';
import { type MeshArrayName, type MeshArraySpec, meshArrays, slotCount } from './mesh-arrays.js';
import type { Phase } from './operation.js';

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
 * count as absent. The comparison is the check of change records and of phase diffs.
 */
export function diffPointers(before: MeshPointers, after: MeshPointers, limit = DIFF_LISTED): PointerDiff {
  return compare(before, after, limit, null);
}

/**
 * The pointer diff of a phase, read off what it says it created, rewired and removed (its
 * `Phase` lists): only those elements are compared, so a phase that only moves vertices costs
 * nothing, and one that rewires the whole mesh what it wrote. Equal to `diffPointers` of the
 * whole mesh for every phase of the stepped operations (tested).
 */
export function phaseDiff(before: MeshPointers, after: MeshPointers, phase: Phase, limit = DIFF_LISTED): PointerDiff {
  if (!phase.created && !phase.rewired && !phase.removed) return { changes: [], total: 0 };
  const marks = {
    halfedge: new Uint8Array(Math.max(slotCount(before, 'halfedge'), slotCount(after, 'halfedge'))),
    vertex: new Uint8Array(Math.max(before.vertexSlots, after.vertexSlots)),
    face: new Uint8Array(Math.max(before.faceSlots, after.faceSlots)),
  };
  for (const ids of [phase.created, phase.rewired, phase.removed]) {
    if (!ids) continue;
    for (const h of ids.halfedges ?? []) marks.halfedge[h] = 1;
    for (const e of ids.edges ?? []) marks.halfedge[2 * e] = marks.halfedge[2 * e + 1] = 1;
    for (const v of ids.vertices ?? []) marks.vertex[v] = 1;
    for (const f of ids.faces ?? []) marks.face[f] = 1;
  }
  return compare(before, after, limit, marks);
}

/** The fields of each kind's pointers, in the order a diff lists them. */
const pointerArrays = Object.fromEntries(
  (['halfedge', 'vertex', 'face'] as const).map((kind) => [kind, meshArrays.filter((spec) => spec.owner === kind && spec.field)]),
) as Record<'halfedge' | 'vertex' | 'face', MeshArraySpec[]>;

const deletedArray = { halfedge: 'eDeleted', vertex: 'vDeleted', face: 'fDeleted' } as const;

/** Compares the pointers of the elements marked (null: all), halfedges then vertices then faces, each by id. */
function compare(before: MeshPointers, after: MeshPointers, limit: number, marks: Record<'halfedge' | 'vertex' | 'face', Uint8Array> | null): PointerDiff {
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
    const marked = marks?.[kind];
    const count = Math.max(beforeCount, afterCount);
    for (let id = 0; id < count; id++) {
      if (marked && marked[id] === 0) continue;
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
