/**
 * Poke face: a new vertex m at the centroid of a face of k corners, joined to each corner; the
 * face becomes a fan of k triangles (the first keeps the face's id).
 *
 * ```
 *      v3 ◄─────── v2            v3 ◄─────── v2
 *       │           ▲             │ ╲   2   ╱ ▲
 *       │           │             │   ╲   ╱   │
 *       │     f     │     ──►     │ 3   m   1 │       triangle i = (v_i, v_i+1, m)
 *       │           │             │   ╱   ╲   │
 *       ▼           │             ▼ ╱   0   ╲ │
 *      v0 ───────► v1            v0 ───────► v1
 * ```
 * Each spoke is an edge whose halfedge `2s` runs v_i → m and `2s + 1` runs m → v_i. m takes the
 * average of the corners' vertex attributes (positions included) and of their corner values.
 * On a non-convex face the centroid may lie outside it, and some triangles then fold over.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingFace } from './find.js';
import { type EditOptions, PointerWriter, type VertexEditResult } from '../change/writer.js';

/** Why face `f` cannot be poked, or null when it can (any live face can). */
export function canPokeFace(mesh: HalfedgeMesh, f: number): string | null {
  return missingFace(mesh, f);
}

/**
 * Replaces face `f` by a fan of triangles around a new vertex at its centroid.
 * @example const { vertex } = pokeFace(mesh, f);
 * @throws TopologyError with `canPokeFace`'s sentence when `f` is not a live face.
 */
export function pokeFace(mesh: HalfedgeMesh, f: number, options: EditOptions = {}): VertexEditResult {
  const why = canPokeFace(mesh, f);
  if (why) throw new TopologyError(`pokeFace: ${why}`);
  const w = new PointerWriter(mesh, options);
  const sides: number[] = [];
  let h = mesh.fHalfedge[f];
  do {
    sides.push(h);
    h = mesh.heNext[h];
  } while (h !== sides[0]);
  const k = sides.length;
  const corners = sides.map((g) => mesh.heVertex[g]);
  const weights = corners.map(() => 1 / k);

  const m = w.addVertex();
  w.blend('vertex', m, corners, weights);
  const spokes = sides.map(() => w.addEdge());
  const faces = sides.map((_, i) => (i === 0 ? f : w.addFace()));
  for (let i = 1; i < k; i++) w.copy('face', faces[i], f);
  for (let i = 0; i < k; i++) {
    const inward = 2 * spokes[i]; // v_i → m
    const outward = inward + 1; // m → v_i
    w.copy('halfedge', inward, sides[i]);
    if (i === 0) w.blend('halfedge', outward, sides, weights);
    else w.copy('halfedge', outward, 2 * spokes[0] + 1);
    w.setOrigin(inward, corners[i]);
    w.setOrigin(outward, m);
  }
  // triangle i: v_i → v_i+1 (the old side), v_i+1 → m, m → v_i
  for (let i = 0; i < k; i++) {
    const side = sides[i];
    const inward = 2 * spokes[(i + 1) % k];
    const outward = 2 * spokes[i] + 1;
    w.link(side, inward);
    w.link(inward, outward);
    w.link(outward, side);
    w.setFace(side, faces[i]);
    w.setFace(inward, faces[i]);
    w.setFace(outward, faces[i]);
    w.setFaceHalfedge(faces[i], side);
  }
  w.setVertexHalfedge(m, 2 * spokes[0] + 1);
  return { ...w.result(), vertex: m };
}
