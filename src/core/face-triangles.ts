/**
 * Triangles of a face, for drawing it and for writing formats that hold only triangles: `degree − 2`
 * of them. A triangle passes through; convex polygons become fans; non-convex ones are ear-clipped
 * in their own plane, so an L-shaped face draws as an L. The mesh itself is not changed.
 */
import { planeBasis, triangulatePolygon } from './edits/triangulate.js';
import { faceVectorArea } from './geometry.js';
import type { HalfedgeMesh } from './mesh.js';

export function faceTriangles(mesh: HalfedgeMesh, f: number): Uint32Array {
  const loop = faceLoop(mesh, f);
  return Uint32Array.from(faceCornerTriangles(mesh, f, loop), (i) => loop[i]);
}

/**
 * The same triangles as positions in the face's loop of vertices (0 is the origin of
 * `fHalfedge[f]`, 1 that of the next halfedge, …), for a writer that keeps values per corner.
 */
export function faceCornerTriangles(mesh: HalfedgeMesh, f: number, loop = faceLoop(mesh, f)): number[] {
  const normal = [0, 0, 0];
  const corners = loop.map((_, i) => i);
  if (loop.length === 3 || isConvex(mesh.positions, loop, faceVectorArea(mesh, f, normal))) return fan(corners);
  return earClip(mesh.positions, loop, normal);
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

function fan(loop: number[]): number[] {
  const corners: number[] = [];
  for (let i = 1; i + 1 < loop.length; i++) corners.push(loop[0], loop[i], loop[i + 1]);
  return corners;
}

/** Every corner turns the same way as the face's normal. */
function isConvex(p: Float64Array, loop: number[], normal: number[]): boolean {
  const n = loop.length;
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
    if (turn < 0) return false;
  }
  return true;
}

/** Ear clipping in the face's best-fit plane (a face whose outline crosses itself gets a fan); positions in the loop. */
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
  const corners = triangulatePolygon(flat, []);
  return corners ? Array.from(corners) : fan(loop.map((_, i) => i));
}
