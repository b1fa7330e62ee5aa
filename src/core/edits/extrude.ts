/**
 * Face extrusion: face f of k corners is surrounded by a ring of k quads, one per side, and its
 * corners are copied to k new vertices, which then move: `offset` along f's normal, and `inset` of
 * the way toward its centroid. Offset 0 with inset > 0 is the usual "inset face"; both 0 leave the
 * ring flat (zero-area quads), ready to be pulled out later.
 *
 * ```
 *      v3 ◄──────────────── v2             v3 ◄──────────────── v2
 *       │                    ▲              │ ╲       q2       ╱ ▲
 *       │                    │              │  u3 ◄──────── u2   │
 *       │                    │              │   │            ▲   │
 *       │         f          │     ──►      │q3 │     f      │ q1│     u_i: the copy of v_i
 *       │                    │              │   ▼            │   │     q_i: the quad on side i
 *       │                    │              │  u0 ────────► u1   │
 *       ▼                    │              ▼ ╱       q0       ╲ │
 *      v0 ────────────────► v1             v0 ────────────────► v1
 * ```
 * Side i (halfedge h_i, v_i → v_i+1) stays where it was, with its twin: it becomes the outer side
 * of q_i, so the face across it (or the hole, when h_i is on the boundary) does not change. Each
 * quad is q_i = (v_i, v_i+1, u_i+1, u_i); f keeps its id and runs around the new corners u_i on k
 * new "rim" edges, and k new "rung" edges join each v_i to its u_i.
 *
 * Counts: k vertices, 2k edges and k faces more; the Euler characteristic does not change.
 *
 * Attributes: u_i copies v_i's vertex attributes (then its position moves); each quad copies f's
 * face attributes, and each rim edge the edge attributes of its side (rungs are new: zero). Corner
 * values (texture coordinates…) follow the corner they grew from: f keeps its own at u_i, and each
 * quad takes f's old values at its two ends along both of them, so the ring is a strip of zero width
 * in texture space and no seam appears between f, the ring and the rest.
 *
 * Positions: with c the centroid of f (the mean of its corners) and n its unit normal (Newell's
 * vector area, normalised, so the area-weighted normal of a warped face),
 * `u_i = (1 − inset)·v_i + inset·c + offset·n`: the moved face's centroid is c + offset·n.
 */
import { faceHalfedges } from '../circulators.js';
import { TopologyError } from '../errors.js';
import { faceCentroid, faceNormal } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingFace } from './find.js';
import { type EditOptions, type FaceEditResult, PointerWriter } from '../change/writer.js';

/** Where an extruded face goes. */
export interface ExtrudePlacement {
  /** How far the face moves along its unit normal (negative: inward); default 0. */
  offset?: number;
  /** The fraction of the way each corner moves toward the face's centroid, 0 … 1; default 0. */
  inset?: number;
}

export interface ExtrudeOptions extends EditOptions, ExtrudePlacement {}

/**
 * Why face `f` cannot be extruded with these options, or null when it can. Any live face can,
 * on the boundary too; refused are an inset outside 0 … 1 (1 already shrinks the face to a point),
 * an offset that is not a finite number, and a non-zero offset on a face of zero area, which has
 * no normal to move along.
 * @example canExtrudeFace(mesh, f, { offset: 0.2 }) // null, or "f3 has no area, …"
 */
export function canExtrudeFace(mesh: HalfedgeMesh, f: number, placement: ExtrudePlacement = {}): string | null {
  const missing = missingFace(mesh, f);
  if (missing) return missing;
  const { offset = 0, inset = 0 } = placement;
  if (!(inset >= 0 && inset <= 1)) {
    return `inset = ${inset} is not between 0 and 1: it is the fraction of the way the corners of f${f} move toward its centroid`;
  }
  if (!Number.isFinite(offset)) return `offset = ${offset} is not a finite number: f${f} cannot move that far`;
  if (offset !== 0) {
    const [x, y, z] = faceNormal(mesh, f);
    if (x === 0 && y === 0 && z === 0) {
      return `f${f} has no area, so no normal to move it along: extrude it with offset 0 (inset alone works)`;
    }
  }
  return null;
}

