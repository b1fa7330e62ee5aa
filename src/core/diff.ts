/**
 * The pointer diff: which `next`, `prev`, `origin`, `face` (of halfedges) and `halfedge` (of
 * vertices and faces) fields differ between two states of a mesh, old → new. The app shows it
 * after every step ("what did this stage rewire?"), and the tests check that each local edit
 * reports exactly the changes this comparison finds.
 */
import type { HalfedgeMesh } from './mesh.js';

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

/**
 * Compares every pointer of two meshes, element by element (ids are compared as they are: an
 * element that exists on one side only counts as changing from or to -1). Deleted elements
 * count as absent.
 */
export function diffPointers(before: HalfedgeMesh, after: HalfedgeMesh, limit = 10_000): PointerDiff {
  const changes: PointerChange[] = [];
  let total = 0;
  const note = (element: PointerChange['element'], id: number, field: PointerField, a: number, b: number) => {
    if (a === b) return;
    total++;
    if (changes.length < limit) changes.push({ element, id, field, before: a, after: b });
  };
  const halfedgeSlots = Math.max(before.halfedgeSlots, after.halfedgeSlots);
  const liveHalfedge = (mesh: HalfedgeMesh, h: number) => h < mesh.halfedgeSlots && mesh.eDeleted[h >> 1] === 0;
  for (let h = 0; h < halfedgeSlots; h++) {
    const inBefore = liveHalfedge(before, h);
    const inAfter = liveHalfedge(after, h);
    if (!inBefore && !inAfter) continue;
    const read = (mesh: HalfedgeMesh, live: boolean, array: 'heNext' | 'hePrev' | 'heVertex' | 'heFace') =>
      live ? mesh[array][h] : -1;
    note('halfedge', h, 'next', read(before, inBefore, 'heNext'), read(after, inAfter, 'heNext'));
    note('halfedge', h, 'prev', read(before, inBefore, 'hePrev'), read(after, inAfter, 'hePrev'));
    note('halfedge', h, 'origin', read(before, inBefore, 'heVertex'), read(after, inAfter, 'heVertex'));
    note('halfedge', h, 'face', read(before, inBefore, 'heFace'), read(after, inAfter, 'heFace'));
  }
  const vertexSlots = Math.max(before.vertexSlots, after.vertexSlots);
  for (let v = 0; v < vertexSlots; v++) {
    const a = v < before.vertexSlots && !before.vDeleted[v] ? before.vHalfedge[v] : -1;
    const b = v < after.vertexSlots && !after.vDeleted[v] ? after.vHalfedge[v] : -1;
    note('vertex', v, 'halfedge', a, b);
  }
  const faceSlots = Math.max(before.faceSlots, after.faceSlots);
  for (let f = 0; f < faceSlots; f++) {
    const a = f < before.faceSlots && !before.fDeleted[f] ? before.fHalfedge[f] : -1;
    const b = f < after.faceSlots && !after.fDeleted[f] ? after.fHalfedge[f] : -1;
    note('face', f, 'halfedge', a, b);
  }
  return { changes, total };
}
