/**
 * Phase 3 of the plane cut: split each face the plane crosses along the cut, so that afterwards
 * every face lies on one side (its corners are all ≥ 0 or all ≤ 0).
 *
 * After phase 2, wherever a face's outline passes from one side to the other it does so at a
 * corner on the plane (0). Walking round the face, each side of the outline runs on one side of
 * the plane: that of its corners off the plane or, for a side lying in the plane, the one where
 * the face's inside is next to it. A *crossing* is a corner where this changes (a corner where the
 * outline only touches the plane is none). Crossings come in pairs, and each pair is joined by a
 * new edge along the plane:
 *
 * ```
 *     + ───── 0 ───── −           a convex face: 2 crossings, 1 new edge
 *     │       ┊       │
 *     + ───── 0 ───── −
 *
 *     +───+   +───+               a U-shaped face crossed twice (line ┄): 4 crossings,
 *   ┄┄0┄┄┄0┄┄┄0┄┄┄0┄┄              joined in order along the line: 1–2 and 3–4
 *     −   −───−   −               (2–3 would run through the notch, outside the face)
 *     −───────────−
 * ```
 * Along the cutting line, inside and outside alternate, so the crossings sorted along it pair up
 * as 1–2, 3–4, …. (Cut exactly along the bottom of the U's notch, the two ends of that bottom
 * are crossings too, and the line pairs them with the outer ones.) For a face that is far from
 * planar, that order can give edges that cross; the face is then split by crossings paired in
 * their order round the face, which always gives pieces on one side each.
 *
 * Two crossings already joined by an edge elsewhere (on a coarse mesh, two corners of a quad on
 * the plane may be neighbours round the other way) are joined through a new vertex halfway, on
 * the plane too: a second edge between the same two vertices is what no file can hold.
 */
import { faceVectorArea } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import { halfedgeFromTo } from '../edits/find.js';
import { splitEdgeAt } from '../edits/split-edge.js';
import { splitFaceAt } from '../edits/split-face.js';
import type { PointerWriter } from '../change/writer.js';
import type { UnitPlane } from './plane.js';

/**
 * Splits every face around the vertices `onPlane` that has corners on both sides (`side[v]`
 * is +1, −1 or 0). Returns the faces that were split, and the vertices made halfway along new
 * edges (on the plane).
 */
export function splitCrossedFaces(
  w: PointerWriter,
  side: Int8Array,
  onPlane: ArrayLike<number>,
  plane: UnitPlane,
): { split: number[]; midpoints: number[] } {
  const mesh = w.mesh;
  const { hePrev, heFace } = mesh;
  // only faces with a corner on the plane can be crossed now
  const seen = new Uint8Array(mesh.faceSlots);
  const candidates: number[] = [];
  for (let i = 0; i < onPlane.length; i++) {
    const start = mesh.vHalfedge[onPlane[i]];
    if (start < 0) continue;
    let h = start;
    do {
      const f = heFace[h];
      if (f !== -1 && !seen[f]) {
        seen[f] = 1;
        candidates.push(f);
      }
      h = hePrev[h] ^ 1;
    } while (h !== start);
  }
  const split: number[] = [];
  const midpoints: number[] = [];
  for (const f of candidates) if (splitAtCrossings(w, f, side, plane, midpoints)) split.push(f);
  return { split, midpoints };
}

