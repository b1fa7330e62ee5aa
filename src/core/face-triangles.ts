/**
 * Triangles of a face, for drawing it and for writing formats that hold only triangles: `degree − 2`
 * of them. A triangle passes through; a quad splits along the diagonal inside it; other convex
 * polygons become fans; non-convex ones are ear-clipped in their own plane, so an L-shaped face
 * draws as an L. The mesh itself is not changed. One function (`writeFaceTriangles`) decides for
 * the drawing, its patches and the files alike.
 */
import earcut from 'earcut';
import { planeBasis } from './edits/triangulate.js';
import { faceVectorArea } from './geometry.js';
import type { HalfedgeMesh } from './mesh.js';

/** A face's loop of vertices, kept between calls of `writeFaceTriangles` (grown when a face needs more). */
let scratch = new Int32Array(64);
const scratchNormal = [0, 0, 0];

/**
 * Writes the triangles of face `f` as corner vertex ids into `out` from triangle `at` on and
 * returns how many: what `faceTriangles` gives, without a list per face for a convex one (a
 * million faces laid out for drawing).
 */
export function writeFaceTriangles(mesh: HalfedgeMesh, f: number, out: Uint32Array, at: number): number {
  const { heNext, heVertex, fHalfedge } = mesh;
  const start = fHalfedge[f];
  let n = 0;
  let h = start;
  do {
    if (n === scratch.length) {
      const larger = new Int32Array(2 * n);
      larger.set(scratch);
      scratch = larger;
    }
    scratch[n++] = heVertex[h];
    h = heNext[h];
  } while (h !== start && n <= mesh.halfedgeSlots);
  if (n === 4) return writeQuad(mesh.positions, out, at);
  if (n === 3 || isConvex(mesh.positions, scratch, n, faceVectorArea(mesh, f, scratchNormal))) {
    for (let i = 1; i + 1 < n; i++) {
      const o = 3 * (at + i - 1);
      out[o] = scratch[0];
      out[o + 1] = scratch[i];
      out[o + 2] = scratch[i + 1];
    }
    return n - 2;
  }
  if (n <= SMALL && clipSmall(mesh.positions, n, scratchNormal, out, at)) return n - 2;
  const loop = Array.from(scratch.subarray(0, n));
  const corners = earClip(mesh.positions, loop, scratchNormal);
  for (let k = 0; k < corners.length; k++) out[3 * at + k] = loop[corners[k]];
  return corners.length / 3;
}

/**
 * The two triangles of the quad in `scratch`: split along the diagonal 0–2 when the two halves
 * face the same way (a convex quad, or one bent along that diagonal), else along 1–3 (the
 * diagonal inside a quad with a reflex corner). What ear clipping gives, without the plane.
 */
function writeQuad(p: Float64Array, out: Uint32Array, at: number): number {
  const first = quadSplitCorner(p, scratch[0], scratch[1], scratch[2], scratch[3]);
  const o = 3 * at;
  for (let t = 0; t < 2; t++) {
    out[o + 3 * t] = scratch[first];
    out[o + 3 * t + 1] = scratch[(first + 1 + t) % 4];
    out[o + 3 * t + 2] = scratch[(first + 2 + t) % 4];
  }
  return 2;
}

/**
 * The corner a quad's diagonal starts from, 0 (the diagonal 0–2) or 1 (1–3), for the quad of
 * vertices `v0 … v3` in order, with positions `p` (see `writeQuad`).
 */
export function quadSplitCorner(p: ArrayLike<number>, v0: number, v1: number, v2: number, v3: number): 0 | 1 {
  const a = 3 * v0;
  const b = 3 * v1;
  const c = 3 * v2;
  const d = 3 * v3;
  // (b − a) × (c − a) against (c − a) × (d − a): the normals of the halves either side of 0–2
  const ux = p[b] - p[a];
  const uy = p[b + 1] - p[a + 1];
  const uz = p[b + 2] - p[a + 2];
  const vx = p[c] - p[a];
  const vy = p[c + 1] - p[a + 1];
  const vz = p[c + 2] - p[a + 2];
  const wx = p[d] - p[a];
  const wy = p[d + 1] - p[a + 1];
  const wz = p[d + 2] - p[a + 2];
  const mx = uy * vz - uz * vy;
  const my = uz * vx - ux * vz;
  const mz = ux * vy - uy * vx;
  const nx = vy * wz - vz * wy;
  const ny = vz * wx - vx * wz;
  const nz = vx * wy - vy * wx;
  return mx * nx + my * ny + mz * nz >= 0 ? 0 : 1;
}

