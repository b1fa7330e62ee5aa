/**
 * Triangulating polygons by ear clipping: a face (any simple polygon, convex or not), or a
 * polygon with holes such as the cap of a plane cut.
 *
 * The polygon is laid flat first: its corners are projected onto a plane (a face's best-fit
 * plane, whose normal is the Newell vector area; the cutting plane for a cap), in coordinates
 * that keep counter-clockwise counter-clockwise, measured from one of the corners (so a model
 * far from the origin keeps its precision). Ear clipping (earcut) then cuts off one ear after
 * another.
 *
 * Corners that lie on a straight line need care. A corner in the middle of a straight side (made
 * by a plain edge split; the many of a cut through a voxel model) is either dropped by ear
 * clipping or left as the middle of a triangle of zero area, so such corners are left out of the
 * ear clipping; and where holes line up, earcut may run one triangle side along several ring
 * sides at once. Afterwards, each triangle side that is no ring side and has no triangle on its
 * other side is checked for corners lying on it, and its triangle is fanned from its third
 * corner over them:
 * ```
 *       z                          z
 *      ╱  ╲                      ╱ │ ╲
 *     ╱     ╲          ──►      ╱  │   ╲        the side x → y runs over w:
 *    x ── w ── y               x ── w ── y      the triangle becomes a fan from z over x, w, y
 * ```
 * Every ring side must end up in exactly one triangle, every diagonal in two (once each way),
 * and the triangles' areas must add up to the polygon's; when that fails (an outline that
 * crosses itself), the triangulation is refused.
 */
import earcut from 'earcut';
import { TopologyError } from '../errors.js';
import { faceVectorArea } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import { halfedgeFromTo, missingFace } from './find.js';
import { type EditOptions, type EditResult, PointerWriter } from '../change/writer.js';

/**
 * Two unit vectors `u`, `w` spanning the plane with normal `n`, with u × w along n: the
 * coordinates (p·u, p·w) show the plane as seen from the side `n` points to.
 */
export function planeBasis(nx: number, ny: number, nz: number): [u: number[], w: number[]] {
  const length = Math.hypot(nx, ny, nz);
  const n = [nx / length, ny / length, nz / length];
  // cross n with the axis it leans on least, for a well-conditioned u
  const ax = Math.abs(n[0]);
  const ay = Math.abs(n[1]);
  const az = Math.abs(n[2]);
  const axis = ax <= ay && ax <= az ? [1, 0, 0] : ay <= az ? [0, 1, 0] : [0, 0, 1];
  const u = normalize(cross(axis, n));
  return [u, cross(n, u)];
}

/**
 * Triangles covering a polygon given by its corners in 2D (`coords` = x0, y0, x1, y1, …): ring 0
 * from corner 0, hole rings from each of `holeStarts` (as in earcut). Rings run with the region
 * on their left (outer ring counter-clockwise, holes clockwise), and so do the triangles, as
 * corner-index triples. Corners at the same point count as one (an outline may touch itself, as
 * a cap does where the cut passes through a saddle): the triangles name the first corner at each
 * point. Every point is used. Returns null when the polygon cannot be triangulated (fewer than 3
 * corners, an outline that crosses itself).
 * @example triangulatePolygon([0, 0, 2, 0, 2, 2, 1, 1, 0, 2], []) // a non-convex pentagon: 3 triangles
 */