/**
 * Surrounds face `f` with a ring of quads and moves its corners by `offset` along its normal and
 * `inset` toward its centroid (see the diagram above). Returns `f`, whose corners are now the new
 * vertices; `created` lists the new vertices, edges (rims, then rungs) and quads.
 * @example const { face } = extrudeFace(mesh, f, { offset: 0.5, inset: 0.2 });
 * @throws TopologyError with `canExtrudeFace`'s sentence when the extrusion does not apply.
 */
export function extrudeFace(mesh: HalfedgeMesh, f: number, options: ExtrudeOptions = {}): FaceEditResult {
  const why = canExtrudeFace(mesh, f, options);
  if (why) throw new TopologyError(`extrudeFace: ${why}`);
  const offset = options.offset ?? 0;
  const inset = options.inset ?? 0;

  // where the new corners go, read off the face as it is
  const sides = [...faceHalfedges(mesh, f)];
  const k = sides.length;
  const corners = sides.map((h) => mesh.heVertex[h]);
  const centroid = faceCentroid(mesh, f);
  const normal = offset === 0 ? [0, 0, 0] : faceNormal(mesh, f);
  const places = corners.map((v) => mesh.position(v).map((x, c) => (1 - inset) * x + inset * centroid[c] + offset * normal[c]));

  // new elements first: adding may grow the arrays
  const w = new PointerWriter(mesh, options);
  const inner = corners.map(() => w.addVertex());
  const rims = sides.map(() => w.addEdge());
  const rungs = sides.map(() => w.addEdge());
  const quads = sides.map(() => w.addFace());

  // values: u_i is a copy of v_i, moved; each quad is a copy of f; each rim of its side
  for (let i = 0; i < k; i++) {
    w.copy('vertex', inner[i], corners[i]);
    w.setPosition(inner[i], places[i][0], places[i][1], places[i][2]);
    w.copy('face', quads[i], f);
    w.copy('edge', rims[i], sides[i] >> 1);
  }

  for (let i = 0; i < k; i++) {
    const j = (i + 1) % k;
    const side = sides[i]; // v_i → v_j, stays: the outer side of q_i
    const rim = 2 * rims[i]; // u_i → u_j, in f
    const rimOut = rim + 1; // u_j → u_i, in q_i
    const up = 2 * rungs[j]; // v_j → u_j, in q_i
    const down = 2 * rungs[i] + 1; // u_i → v_i, in q_i
    // corner values: f's at v_i and v_j, wherever f or q_i now has a corner there or above it
    w.copy('halfedge', rim, side);
    w.copy('halfedge', down, side);
    w.copy('halfedge', up, sides[j]);
    w.copy('halfedge', rimOut, sides[j]);
    // rung i: v_i → u_i and back
    w.setOrigin(2 * rungs[i], corners[i]);
    w.setOrigin(2 * rungs[i] + 1, inner[i]);
    w.setOrigin(rim, inner[i]);
    w.setOrigin(rimOut, inner[j]);
    // q_i = v_i → v_j → u_j → u_i
    w.link(side, up);
    w.link(up, rimOut);
    w.link(rimOut, down);
    w.link(down, side);
    for (const g of [side, up, rimOut, down]) w.setFace(g, quads[i]);
    w.setFaceHalfedge(quads[i], side);
  }
  // f = u_0 → u_1 → … on the rims; the v_i keep their handles (their old halfedges all still leave them)
  for (let i = 0; i < k; i++) {
    w.link(2 * rims[i], 2 * rims[(i + 1) % k]);
    w.setFace(2 * rims[i], f);
    w.setVertexHalfedge(inner[i], 2 * rims[i]);
  }
  w.setFaceHalfedge(f, 2 * rims[0]);
  return { ...w.result(), face: f };
}
