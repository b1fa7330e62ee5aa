/**
 * The exploded view: the parts of the mesh (its connected components) drawn pulled apart, so that
 * parts that touch can each be seen: the two halves of a plane cut, whose caps lie face to face,
 * or the pieces of a model made of several. After a cut that kept both sides, the half above the
 * plane moves along its normal and the half below against it; otherwise each part moves away from
 * the centre of the whole (a part at the centre stays).
 *
 * Only the view moves, by one offset per part, added where the view takes its positions from:
 * - the surface, its edges and dots are one buffer for the whole mesh, so they get a copy of the
 *   render positions with every vertex moved by its part's offset (`explodedRender`);
 * - the arrows, highlights, labels, picking and framing all work out their points from a
 *   `HalfedgeMesh`, so they get a drawn mesh that reads every array of the page's mesh but these
 *   moved positions (`explodedMesh`).
 * A transform per part would not do: a part is not an object of its own in the scene, and every
 * layer that reads positions from the mesh would have to learn the transform. With the offsets
 * where positions are made, no layer knows the view is exploded, so none can disagree with
 * another; and the session's mesh, the records, the exports and the fingerprints never see them.
 */
import { boundingSphere, componentRoots, type HalfedgeMesh, unitPlane } from '../core/index.js';
import type { HistoryItem, RenderBuffers } from '../workers/protocol.js';
import { renderBounds } from '../workers/render.js';

/**
 * How far each part moves, as a share of the whole mesh's bounding radius: the two halves of a cut
 * through the middle then stand 0.4 radii apart, enough to see each cap from a three-quarter view.
 */
export const EXPLODE_SHARE = 0.2;

type Plane = [number, number, number, number];

export interface Explosion {
  /** The offset of each vertex slot (x, y, z): its part's; zero for a vertex of no part (isolated or deleted). */
  offsets: Float64Array;
  /** How far the parts that move are moved. */
  distance: number;
}

/**
 * The offsets that pull the parts of `mesh` apart: along the normal of `plane` (each part to the
 * side of it its centre is on), or without one away from the centre of the whole. Centres are
 * those of bounding boxes. Null when the mesh has fewer than two parts: nothing to pull apart.
 */
export function explodeOffsets(mesh: HalfedgeMesh, plane: Plane | null): Explosion | null {
  const sphere = boundingSphere(mesh);
  if (!sphere) return null;
  const roots = componentRoots(mesh);
  const p = mesh.positions;
  const isOfPart = (v: number) => !mesh.vDeleted[v] && mesh.vHalfedge[v] !== -1;
  // each part's bounding box, kept at its root (the part's lowest vertex)
  const low = new Float64Array(3 * mesh.vertexSlots).fill(Infinity);
  const high = new Float64Array(3 * mesh.vertexSlots).fill(-Infinity);
  const parts: number[] = [];
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (!isOfPart(v)) continue;
    const r = roots[v];
    if (r === v) parts.push(r);
    for (let k = 0; k < 3; k++) {
      const x = p[3 * v + k];
      if (!Number.isFinite(x)) continue;
      low[3 * r + k] = Math.min(low[3 * r + k], x);
      high[3 * r + k] = Math.max(high[3 * r + k], x);
    }
  }
  if (parts.length < 2) return null;

  const distance = EXPLODE_SHARE * sphere.radius;
  // a part whose centre is this close to the plane or to the centre of the whole has no way to go
  // (nor one with no finite coordinate, whose centre is not a number)
  const still = 1e-9 * sphere.radius;
  const unit = plane && unitPlane(plane);
  const shift = new Float64Array(3 * mesh.vertexSlots);
  for (const r of parts) {
    const centre = [0, 1, 2].map((k) => (low[3 * r + k] + high[3 * r + k]) / 2);
    let direction: number[];
    if (unit) {
      const side = unit.nx * centre[0] + unit.ny * centre[1] + unit.nz * centre[2] + unit.d;
      direction = !(Math.abs(side) > still) ? [0, 0, 0] : [unit.nx, unit.ny, unit.nz].map((n) => Math.sign(side) * n);
    } else {
      const away = centre.map((c, k) => c - sphere.center[k]);
      const length = Math.hypot(...away);
      direction = !(length > still) ? [0, 0, 0] : away.map((a) => a / length);
    }
    for (let k = 0; k < 3; k++) shift[3 * r + k] = distance * direction[k];
  }
  const offsets = new Float64Array(3 * mesh.vertexSlots);
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (!isOfPart(v)) continue;
    for (let k = 0; k < 3; k++) offsets[3 * v + k] = shift[3 * roots[v] + k];
  }
  return { offsets, distance };
}

/**
 * The mesh as the exploded view draws it: the same mesh (it is the prototype, so every array and
 * count read is the page's own, patched or not) with its own positions, moved by the offsets.
 */
export function explodedMesh(mesh: HalfedgeMesh, { offsets }: Explosion): HalfedgeMesh {
  const moved = mesh.positions.slice();
  for (let i = 0; i < offsets.length; i++) moved[i] += offsets[i];
  return Object.create(mesh, { positions: { value: moved } }) as HalfedgeMesh;
}

/** The render buffers with the positions moved by the offsets (a copy), and the bounds of the parts where they moved to (`exploded` is the mesh `explodedMesh` gave). */
export function explodedRender(render: RenderBuffers, { offsets }: Explosion, exploded: HalfedgeMesh): RenderBuffers {
  const positions = render.positions.slice();
  for (let i = 0; i < offsets.length; i++) positions[i] += offsets[i];
  return { ...render, positions, bounds: renderBounds(exploded) };
}

/** The plane of the cut that made the mesh on show, when it kept both sides (the entry of the history the view is at); else null. */
export function cutPlaneOnShow(history: { items: HistoryItem[]; index: number }): Plane | null {
  const source = history.items[history.index]?.source;
  if (source?.kind !== 'operation' || source.request.kind !== 'cut') return null;
  return (source.request.keep ?? 'both') === 'both' ? source.request.plane : null;
}