export function triangulatePolygon(coords: ArrayLike<number>, holeStarts: ArrayLike<number>): Uint32Array | null {
  const n = coords.length >> 1;
  if (n < 3) return null;
  const next = ringSuccessors(n, holeStarts);
  const prev = new Int32Array(n);
  for (let i = 0; i < n; i++) prev[next[i]] = i;
  const point = firstCornerAtEachPoint(coords);
  const cornersAtPoint = new Int32Array(n);
  for (let i = 0; i < n; i++) cornersAtPoint[point[i]]++;
  const straight = (i: number) => cornersAtPoint[point[i]] === 1 && isStraight(coords, prev[i], i, next[i]);

  // hand earcut only the corners that turn (and those where the outline touches itself): left
  // in, a corner on a straight side can end up as the middle of a triangle of zero area; left
  // out, it is fanned in below
  const kept: number[] = [];
  const keptHoleStarts: number[] = [];
  for (let r = 0; r <= holeStarts.length; r++) {
    if (r > 0) keptHoleStarts.push(kept.length);
    const start = r === 0 ? 0 : holeStarts[r - 1];
    const end = r < holeStarts.length ? holeStarts[r] : n;
    const first = kept.length;
    for (let i = start; i < end; i++) if (!straight(i)) kept.push(i);
    if (kept.length - first < 3) return null;
  }
  const keptCoords = new Float64Array(2 * kept.length);
  kept.forEach((i, k) => keptCoords.set([coords[2 * i], coords[2 * i + 1]], 2 * k));
  const raw = earcut(keptCoords, keptHoleStarts.length ? keptHoleStarts : null, 2).map((k) => point[kept[k]]);

  // earcut winds its triangles its own way: turn them to the rings' way
  let doubleArea = 0;
  for (let i = 0; i < raw.length; i += 3) doubleArea += cross2(coords, raw[i], raw[i + 1], raw[i + 2]);
  if (doubleArea < 0) {
    for (let i = 0; i < raw.length; i += 3) [raw[i + 1], raw[i + 2]] = [raw[i + 2], raw[i + 1]];
  }

  // the ring sides, between points, with how often each occurs
  const ringSides = new Map<number, number>();
  for (let i = 0; i < n; i++) {
    const key = point[i] * n + point[next[i]];
    ringSides.set(key, (ringSides.get(key) ?? 0) + 1);
  }
  const triangles = fanOverSkippedCorners(raw, coords, point, next, ringSides);
  return coversPolygon(triangles, coords, point, ringSides, next) ? Uint32Array.from(triangles) : null;
}

/** For each corner, the first corner at the same point (itself when it is the first). */
function firstCornerAtEachPoint(coords: ArrayLike<number>): Int32Array {
  const point = new Int32Array(coords.length >> 1);
  const first = new Map<string, number>();
  for (let i = 0; i < point.length; i++) {
    const key = `${coords[2 * i]},${coords[2 * i + 1]}`;
    const seen = first.get(key);
    if (seen === undefined) first.set(key, i);
    point[i] = seen ?? i;
  }
  return point;
}

/**
 * Repairs the triangles where a side runs over corners instead of through them (corners left
 * out as straight, dropped by earcut, or met where holes line up): a side that is no ring side
 * and has no triangle on its other side is checked for corners lying on it (those skipped along
 * the ring, else any on the segment), and its triangle is fanned from its third corner over
 * them. Repeats until nothing changes (each round fans every triangle at most once, so a
 * triangle with two such sides takes two rounds).
 */
function fanOverSkippedCorners(
  triangles: number[],
  coords: ArrayLike<number>,
  point: Int32Array,
  next: Int32Array,
  ringSides: Map<number, number>,
): number[] {
  const n = point.length;
  const used = new Uint8Array(n);
  for (const c of triangles) used[c] = 1;
  for (let round = 0; round < n; round++) {
    const sides = new Set<number>();
    for (let i = 0; i < triangles.length; i++) sides.add(triangles[i] * n + triangles[i % 3 === 2 ? i - 2 : i + 1]);
    const repaired: number[] = [];
    let changed = false;
    for (let i = 0; i < triangles.length; i += 3) {
      const corners = [triangles[i], triangles[i + 1], triangles[i + 2]];
      let fanned = false;
      for (let k = 0; k < 3 && !fanned; k++) {
        const x = corners[k];
        const y = corners[(k + 1) % 3];
        const z = corners[(k + 2) % 3];
        if (ringSides.has(x * n + y) || sides.has(y * n + x)) continue;
        const between = skippedAlongRing(point, next, used, x, y) ?? pointsOnSegment(coords, point, x, y);
        if (between.length === 0) continue;
        let p = x;
        for (const q of [...between, y]) {
          repaired.push(p, q, z);
          p = q;
        }
        fanned = changed = true;
      }
      if (!fanned) repaired.push(corners[0], corners[1], corners[2]);
    }
    triangles = repaired;
    if (!changed) break;
  }
  return triangles;
}

/**
 * The usual case, found in O(corners skipped): the points after x along its ring up to y, when
 * none of them is in a triangle (left out as straight, or dropped by earcut). Null otherwise.
 * The walk goes from point to point, and where corners share a point it follows the first one's
 * ring, which may lead round in a circle (a point whose next corner is at the same point leads
 * back to itself): after as many steps as there are corners, y is not ahead.
 */