/** Splits face `f` at its crossings; false when it has none. */
function splitAtCrossings(w: PointerWriter, f: number, side: Int8Array, plane: UnitPlane, midpoints: number[]): boolean {
  const mesh = w.mesh;
  const { heNext, heVertex } = mesh;
  const loop: number[] = [];
  let above = false;
  let below = false;
  let h = mesh.fHalfedge[f];
  do {
    loop.push(h);
    above ||= side[heVertex[h]] > 0;
    below ||= side[heVertex[h]] < 0;
    h = heNext[h];
  } while (h !== mesh.fHalfedge[f]);
  if (!above || !below) return false;

  // which side of the plane each of the face's sides runs on: that of an end off the plane or,
  // for a face side lying in the plane, the one where the face's inside is next to it (taken
  // from the face side before when the face is too warped to tell)
  const k = loop.length;
  const normal = faceVectorArea(mesh, f);
  const along = loop.map((g, i) => side[heVertex[g]] || side[heVertex[loop[(i + 1) % k]]] || sideOfInside(mesh, g, normal, plane));
  const start = along.findIndex((s) => s !== 0);
  for (let j = 1; j < k; j++) {
    const i = (start + j) % k;
    if (along[i] === 0) along[i] = along[(i + k - 1) % k];
  }
  // a crossing: a corner (on the plane) where the outline goes on at the other side
  const crossings: number[] = []; // the halfedges leaving the crossing corners
  for (let i = 0; i < k; i++) if (along[(i + k - 1) % k] !== along[i]) crossings.push(loop[i]);
  for (const [a, b] of pairCrossings(mesh, loop, crossings, normal, plane)) {
    const joined = halfedgeFromTo(mesh, heVertex[crossings[a]], heVertex[crossings[b]]) !== -1;
    const edge = splitFaceAt(w, crossings[a], crossings[b]);
    if (joined) midpoints.push(splitEdgeAt(w, edge, 0.5));
  }
  return true;
}

/**
 * For a side `g` of the face that lies in the plane: the side of the plane the face's inside is on
 * next to it (+1, −1, or 0 when the face is parallel to the plane). The inside is on the left:
 * along normal × (direction of g).
 */
function sideOfInside(mesh: HalfedgeMesh, g: number, normal: number[], plane: UnitPlane): number {
  const p = mesh.positions;
  const a = 3 * mesh.heVertex[g];
  const b = 3 * mesh.heVertex[mesh.heNext[g]];
  const dx = p[b] - p[a];
  const dy = p[b + 1] - p[a + 1];
  const dz = p[b + 2] - p[a + 2];
  const [nx, ny, nz] = normal;
  const inward = plane.nx * (ny * dz - nz * dy) + plane.ny * (nz * dx - nx * dz) + plane.nz * (nx * dy - ny * dx);
  return Math.sign(inward);
}

/** Pairs of crossings (indices in round-the-face order) to join by new edges. */
function pairCrossings(
  mesh: HalfedgeMesh,
  loop: number[],
  crossings: number[],
  normal: number[],
  plane: UnitPlane,
): Array<[number, number]> {
  const n = crossings.length;
  // sort along the cutting line within the face: direction = plane normal × face normal
  const [fx, fy, fz] = normal;
  const lx = plane.ny * fz - plane.nz * fy;
  const ly = plane.nz * fx - plane.nx * fz;
  const lz = plane.nx * fy - plane.ny * fx;
  const p = mesh.positions;
  const along = crossings.map((g) => {
    const v = 3 * mesh.heVertex[g];
    return p[v] * lx + p[v + 1] * ly + p[v + 2] * lz;
  });
  const order = along.map((_, i) => i).sort((i, j) => along[i] - along[j]);
  const pairs = (first: (i: number) => number, second: (i: number) => number) =>
    Array.from({ length: n / 2 }, (_, i): [number, number] => {
      const a = first(i);
      const b = second(i);
      return a < b ? [a, b] : [b, a];
    });
  const alongLine = pairs((i) => order[2 * i], (i) => order[2 * i + 1]);
  // new edges inside one face must not cross: as intervals of the round-the-face order, two
  // pairs may nest or be apart, but not overlap
  const crossing = alongLine.some(([a, b]) => alongLine.some(([c, d]) => a < c && c < b && b < d));
  const chosen = crossing ? pairs((i) => 2 * i, (i) => 2 * i + 1) : alongLine;
  // two crossings at the ends of one side lying in the plane are joined by that side already
  const k = loop.length;
  const position = new Map(loop.map((g, i) => [g, i]));
  return chosen.filter(([a, b]) => {
    const gap = Math.abs(position.get(crossings[a])! - position.get(crossings[b])!);
    return gap !== 1 && gap !== k - 1;
  });
}
