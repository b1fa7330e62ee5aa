/**
 * Triangles for drawing: each polygon face split into `degree − 2` triangles that remember their
 * face (so a click on a triangle selects the face). Triangles pass through; convex polygons become
 * fans; non-convex ones are ear-clipped in their own plane, so an L-shaped face draws as an L.
 * The mesh itself is not changed.
 */
import earcut from 'earcut';
import { faceVectorArea, type HalfedgeMesh } from '../core/index.js';
import type { RenderBuffers } from './protocol.js';

export function triangulateFaces(mesh: HalfedgeMesh): RenderBuffers {
  const { heNext, heVertex, fHalfedge, fDeleted, positions: p } = mesh;
  let count = 0;
  for (let f = 0; f < mesh.faceSlots; f++) if (!fDeleted[f]) count += mesh.faceDegree(f) - 2;
  const triangles = new Uint32Array(3 * count);
  const triangleFace = new Int32Array(count);
  const loop: number[] = [];
  const normal = [0, 0, 0];
  let t = 0;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    loop.length = 0;
    const start = fHalfedge[f];
    let h = start;
    do {
      loop.push(heVertex[h]);
      h = heNext[h];
    } while (h !== start);
    const corners = loop.length === 3 || isConvex(p, loop, faceVectorArea(mesh, f, normal)) ? fan(loop) : earClip(p, loop, normal);
    for (let i = 0; i < corners.length; i += 3) {
      triangles[3 * t] = corners[i];
      triangles[3 * t + 1] = corners[i + 1];
      triangles[3 * t + 2] = corners[i + 2];
      triangleFace[t++] = f;
    }
  }
  return { triangles, triangleFace };
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

/**
 * Ear clipping in the plane the face mostly lies in: drop the coordinate along which the normal is
 * largest (swapping the other two when that axis points backwards, to keep the loop's turning).
 */
function earClip(p: Float64Array, loop: number[], normal: number[]): number[] {
  const ax = Math.abs(normal[0]);
  const ay = Math.abs(normal[1]);
  const az = Math.abs(normal[2]);
  const drop = az >= ax && az >= ay ? 2 : ay >= ax ? 1 : 0;
  let [u, v] = [(drop + 1) % 3, (drop + 2) % 3];
  if (normal[drop] < 0) [u, v] = [v, u];
  const flat = new Float64Array(2 * loop.length);
  loop.forEach((vertex, i) => {
    flat[2 * i] = p[3 * vertex + u];
    flat[2 * i + 1] = p[3 * vertex + v];
  });
  const ears = earcut(flat);
  // earcut gives up on self-intersecting outlines; a fan still covers the face
  if (ears.length !== 3 * (loop.length - 2)) return fan(loop);
  return ears.map((i) => loop[i]);
}