function skippedAlongRing(point: Int32Array, next: Int32Array, used: Uint8Array, x: number, y: number): number[] | null {
  const skipped: number[] = [];
  let q = point[next[x]];
  while (q !== y && !used[q]) {
    if (skipped.length === point.length) return null;
    skipped.push(q);
    q = point[next[q]];
  }
  return q === y && skipped.length > 0 ? skipped : null;
}

/** The points (first corners) strictly inside the segment from corner x to corner y, in order from x. */
function pointsOnSegment(c: ArrayLike<number>, point: Int32Array, x: number, y: number): number[] {
  const dx = c[2 * y] - c[2 * x];
  const dy = c[2 * y + 1] - c[2 * x + 1];
  const length2 = dx * dx + dy * dy;
  const found: Array<[number, number]> = [];
  for (let v = 0; v < point.length; v++) {
    if (point[v] !== v) continue;
    const wx = c[2 * v] - c[2 * x];
    const wy = c[2 * v + 1] - c[2 * x + 1];
    const t = (wx * dx + wy * dy) / length2;
    if (t > 0 && t < 1 && Math.abs(wx * dy - wy * dx) <= 1e-10 * length2) found.push([t, v]);
  }
  return found.sort((a, b) => a[0] - b[0]).map(([, v]) => v);
}

/**
 * Each ring side in exactly one triangle, each diagonal in two (once each way), and the
 * triangles' areas adding up to the polygon's (nothing folded over or covered twice).
 */
function coversPolygon(
  triangles: number[],
  coords: ArrayLike<number>,
  point: Int32Array,
  ringSides: Map<number, number>,
  next: Int32Array,
): boolean {
  const n = point.length;
  const unused = new Map(ringSides);
  const diagonals = new Map<number, number>();
  for (let i = 0; i < triangles.length; i++) {
    const key = triangles[i] * n + triangles[i % 3 === 2 ? i - 2 : i + 1];
    const left = unused.get(key);
    if (left === 0) return false;
    if (left !== undefined) unused.set(key, left - 1);
    else diagonals.set(key, (diagonals.get(key) ?? 0) + 1);
  }
  for (const left of unused.values()) if (left !== 0) return false;
  for (const [key, count] of diagonals) {
    if (diagonals.get((key % n) * n + Math.floor(key / n)) !== count) return false;
  }
  // the triangles' area against the rings' (about corner 0), up to rounding, which grows with
  // the products summed, not with the area (a sliver has a tiny area made of long sides)
  let trianglesArea = 0;
  let polygonArea = 0;
  let rounding = 0;
  const area = (a: number, b: number, c: number) => {
    const p = (coords[2 * b] - coords[2 * a]) * (coords[2 * c + 1] - coords[2 * a + 1]);
    const q = (coords[2 * b + 1] - coords[2 * a + 1]) * (coords[2 * c] - coords[2 * a]);
    rounding += Math.abs(p) + Math.abs(q);
    return p - q;
  };
  for (let i = 0; i < triangles.length; i += 3) trianglesArea += Math.abs(area(triangles[i], triangles[i + 1], triangles[i + 2]));
  for (let i = 1; i < n; i++) polygonArea += area(0, i, next[i]);
  return Math.abs(trianglesArea - polygonArea) <= 1e-9 * rounding;
}

/** The corner after each corner along its ring. */
function ringSuccessors(n: number, holeStarts: ArrayLike<number>): Int32Array {
  const next = new Int32Array(n);
  for (let r = 0; r <= holeStarts.length; r++) {
    const start = r === 0 ? 0 : holeStarts[r - 1];
    const end = r < holeStarts.length ? holeStarts[r] : n;
    for (let i = start; i < end; i++) next[i] = i + 1 < end ? i + 1 : start;
  }
  return next;
}

/**
 * Fills rings of halfedges with triangles from `triangulatePolygon`: corner i is the origin of
 * `ring[i]`, and the ring side from corner i to the next is `ring[i]` itself. Sides are matched by
 * the vertices at their ends, so corners at one point must be one vertex. Makes the diagonals
 * and the faces (the first triangle keeps `face` when it is not -1, and the others copy its
 * attributes); returns the faces. Used by `triangulateFace` and by the plane cut's caps.
 */
