/**
 * `validate(mesh)` checks every invariant of the halfedge convention (see `mesh.ts`) and returns
 * each violation with the ids involved; an empty list means the mesh is sound.
 *
 * It runs the checks of `invariants.ts` on every element, with plain loops over the raw arrays,
 * never the circulators it is meant to vouch for, and every walk is bounded, so it terminates on
 * any corrupted mesh. Tests run it after every operation; the app runs it after every step (and
 * `validateAround` the same checks on the elements an edit touched).
 */
import {
  checkCycle,
  checkFace,
  checkHalfedge,
  checkParallelEdges,
  checkVertex,
  collectViolations,
  type Fail,
  SlotFlags,
  type ValidateOptions,
  VertexStamps,
  type Violation,
} from './invariants.js';
import type { HalfedgeMesh } from './mesh.js';

export type { Invariant, ValidateOptions, Violation } from './invariants.js';

export function validate(mesh: HalfedgeMesh, options: ValidateOptions = {}): Violation[] {
  return collectViolations(options, (fail, found) => {
    const { eDeleted, vDeleted, fDeleted } = mesh;
    const nH = mesh.halfedgeSlots;
    for (let h = 0; h < nH; h++) if (!eDeleted[h >> 1]) checkHalfedge(mesh, h, fail);
    if (found.length === 0) {
      const seen = new SlotFlags(nH);
      for (let h = 0; h < nH; h++) if (!seen.has(h) && !eDeleted[h >> 1]) checkCycle(mesh, h, seen, fail);
    }
    const corners = new VertexStamps(mesh.vertexSlots);
    for (let f = 0; f < mesh.faceSlots; f++) if (!fDeleted[f]) checkFace(mesh, f, corners, fail);
    const leaving = leavingCounts(mesh);
    for (let v = 0; v < mesh.vertexSlots; v++) {
      if (!vDeleted[v]) checkVertex(mesh, v, { count: leaving.count[v], boundary: leaving.boundary[v] }, fail);
    }
    checkAllParallelEdges(mesh, fail);
  });
}

/** For every vertex, how many live halfedges leave it and the last of them on the boundary. */
function leavingCounts(mesh: HalfedgeMesh): { count: Int32Array; boundary: Int32Array } {
  const { heVertex, heFace, eDeleted } = mesh;
  const nV = mesh.vertexSlots;
  const count = new Int32Array(nV);
  const boundary = new Int32Array(nV).fill(-1);
  for (let h = 0; h < mesh.halfedgeSlots; h++) {
    if (eDeleted[h >> 1]) continue;
    const v = heVertex[h];
    if (v < 0 || v >= nV) continue; // reported with the halfedges
    count[v]++;
    if (heFace[h] === -1) boundary[v] = h;
  }
  return { count, boundary };
}

/** Parallel edges, in linear time: the halfedges bucketed by origin (a counting sort), each vertex's targets stamped with its id. */
function checkAllParallelEdges(mesh: HalfedgeMesh, fail: Fail): void {
  const { heVertex, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const nV = mesh.vertexSlots;
  const inRange = (v: number) => v >= 0 && v < nV;
  const start = new Int32Array(nV + 1);
  for (let h = 0; h < nH; h++) {
    if (!eDeleted[h >> 1] && inRange(heVertex[h]) && inRange(heVertex[h ^ 1])) start[heVertex[h] + 1]++;
  }
  for (let v = 0; v < nV; v++) start[v + 1] += start[v];
  const fill = start.slice(0, nV);
  const byOrigin = new Int32Array(start[nV]);
  for (let h = 0; h < nH; h++) {
    if (!eDeleted[h >> 1] && inRange(heVertex[h]) && inRange(heVertex[h ^ 1])) byOrigin[fill[heVertex[h]]++] = h;
  }
  const targets = new VertexStamps(nV);
  for (let v = 0; v < nV; v++) checkParallelEdges(mesh, v, byOrigin, start[v], start[v + 1], targets, lowerEnd, fail);
}

/** Meeting every pair at both ends, the whole-mesh pass names it at the lower one. */
export const lowerEnd = (v: number, target: number) => v < target;
