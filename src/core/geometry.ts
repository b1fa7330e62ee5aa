/**
 * Measures of the surface: normals, areas, volume, bounding box, triangle quality. Faces may be
 * any polygon, planar or not: areas and normals use Newell's method (the vector area, the sum of
 * the cross products of consecutive corners), which is exact for planar polygons and a sensible
 * average for warped ones.
 */
import type { HalfedgeMesh } from './mesh.js';

/** Half the sum of `p_i × p_(i+1)` around face `f`: its normal scaled by its area. */
export function faceVectorArea(mesh: HalfedgeMesh, f: number, out: number[] = [0, 0, 0]): number[] {
  const { heNext, heVertex, positions: p } = mesh;
  let nx = 0;
  let ny = 0;
  let nz = 0;
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    const a = 3 * heVertex[h];
    const b = 3 * heVertex[heNext[h]];
    nx += p[a + 1] * p[b + 2] - p[a + 2] * p[b + 1];
    ny += p[a + 2] * p[b] - p[a] * p[b + 2];
    nz += p[a] * p[b + 1] - p[a + 1] * p[b];
    h = heNext[h];
  } while (h !== start);
  out[0] = nx / 2;
  out[1] = ny / 2;
  out[2] = nz / 2;
  return out;
}

/** Scratch for the passes over every face below: a fresh array per face would cost as much as the pass. */
const scratch = [0, 0, 0];

export function faceArea(mesh: HalfedgeMesh, f: number): number {
  const [x, y, z] = faceVectorArea(mesh, f, scratch);
  // not Math.hypot, which costs ten times as much in a pass over every face; its guard against
  // overflow would matter only for coordinates beyond 1e150
  return Math.sqrt(x * x + y * y + z * z);
}

/** Unit normal of face `f` (zero for a face of zero area). */
export function faceNormal(mesh: HalfedgeMesh, f: number, out: number[] = [0, 0, 0]): number[] {
  faceVectorArea(mesh, f, out);
  return normalize(out);
}

/** Mean of the corners of face `f`. */
export function faceCentroid(mesh: HalfedgeMesh, f: number, out: number[] = [0, 0, 0]): number[] {
  const { heNext, heVertex, positions: p } = mesh;
  out[0] = out[1] = out[2] = 0;
  let n = 0;
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    const a = 3 * heVertex[h];
    out[0] += p[a];
    out[1] += p[a + 1];
    out[2] += p[a + 2];
    n++;
    h = heNext[h];
  } while (h !== start);
  out[0] /= n;
  out[1] /= n;
  out[2] /= n;
  return out;
}

/** Unit normals of every face slot (3 numbers each; zero for deleted faces). */
export function faceNormals(mesh: HalfedgeMesh): Float64Array {
  const normals = new Float64Array(3 * mesh.faceSlots);
  const n = [0, 0, 0];
  for (const f of mesh.faces()) {
    faceNormal(mesh, f, n);
    normals.set(n, 3 * f);
  }
  return normals;
}

/** Unit vertex normals: the area-weighted mean of the normals of the faces around each vertex. */
export function vertexNormals(mesh: HalfedgeMesh): Float64Array {
  const normals = new Float64Array(3 * mesh.vertexSlots);
  const { heNext, heVertex } = mesh;
  const n = [0, 0, 0];
  for (const f of mesh.faces()) {
    faceVectorArea(mesh, f, n);
    const start = mesh.fHalfedge[f];
    let h = start;
    do {
      const v = 3 * heVertex[h];
      normals[v] += n[0];
      normals[v + 1] += n[1];
      normals[v + 2] += n[2];
      h = heNext[h];
    } while (h !== start);
  }
  for (let i = 0; i < normals.length; i += 3) {
    const length = Math.hypot(normals[i], normals[i + 1], normals[i + 2]);
    if (length > 0) {
      normals[i] /= length;
      normals[i + 1] /= length;
      normals[i + 2] /= length;
    }
  }
  return normals;
}

export function surfaceArea(mesh: HalfedgeMesh): number {
  let area = 0;
  for (let f = 0; f < mesh.faceSlots; f++) if (!mesh.fDeleted[f]) area += faceArea(mesh, f);
  return area;
}

/**
 * Signed volume enclosed by the faces (divergence theorem over a fan of triangles per face).
 * Positive when the faces run counter-clockwise seen from outside. Meaningful for closed meshes.
 */