export function fillRings(
  w: PointerWriter,
  ring: ArrayLike<number>,
  holeStarts: ArrayLike<number>,
  triangles: Uint32Array,
  face: number,
): Int32Array {
  const mesh = w.mesh;
  const n = ring.length;
  const next = ringSuccessors(n, holeStarts);
  const corner = Int32Array.from(ring, (h) => mesh.heVertex[h]);
  const nV = mesh.vertexSlots;
  const ringSides = new Map<number, number>();
  for (let i = 0; i < n; i++) ringSides.set(corner[i] * nV + corner[next[i]], ring[i]);
  const faces = new Int32Array(triangles.length / 3);
  for (let i = 0; i < faces.length; i++) {
    faces[i] = i === 0 && face !== -1 ? face : w.addFace();
    if (face !== -1 && i > 0) w.copy('face', faces[i], face);
  }
  // the halfedge from corner x to corner y: a ring side, or a diagonal made on first use
  const diagonals = new Map<number, number>();
  const halfedge = (x: number, y: number): number => {
    const side = ringSides.get(corner[x] * nV + corner[y]);
    if (side !== undefined) return side;
    const low = Math.min(corner[x], corner[y]);
    const high = Math.max(corner[x], corner[y]);
    let d = diagonals.get(low * nV + high);
    if (d === undefined) {
      d = 2 * w.addEdge(); // d runs low → high
      w.setOrigin(d, low);
      w.setOrigin(d + 1, high);
      w.copy('halfedge', d, ring[low === corner[x] ? x : y]);
      w.copy('halfedge', d + 1, ring[low === corner[x] ? y : x]);
      diagonals.set(low * nV + high, d);
    }
    return corner[x] === low ? d : d + 1;
  };
  for (let i = 0; i < faces.length; i++) {
    const a = triangles[3 * i];
    const b = triangles[3 * i + 1];
    const c = triangles[3 * i + 2];
    const sides = [halfedge(a, b), halfedge(b, c), halfedge(c, a)];
    for (let k = 0; k < 3; k++) {
      w.link(sides[k], sides[(k + 1) % 3]);
      w.setFace(sides[k], faces[i]);
    }
    w.setFaceHalfedge(faces[i], sides[0]);
  }
  return faces;
}

/**
 * The triangles of face `f` (as corner triples of its halfedge loop), or why there are none.
 */
function planFace(mesh: HalfedgeMesh, f: number): { ring: number[]; triangles: Uint32Array } | string {
  const missing = missingFace(mesh, f);
  if (missing) return missing;
  const { heNext, heVertex, positions: p } = mesh;
  const ring: number[] = [];
  let h = mesh.fHalfedge[f];
  do {
    ring.push(h);
    h = heNext[h];
  } while (h !== mesh.fHalfedge[f]);
  if (ring.length === 3) return { ring, triangles: Uint32Array.of(0, 1, 2) };
  // two corners at one point could not be told apart in the plane
  const corners = new Map<string, number>();
  for (const h of ring) {
    const v = heVertex[h];
    const key = `${p[3 * v]},${p[3 * v + 1]},${p[3 * v + 2]}`;
    const other = corners.get(key);
    if (other !== undefined) return `f${f} has two corners at the same point (v${other}, v${v}): ear clipping cannot tell them apart`;
    corners.set(key, v);
  }
  const [nx, ny, nz] = faceVectorArea(mesh, f);
  if (nx === 0 && ny === 0 && nz === 0) return `f${f} has zero area: it has no plane to be triangulated in`;
  const [u, v] = planeBasis(nx, ny, nz);
  const coords = new Float64Array(2 * ring.length);
  const o = 3 * heVertex[ring[0]];
  for (let i = 0; i < ring.length; i++) {
    const a = 3 * heVertex[ring[i]];
    const x = p[a] - p[o];
    const y = p[a + 1] - p[o + 1];
    const z = p[a + 2] - p[o + 2];
    coords[2 * i] = x * u[0] + y * u[1] + z * u[2];
    coords[2 * i + 1] = x * v[0] + y * v[1] + z * v[2];
  }
  // ear clipping starts its search at the first corner: from another start it may choose other
  // diagonals, which is the way round one that joins two corners already joined outside the face
  let clash = '';
  for (let first = 0; first < ring.length; first++) {
    const rotated = Float64Array.from({ length: coords.length }, (_, k) => coords[(k + 2 * first) % coords.length]);
    const triangles = triangulatePolygon(rotated, []);
    if (!triangles) return `f${f}'s outline, seen along its normal, crosses itself or has no area: ear clipping cannot triangulate it`;
    for (let k = 0; k < triangles.length; k++) triangles[k] = (triangles[k] + first) % ring.length;
    clash = existingDiagonal(mesh, ring, triangles);
    if (!clash) return { ring, triangles };
  }
  return `every triangulation of f${f} tried would join ${clash} a second time: a second edge between two vertices is not allowed`;
}

