/**
 * Phase 4 of the plane cut: pull the two sides apart along the cut, so above and below become
 * separate pieces of surface, each with a hole where the cut ran.
 *
 * Each face now lies on one side. A *cut edge* is an edge with faces on both sides (its ends are
 * on the plane). It becomes two edges, one per side: the halfedge on the below side moves to a
 * new edge, and the two halfedges left without a face become boundary halfedges.
 *
 * ```
 *        above                         above
 *   ───── h ─────►                ───── h ─────►       h keeps edge e; t is now boundary
 *   ◄──── t ──────       ──►      ◄──── t ──────
 *        below                    ───── g ─────►       g (boundary) and g' (in place of t)
 *                                 ◄──── g' ─────       make the new edge e'
 *                                      below
 * ```
 * A vertex on the cut keeps one fan of faces per side, or more: going round it, each run of
 * faces between two gaps (cut edges, or a hole it was already on) is an *arc*, and each arc gets
 * its own vertex (the first keeps the old id; the others are copies with the same attributes).
 * That keeps the surface manifold even where it only touches the plane from one side at a vertex.
 * Last, the boundary halfedges at each arc are linked: the one arriving at the arc's clockwise
 * end continues with the one leaving its counter-clockwise end.
 */
import { faceVectorArea } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { PointerWriter } from '../change/writer.js';
import type { UnitPlane } from './plane.js';

/**
 * The side of every face: the sign of its corners off the plane. A face lying in the plane
 * belongs to the side behind it (the side its normal points away from): a cube cut along its
 * bottom face keeps that face with the cube, above the plane.
 */
export function faceSides(mesh: HalfedgeMesh, side: Int8Array, plane: UnitPlane): Int8Array {
  const { heNext, heVertex, fHalfedge, fDeleted } = mesh;
  const sides = new Int8Array(mesh.faceSlots);
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const start = fHalfedge[f];
    let h = start;
    let s = side[heVertex[h]];
    while (s === 0) {
      h = heNext[h];
      if (h === start) break;
      s = side[heVertex[h]];
    }
    if (s === 0) {
      const [x, y, z] = faceVectorArea(mesh, f);
      s = x * plane.nx + y * plane.ny + z * plane.nz > 0 ? -1 : 1;
    }
    sides[f] = s;
  }
  return sides;
}

export interface Separation {
  /** The edges that had faces on both sides (they keep the above side's halfedge). */
  cutEdges: number[];
  /** The new edge of each cut edge (holding the below side's halfedge), in the same order. */
  newEdges: number[];
  /** The vertices on the cut (each keeps its first arc). */
  cutVertices: number[];
}

/** Separates the sides along the edges around `onPlane` vertices whose faces differ in side. */
export function separateSides(w: PointerWriter, onPlane: ArrayLike<number>, faceSide: Int8Array): Separation {
  const mesh = w.mesh;
  const { hePrev, heFace, vHalfedge } = mesh;

  // the cut edges, each seen once from the end its even halfedge leaves
  const cutEdges: number[] = [];
  const cutVertices: number[] = [];
  const arcStarts: number[] = [];
  for (let i = 0; i < onPlane.length; i++) {
    const v = onPlane[i];
    const start = vHalfedge[v];
    if (start < 0) continue;
    let h = start;
    let onCut = false;
    do {
      const f = heFace[h];
      const g = heFace[h ^ 1];
      if (f !== -1 && g !== -1 && faceSide[f] !== faceSide[g]) {
        onCut = true;
        if ((h & 1) === 0) cutEdges.push(h >> 1);
      }
      h = hePrev[h] ^ 1;
    } while (h !== start);
    if (!onCut) continue;
    cutVertices.push(v);
    // a vertex already on a hole: one arc starts after that hole
    if (heFace[start] === -1) arcStarts.push(hePrev[start] ^ 1);
  }

  // each cut edge: the halfedge on the below side moves to a new edge
  const newEdges: number[] = [];
  for (const e of cutEdges) {
    const n = w.addEdge();
    const { heNext, hePrev, heVertex, heFace, fHalfedge } = mesh; // after any growth
    const t = faceSide[heFace[2 * e]] > 0 ? 2 * e + 1 : 2 * e; // the below side's halfedge
    const f = heFace[t];
    const g = 2 * n;
    const gt = g + 1; // takes t's place in its face
    mesh.edgeAttributes.copy(n, e);
    mesh.halfedgeAttributes.copy(gt, t);
    w.setOrigin(gt, heVertex[t]);
    w.setOrigin(g, heVertex[t ^ 1]);
    w.link(hePrev[t], gt);
    w.link(gt, heNext[t]);
    w.setFace(gt, f);
    if (fHalfedge[f] === t) w.setFaceHalfedge(f, gt);
    w.setFace(t, -1);
    newEdges.push(n);
    // each side's arcs start (going counter-clockwise) at its interior halfedge of the cut edge
    arcStarts.push(t ^ 1, gt);
  }

  // one vertex per arc; link the boundary halfedges at each arc
  const claimed = new Uint8Array(mesh.vertexSlots);
  for (const start of arcStarts) {
    const v = mesh.heVertex[start];
    let u = v;
    if (claimed[v]) {
      u = w.addVertex();
      mesh.vertexAttributes.copy(u, v);
    }
    claimed[v] = 1;
    // rotate counter-clockwise through the arc's faces to the boundary halfedge that ends it
    let h = start;
    let out = mesh.hePrev[h] ^ 1;
    w.setOrigin(h, u);
    while (mesh.heFace[out] !== -1) {
      h = out;
      w.setOrigin(h, u);
      out = mesh.hePrev[h] ^ 1;
    }
    w.setOrigin(out, u);
    w.link(start ^ 1, out);
    w.setVertexHalfedge(u, out);
  }
  return { cutEdges, newEdges, cutVertices };
}
