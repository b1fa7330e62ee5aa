/** Small look-ups the edits share. */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';

/**
 * The halfedge from `u` to `v`, or -1 when no edge joins them. Rotates around `u`: O(valence).
 * @example if (halfedgeFromTo(mesh, c, d) !== -1) return 'c and d are already joined';
 */
export function halfedgeFromTo(mesh: HalfedgeMesh, u: number, v: number): number {
  const { hePrev, heVertex } = mesh;
  const start = mesh.vHalfedge[u];
  if (start < 0) return -1;
  let h = start;
  do {
    if (heVertex[h ^ 1] === v) return h;
    h = hePrev[h] ^ 1;
  } while (h !== start);
  return -1;
}

/** The halfedge of face `f` that starts at `v`, or -1 when `v` is not a corner of `f`. O(degree). */
export function faceHalfedgeFrom(mesh: HalfedgeMesh, f: number, v: number): number {
  const { heNext, heVertex } = mesh;
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    if (heVertex[h] === v) return h;
    h = heNext[h];
  } while (h !== start);
  return -1;
}

/** True when the `next` cycle through `h` has exactly three halfedges. */
export function isTriangleLoop(mesh: HalfedgeMesh, h: number): boolean {
  const { heNext } = mesh;
  return heNext[heNext[heNext[h]]] === h;
}

/** Why `e` is not a live edge of `mesh` ("e12 is deleted"), or null when it is one. */
export function missingEdge(mesh: HalfedgeMesh, e: number): string | null {
  if (!Number.isInteger(e) || e < 0 || e >= mesh.edgeSlots) return `e${e} is not an edge of this mesh (ids run 0…${mesh.edgeSlots - 1})`;
  return mesh.eDeleted[e] ? `e${e} is deleted` : null;
}

/** Why `v` is not a live vertex of `mesh` ("v12 is deleted"), or null when it is one. */
export function missingVertex(mesh: HalfedgeMesh, v: number): string | null {
  if (!Number.isInteger(v) || v < 0 || v >= mesh.vertexSlots) return `v${v} is not a vertex of this mesh (ids run 0…${mesh.vertexSlots - 1})`;
  return mesh.vDeleted[v] ? `v${v} is deleted` : null;
}

/** Why `f` is not a live face of `mesh`, or null when it is one. */
export function missingFace(mesh: HalfedgeMesh, f: number): string | null {
  if (!Number.isInteger(f) || f < 0 || f >= mesh.faceSlots) return `f${f} is not a face of this mesh (ids run 0…${mesh.faceSlots - 1})`;
  return mesh.fDeleted[f] ? `f${f} is deleted` : null;
}

/**
 * The halfedges leaving origin(h), counter-clockwise from h (each the next one's `prev.twin`): a
 * walk bounded by the halfedge count, which throws on a rotation that does not close (an invalid mesh).
 */
export function rotationFrom(mesh: HalfedgeMesh, h: number): number[] {
  const { hePrev } = mesh;
  const rotation: number[] = [];
  let g = h;
  do {
    rotation.push(g);
    g = hePrev[g] ^ 1;
    if (rotation.length > mesh.halfedgeSlots) throw new TopologyError(`the rotation around v${mesh.heVertex[h]} does not close`);
  } while (g !== h);
  return rotation;
}