export function faceTriangles(mesh: HalfedgeMesh, f: number): Uint32Array {
  const out = new Uint32Array(3 * Math.max(0, mesh.faceDegree(f) - 2));
  writeFaceTriangles(mesh, f, out, 0);
  return out;
}

/**
 * The same triangles as positions in the face's loop of vertices (0 is the origin of
 * `fHalfedge[f]`, 1 that of the next halfedge, …), for a writer that keeps values per corner.
 */
export function faceCornerTriangles(mesh: HalfedgeMesh, f: number, loop = faceLoop(mesh, f)): number[] {
  // a valid face passes through each of its vertices once: a vertex names its corner
  return Array.from(faceTriangles(mesh, f), (vertex) => loop.indexOf(vertex));
}
/** The face's vertices from its `fHalfedge` along `next` (a bounded walk). */
function faceLoop(mesh: HalfedgeMesh, f: number): number[] {
  const { heNext, heVertex, fHalfedge } = mesh;
  const loop: number[] = [];
  const start = fHalfedge[f];
  let h = start;
  do {
    loop.push(heVertex[h]);
    h = heNext[h];
  } while (h !== start && loop.length <= mesh.halfedgeSlots);
  return loop;
}

/** The square of the sine of the largest turn backwards that counts as going straight on. */
const STRAIGHT = 1e-20;

function fan(loop: number[]): number[] {
  const corners: number[] = [];
  for (let i = 1; i + 1 < loop.length; i++) corners.push(loop[0], loop[i], loop[i + 1]);
  return corners;
}

/**
 * Every corner turns the same way as the face's normal, or goes straight on: a corner on a
 * straight side (a triangle whose sides a subdivision step has split is a hexagon of three such
 * corners) turns by nothing but rounding, and must not send the face to ear clipping.
 */
function isConvex(p: Float64Array, loop: ArrayLike<number>, n: number, normal: number[]): boolean {
  const normalSquared = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
  for (let i = 0; i < n; i++) {
    const a = 3 * loop[i];
    const b = 3 * loop[(i + 1) % n];
    const c = 3 * loop[(i + 2) % n];
    const ux = p[b] - p[a];
    const uy = p[b + 1] - p[a + 1];
    const uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[b];
    const vy = p[c + 1] - p[b + 1];
    const vz = p[c + 2] - p[b + 2];
    const turn = (uy * vz - uz * vy) * normal[0] + (uz * vx - ux * vz) * normal[1] + (ux * vy - uy * vx) * normal[2];
    // a turn backwards by more than rounding: |turn| against |u| |v| |normal|, squared
    if (turn < 0 && turn * turn > STRAIGHT * (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz) * normalSquared) return false;
  }
  return true;
}

/** Faces of up to this many corners that are not convex are ear-clipped by `clipSmall`. */
const SMALL = 8;
/** The corners `clipSmall` has yet to cut off, as positions in `scratch`. */
const ring = new Int32Array(SMALL);

/**
 * Ear clipping of the small face in `scratch` around its normal, in 3D: cuts off a corner that
 * turns with the normal and whose triangle holds no other corner left (seen along the normal),
 * until three are left; the triangles wound as the face is. What earcut does, without projecting
 * the face or allocating: a Catmull-Clark step leaves a million hexagons whose edge points turn
 * back a little. False when no corner is an ear (an outline that crosses itself, or one whose
 * corners left all go straight on): `earClip` then decides.
 */
