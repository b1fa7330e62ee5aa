/**
 * Where each halfedge's arrow goes: inside its face, along the edge of a copy of the face shrunk
 * towards its centre, and shortened at both ends, so the two halfedges of an edge read as two
 * parallel, opposite arrows. A boundary halfedge has no face: its arrow sits just outside the surface, mirrored from
 * its twin's side. Pure arithmetic on the mesh arrays (no three.js), shared by drawing and picking.
 */
import type { HalfedgeMesh } from '../../core/index.js';

export interface ArrowPlacement {
  start: [number, number, number];
  end: [number, number, number];
  /** Unit normal of the plane the flat arrow lies in (the face's, or the twin's face's). */
  normal: [number, number, number];
  /** Width of the arrow head. */
  width: number;
  boundary: boolean;
}

/** Arrows run along the face shrunk towards its centre by this factor, so they stay inside it. */
const SHRINK = 0.74;
/** Fraction of the (shrunk) edge cut off at each end. */
const SHORTEN = 0.12;
/** Head width as a fraction of the edge's length, and at most of the gap to the edge. */
const HEAD_WIDTH = 0.1;
const HEAD_WIDTH_OF_GAP = 1.1;

export function newPlacement(): ArrowPlacement {
  return { start: [0, 0, 0], end: [0, 0, 0], normal: [0, 0, 1], width: 0, boundary: false };
}

/** Places the arrow of halfedge `h` into `out` (scaled by `scale`, e.g. thicker in presentation mode). */
export function placeArrow(mesh: HalfedgeMesh, h: number, out: ArrowPlacement, scale = 1): ArrowPlacement {
  const p = mesh.positions;
  const a = 3 * mesh.origin(h);
  const b = 3 * mesh.target(h);
  const boundary = mesh.face(h) === -1;
  // the face whose centre the arrow leans towards (or, for a boundary halfedge, away from)
  const [cx, cy, cz, nx, ny, nz] = centreAndNormal(mesh, boundary ? mesh.twin(h) : h);
  // each end moves towards the centre (a shrunk copy of the face), or as far away for a boundary
  const k = boundary ? 2 - SHRINK : SHRINK;
  const ax = cx + k * (p[a] - cx);
  const ay = cy + k * (p[a + 1] - cy);
  const az = cz + k * (p[a + 2] - cz);
  const ex = cx + k * (p[b] - cx) - ax;
  const ey = cy + k * (p[b + 1] - cy) - ay;
  const ez = cz + k * (p[b + 2] - cz) - az;
  out.start[0] = ax + SHORTEN * ex;
  out.start[1] = ay + SHORTEN * ey;
  out.start[2] = az + SHORTEN * ez;
  out.end[0] = ax + (1 - SHORTEN) * ex;
  out.end[1] = ay + (1 - SHORTEN) * ey;
  out.end[2] = az + (1 - SHORTEN) * ez;
  out.normal[0] = nx;
  out.normal[1] = ny;
  out.normal[2] = nz;
  // the gap between the edge and its arrow: (1 − SHRINK) of the distance from the edge to the centre
  const mx = (p[a] + p[b]) / 2 - cx;
  const my = (p[a + 1] + p[b + 1]) / 2 - cy;
  const mz = (p[a + 2] + p[b + 2]) / 2 - cz;
  const gap = (1 - SHRINK) * Math.hypot(mx, my, mz);
  out.width = Math.min(HEAD_WIDTH * Math.hypot(ex, ey, ez) / SHRINK, HEAD_WIDTH_OF_GAP * gap) * scale;
  out.boundary = boundary;
  return out;
}

/** Centre and unit normal of the face on the left of `h` (h must not be a boundary halfedge). */
function centreAndNormal(mesh: HalfedgeMesh, h: number): [number, number, number, number, number, number] {
  const p = mesh.positions;
  let cx = 0;
  let cy = 0;
  let cz = 0;
  let nx = 0;
  let ny = 0;
  let nz = 0;
  let n = 0;
  let g = h;
  do {
    const a = 3 * mesh.origin(g);
    const b = 3 * mesh.target(g);
    cx += p[a];
    cy += p[a + 1];
    cz += p[a + 2];
    nx += p[a + 1] * p[b + 2] - p[a + 2] * p[b + 1];
    ny += p[a + 2] * p[b] - p[a] * p[b + 2];
    nz += p[a] * p[b + 1] - p[a + 1] * p[b];
    n++;
    g = mesh.next(g);
  } while (g !== h && n <= mesh.halfedgeSlots);
  const length = Math.hypot(nx, ny, nz) || 1;
  return [cx / n, cy / n, cz / n, nx / length, ny / length, nz / length];
}