export function signedVolume(mesh: HalfedgeMesh): number {
  const { heNext, heVertex, positions: p } = mesh;
  let sixVolume = 0;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (mesh.fDeleted[f]) continue;
    const start = mesh.fHalfedge[f];
    const o = 3 * heVertex[start];
    let h = heNext[start];
    let a = 3 * heVertex[h];
    h = heNext[h];
    while (h !== start) {
      const b = 3 * heVertex[h];
      sixVolume +=
        p[o] * (p[a + 1] * p[b + 2] - p[a + 2] * p[b + 1]) +
        p[o + 1] * (p[a + 2] * p[b] - p[a] * p[b + 2]) +
        p[o + 2] * (p[a] * p[b + 1] - p[a + 1] * p[b]);
      a = b;
      h = heNext[h];
    }
  }
  return sixVolume / 6;
}

export interface BoundingBox {
  min: [number, number, number];
  max: [number, number, number];
}

/** Box around the live vertices with finite coordinates, or null when there are none. */
export function boundingBox(mesh: HalfedgeMesh): BoundingBox | null {
  const p = mesh.positions;
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  let any = false;
  // a loop over the slots, not the vertices() generator: the app runs this on every smoothing step
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (mesh.vDeleted[v]) continue;
    const x = p[3 * v];
    const y = p[3 * v + 1];
    const z = p[3 * v + 2];
    // each on its own: a sum of finite coordinates can overflow
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
    any = true;
    if (x < min[0]) min[0] = x;
    if (y < min[1]) min[1] = y;
    if (z < min[2]) min[2] = z;
    if (x > max[0]) max[0] = x;
    if (y > max[1]) max[1] = y;
    if (z > max[2]) max[2] = z;
  }
  return any ? { min, max } : null;
}

export interface BoundingSphere {
  center: [number, number, number];
  radius: number;
}

/**
 * Sphere around the live vertices with finite coordinates, or null when there are none: centred
 * in their bounding box (as three.js bounds a geometry), as large as the farthest vertex from there.
 */
export function boundingSphere(mesh: HalfedgeMesh, box = boundingBox(mesh)): BoundingSphere | null {
  if (!box) return null;
  const p = mesh.positions;
  const center: [number, number, number] = [(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2, (box.min[2] + box.max[2]) / 2];
  let farthest = 0;
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (mesh.vDeleted[v]) continue;
    const squared = (p[3 * v] - center[0]) ** 2 + (p[3 * v + 1] - center[1]) ** 2 + (p[3 * v + 2] - center[2]) ** 2;
    // a vertex with a coordinate that is not finite is left out, as from the box
    if (squared > farthest && Number.isFinite(squared)) farthest = squared;
  }
  return { center, radius: Math.sqrt(farthest) };
}

export interface TriangleQuality {
  /** Triangles measured. */
  count: number;
  /** Triangles of zero area (their ratio is infinite; left out of min, mean and max). */
  degenerate: number;
  /** Aspect ratio = longest edge / shortest altitude; 2/√3 ≈ 1.155 for an equilateral triangle. */
  min: number;
  mean: number;
  max: number;
}

/** Aspect ratios of the triangular faces, or null when there are none. */
export function triangleQuality(mesh: HalfedgeMesh): TriangleQuality | null {
  const { heNext, heVertex, positions: p } = mesh;
  let count = 0;
  let degenerate = 0;
  let min = Infinity;
  let max = 0;
  let sum = 0;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (mesh.fDeleted[f]) continue;
    const h0 = mesh.fHalfedge[f];
    const h1 = heNext[h0];
    const h2 = heNext[h1];
    if (heNext[h2] !== h0) continue;
    count++;
    const a = 3 * heVertex[h0];
    const b = 3 * heVertex[h1];
    const c = 3 * heVertex[h2];
    const longestSquared = Math.max(squaredDistance(p, a, b), squaredDistance(p, b, c), squaredDistance(p, c, a));
    const area = faceArea(mesh, f);
    // the shortest altitude falls on the longest edge: 2 · area / longest
    const ratio = longestSquared / (2 * area);
    if (!(area > 0) || !Number.isFinite(ratio)) {
      degenerate++;
      continue;
    }
    if (ratio < min) min = ratio;
    if (ratio > max) max = ratio;
    sum += ratio;
  }
  if (count === 0) return null;
  const measured = count - degenerate;
  return measured === 0
    ? { count, degenerate, min: NaN, mean: NaN, max: NaN }
    : { count, degenerate, min, mean: sum / measured, max };
}

/** |p_b − p_a|², for vertex offsets into the positions. */
function squaredDistance(p: Float64Array, a: number, b: number): number {
  const dx = p[b] - p[a];
  const dy = p[b + 1] - p[a + 1];
  const dz = p[b + 2] - p[a + 2];
  return dx * dx + dy * dy + dz * dz;
}

function normalize(v: number[]): number[] {
  const length = Math.hypot(v[0], v[1], v[2]);
  if (length > 0) {
    v[0] /= length;
    v[1] /= length;
    v[2] /= length;
  }
  return v;
}