/** "v3 and v7 (already joined by e12)" for the first diagonal of `triangles` that is an edge already, or ''. */
function existingDiagonal(mesh: HalfedgeMesh, ring: number[], triangles: Uint32Array): string {
  const n = ring.length;
  for (let k = 0; k < triangles.length; k++) {
    const x = triangles[k];
    const y = triangles[k % 3 === 2 ? k - 2 : k + 1];
    if ((x + 1) % n === y || (y + 1) % n === x) continue; // a side of the face
    const u = mesh.heVertex[ring[x]];
    const v = mesh.heVertex[ring[y]];
    const existing = halfedgeFromTo(mesh, u, v);
    if (existing !== -1) return `v${u} and v${v} (already joined by e${existing >> 1})`;
  }
  return '';
}

/**
 * Why face `f` cannot be triangulated, or null when it can. A triangle can (it stays as it is);
 * refused: a face with two corners at the same point, a face of zero area, one whose outline
 * crosses itself seen along its normal, and one whose every triangulation tried (ear clipping
 * from each corner) has a diagonal joining two vertices that an edge outside the face already joins.
 */
export function canTriangulateFace(mesh: HalfedgeMesh, f: number): string | null {
  const plan = planFace(mesh, f);
  return typeof plan === 'string' ? plan : null;
}

/**
 * Cuts face `f` into triangles by ear clipping on its best-fit plane (non-convex faces
 * included); the first triangle keeps the id `f`, the others copy its attributes.
 * @example const { created } = triangulateFace(mesh, f); // a hexagon: 4 triangles, 3 new edges
 * @throws TopologyError with `canTriangulateFace`'s sentence when it does not apply.
 */
export function triangulateFace(mesh: HalfedgeMesh, f: number, options: EditOptions = {}): EditResult {
  const plan = planFace(mesh, f);
  if (typeof plan === 'string') throw new TopologyError(`triangulateFace: ${plan}`);
  const w = new PointerWriter(mesh, options);
  if (plan.ring.length > 3) fillRings(w, plan.ring, [], plan.triangles, f);
  return w.result();
}

export interface TriangulateMeshResult extends EditResult {
  /** Faces left as they were because they could not be triangulated (see `canTriangulateFace`). */
  skipped: Int32Array;
}

/**
 * Triangulates every face of more than three sides. A face that cannot be triangulated is left
 * as it is and listed in `skipped`. Pass `{ record: false }` on large meshes.
 * @example triangulateMesh(buildMesh(cube()).mesh); // 6 quads → 12 triangles
 */
export function triangulateMesh(mesh: HalfedgeMesh, options: EditOptions = {}): TriangulateMeshResult {
  const w = new PointerWriter(mesh, options);
  const skipped: number[] = [];
  const faceSlots = mesh.faceSlots; // the new triangles need no visit
  for (let f = 0; f < faceSlots; f++) {
    if (mesh.fDeleted[f] || mesh.faceDegree(f) === 3) continue;
    const plan = planFace(mesh, f);
    if (typeof plan === 'string') skipped.push(f);
    else fillRings(w, plan.ring, [], plan.triangles, f);
  }
  return { ...w.result(), skipped: Int32Array.from(skipped) };
}

function cross(a: number[], b: number[]): number[] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function normalize(v: number[]): number[] {
  const length = Math.hypot(v[0], v[1], v[2]);
  return [v[0] / length, v[1] / length, v[2] / length];
}

/**
 * True when corner `i` lies on the straight segment between its neighbours `p` and `q`: the sides
 * go on in the same direction, up to rounding (the sine of the turn below 1e-10; projecting 3D
 * points that are collinear onto a plane rarely keeps them exactly collinear).
 */
function isStraight(c: ArrayLike<number>, p: number, i: number, q: number): boolean {
  const ux = c[2 * i] - c[2 * p];
  const uy = c[2 * i + 1] - c[2 * p + 1];
  const vx = c[2 * q] - c[2 * i];
  const vy = c[2 * q + 1] - c[2 * i + 1];
  return Math.abs(ux * vy - uy * vx) <= 1e-10 * Math.hypot(ux, uy) * Math.hypot(vx, vy) && ux * vx + uy * vy > 0;
}

/** Twice the signed area of the 2D triangle (a, b, c). */
function cross2(p: ArrayLike<number>, a: number, b: number, c: number): number {
  return (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
}