function clipSmall(p: Float64Array, n: number, normal: number[], out: Uint32Array, at: number): boolean {
  for (let i = 0; i < n; i++) ring[i] = scratch[i];
  let left = n;
  let t = at;
  while (left > 3) {
    let ear = -1;
    for (let i = 0; i < left && ear < 0; i++) {
      const a = ring[(i + left - 1) % left];
      const b = ring[i];
      const c = ring[(i + 1) % left];
      if (turn(p, a, b, b, c, normal) <= 0) continue;
      let empty = true;
      for (let k = 0; k < left && empty; k++) {
        const q = ring[k];
        if (q === a || q === b || q === c) continue;
        // q inside or on the triangle: to the left of (or on) all three of its sides
        empty = !(turn(p, a, b, a, q, normal) >= 0 && turn(p, b, c, b, q, normal) >= 0 && turn(p, c, a, c, q, normal) >= 0);
      }
      if (empty) ear = i;
    }
    if (ear < 0) return false;
    out[3 * t] = ring[(ear + left - 1) % left];
    out[3 * t + 1] = ring[ear];
    out[3 * t + 2] = ring[(ear + 1) % left];
    t++;
    ring.copyWithin(ear, ear + 1, left);
    left--;
  }
  out[3 * t] = ring[0];
  out[3 * t + 1] = ring[1];
  out[3 * t + 2] = ring[2];
  return true;
}

/** (b − a) × (d − c) along the normal: positive when going from a to b, c to d turns left around it. */
function turn(p: Float64Array, a: number, b: number, c: number, d: number, normal: number[]): number {
  const ux = p[3 * b] - p[3 * a];
  const uy = p[3 * b + 1] - p[3 * a + 1];
  const uz = p[3 * b + 2] - p[3 * a + 2];
  const vx = p[3 * d] - p[3 * c];
  const vy = p[3 * d + 1] - p[3 * c + 1];
  const vz = p[3 * d + 2] - p[3 * c + 2];
  return (uy * vz - uz * vy) * normal[0] + (uz * vx - ux * vz) * normal[1] + (ux * vy - uy * vx) * normal[2];
}

/**
 * Ear clipping in the face's best-fit plane (earcut; a face whose outline crosses itself gets a
 * fan); positions in the loop, wound as the face is. A face is a simple ring without holes, so
 * the general polygon triangulation of the edits (`triangulatePolygon`, which sorts out repeated
 * points and rings) would cost several times as much for the same triangles: a subdivision step
 * shows a million such faces.
 */
function earClip(p: Float64Array, loop: number[], normal: number[]): number[] {
  const [u, w] = planeBasis(normal[0], normal[1], normal[2]);
  const flat = new Float64Array(2 * loop.length);
  loop.forEach((vertex, i) => {
    const x = p[3 * vertex];
    const y = p[3 * vertex + 1];
    const z = p[3 * vertex + 2];
    flat[2 * i] = x * u[0] + y * u[1] + z * u[2];
    flat[2 * i + 1] = x * w[0] + y * w[1] + z * w[2];
  });
  const corners = earcut(flat, null, 2);
  if (corners.length !== 3 * (loop.length - 2)) return fan(loop.map((_, i) => i));
  // earcut winds its triangles its own way: turn them to the outline's
  let outline = 0;
  for (let i = 0, j = loop.length - 1; i < loop.length; j = i++) outline += flat[2 * j] * flat[2 * i + 1] - flat[2 * i] * flat[2 * j + 1];
  let triangles = 0;
  for (let t = 0; t < corners.length; t += 3) {
    const [a, b, c] = [corners[t], corners[t + 1], corners[t + 2]];
    triangles += (flat[2 * b] - flat[2 * a]) * (flat[2 * c + 1] - flat[2 * a + 1]) - (flat[2 * c] - flat[2 * a]) * (flat[2 * b + 1] - flat[2 * a + 1]);
  }
  if (outline * triangles < 0) for (let t = 0; t < corners.length; t += 3) [corners[t + 1], corners[t + 2]] = [corners[t + 2], corners[t + 1]];
  return corners;
}
