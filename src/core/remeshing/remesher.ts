/**
 * The four steps of an iteration of isotropic remeshing (Botsch & Kobbelt 2004, §4), each one pass
 * over the mesh: `index.ts` runs them as phases. L is the target edge length.
 *
 * 1. `splitLongEdges`: an edge longer than 4/3 L is split at its midpoint, the triangles beside it
 *    through the new vertex; passes repeat until no edge is that long.
 * 2. `collapseShortEdges`: an edge shorter than 4/5 L shrinks to a point, its midpoint, unless that
 *    would break the surface (`canCollapseEdge`), fold a triangle over (`keepsOrientation`), or
 *    make an edge longer than 4/3 L. That last check keeps the collapses from undoing the splits:
 *    the halves of an edge just over 4/3 L are just over 2/3 L, short enough to collapse, but
 *    collapsing one would bring the long edge back. Where the midpoint is too far from a
 *    neighbour, one end may not be, and the edge shrinks onto that end (as CGAL's remeshing
 *    always does): on the benchmark's torus that left a third as many edges under 0.6 L after the
 *    first iteration, and the shortest edge at the end went from 0.34 L to 0.45 L.
 * 3. `flipToValence`: an edge between two triangles is flipped when that brings its two ends and
 *    the two opposite corners nearer the valence of a regular mesh (6 inside, 4 on the boundary),
 *    summed over the four, where `canFlipEdge` allows it, neither new triangle is turned over, and
 *    the new edge is no longer than 4/3 L. That last check is ours, as the collapses': without it
 *    the flips made edges of up to 2.3 L, which the gentle smoothing left at 2 L after three
 *    iterations (with it the longest edge stays under 1.4 L, and 85% of the edges within
 *    4/5 … 4/3 L against 83%, on the benchmark's smaller icosphere and torus, 20k triangles and
 *    10k quads).
 * 4. `smoothAndProject`: every vertex moves a fifth of the way towards the centroid of its
 *    neighbours, but only in its tangent plane (the area-weighted normal's), all new places worked
 *    out from the old ones first; then each goes to the nearest point of the input surface
 *    (`NearestTriangle`, a grid over the input's triangles built once).
 *
 * The boundary keeps its shape exactly: a rim vertex never leaves the rim polyline of the input.
 *   - A rim *corner* (where the rim turns) never moves and is never collapsed away.
 *   - A rim vertex on a straight stretch (its two rim edges in line: one that a split put at a
 *     midpoint, or an input vertex in a straight row) slides along that stretch while smoothing,
 *     towards the midpoint of its two rim neighbours, and may be collapsed into a rim neighbour.
 *   - A boundary edge is split at its midpoint, which lies on the rim.
 *   - An interior edge with one end on the rim collapses onto that end; one with both ends on the
 *     rim never collapses (`canCollapseEdge`: it would pinch the surface).
 * So a closed mesh stays closed, and an open one keeps its boundary loops, its corners and its rim.
 *
 * Edits go through one `PointerWriter` per phase, which writes the phase's record when stepping
 * and nothing else run straight through (as decimation's), so a step then costs only its stores. Deleted elements stay in their slots until `index.ts` compacts the mesh at the end of
 * a run straight through.
 */
import { keepsOrientation } from '../decimation/collapses.js';
import { canCollapseEdge, collapseEdgeAt } from '../edits/collapse.js';
import { canFlipEdge, flipEdgeAt } from '../edits/flip.js';
import { splitEdgeTriangulatedAt } from '../edits/split-edge.js';
import type { PointerWriter } from '../change/writer.js';
import type { HalfedgeMesh } from '../mesh.js';
import { NearestTriangle } from './nearest-triangle.js';

/** How far a vertex moves towards its neighbours' centroid in one smoothing step. */
export const TANGENTIAL_STEP = 0.2;
/** Passes of splits at most: each splits in two every edge then too long, so 30 shorten an edge a billionfold. */
const MAX_SPLIT_PASSES = 30;
/** Passes of collapses at most (the later ones go over the edges around the last pass's collapses). */
const MAX_COLLAPSE_PASSES = 4;
/**
 * The first pass of collapses takes the short edges in this many classes of length, the shortest
 * first (CGAL takes them one by one, the shortest first): on the benchmark's torus the shortest
 * edge left went from 0.41 L to 0.46 L, and on the icosphere from 0.51 L to 0.52 L.
 */
const LENGTH_CLASSES = 4;
/**
 * A rim vertex is on a straight stretch when the sine of the turn between its two rim edges is
 * below this: a midpoint a split made turns by rounding errors only (about 1e-16).
 */
const STRAIGHT = 1e-9;

export class Remesher {
  readonly mesh: HalfedgeMesh;
  /** Squared lengths: an edge longer than 4/3 L is split, one shorter than 4/5 L collapsed. */
  private readonly longSquared: number;
  private readonly shortSquared: number;
  private readonly surface: NearestTriangle;
  /** Per vertex slot: the input triangle it was last nearest to (the projection's first guess), -1 if none. */
  private guess: Int32Array;
  /** Per vertex slot: its number of edges (the flips keep it up to date). */
  private valence: Int32Array;
  /** Per vertex slot: where smoothing puts it, three numbers each. */
  private targets: Float64Array;
  /** Per vertex slot: 1 inside, 2 on a straight stretch of the rim, 0 for the rest (rim corners, isolated, deleted). */
  private roles: Uint8Array;
  /** Scratch: where a collapse puts the merged vertex. */
  private readonly point = new Float64Array(3);
  /**
   * The mesh's positions, read once per step (and again after the splits make room): the mesh's
   * getter looks the attribute up by name, which took 6% of the run when asked at every edge.
   */
  private p: Float64Array;

  /**
   * Prepares the remeshing of `mesh` (a triangle mesh) to edges of `targetLength`: the grid over
   * its triangles as they are now (the surface every later step projects onto).
   */
  constructor(mesh: HalfedgeMesh, targetLength: number) {
    this.mesh = mesh;
    this.p = mesh.positions;
    this.longSquared = ((4 / 3) * targetLength) ** 2;
    this.shortSquared = ((4 / 5) * targetLength) ** 2;
    // cells about as wide as the input's edges hold a few triangles each
    this.surface = new NearestTriangle(mesh, meanEdgeLength(mesh) || targetLength);
    const slots = mesh.vertexSlots;
    this.guess = new Int32Array(slots).fill(-1);
    this.valence = new Int32Array(slots);
    this.targets = new Float64Array(3 * slots);
    this.roles = new Uint8Array(slots);
    // each vertex starts on a triangle of its own (triangle i is the i-th live face)
    const { heFace, vHalfedge, fDeleted } = mesh;
    const triangleOf = new Int32Array(mesh.faceSlots);
    for (let f = 0, t = 0; f < mesh.faceSlots; f++) if (!fDeleted[f]) triangleOf[f] = t++;
    for (let v = 0; v < slots; v++) {
      const h = vHalfedge[v];
      if (h < 0) continue;
      // a boundary vertex's halfedge has no face: its twin has
      const f = heFace[h] !== -1 ? heFace[h] : heFace[h ^ 1];
      this.guess[v] = triangleOf[f];
    }
  }

  /** Makes the per-vertex arrays hold `slots` vertices. */
  private reserveVertices(slots: number): void {
    if (this.guess.length >= slots) return;
    const room = Math.max(slots, Math.ceil(1.5 * this.guess.length));
    const guess = new Int32Array(room).fill(-1);
    guess.set(this.guess);
    this.guess = guess;
    this.valence = new Int32Array(room);
    this.targets = new Float64Array(3 * room);
    this.roles = new Uint8Array(room);
  }

  /** The squared distance between vertices u and v. */
  private distanceSquared(u: number, v: number): number {
    const p = this.p;
    const x = p[3 * u] - p[3 * v];
    const y = p[3 * u + 1] - p[3 * v + 1];
    const z = p[3 * u + 2] - p[3 * v + 2];
    return x * x + y * y + z * z;
  }

  /** The squared length of edge `e`. */
  private lengthSquared(e: number): number {
    const { heVertex } = this.mesh;
    const p = this.p;
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const x = p[a] - p[b];
    const y = p[a + 1] - p[b + 1];
    const z = p[a + 2] - p[b + 2];
    return x * x + y * y + z * z;
  }

  /**
   * Whether edge `e` is to be split: live, longer than 4/3 L, and not between two triangles with
   * the same third corner (a pillow), whose split would join the new vertex to that corner twice.
   */
  private splittable(e: number): boolean {
    const { heVertex, heFace, hePrev, eDeleted } = this.mesh;
    if (eDeleted[e] || this.lengthSquared(e) <= this.longSquared) return false;
    const h = 2 * e;
    return heFace[h] === -1 || heFace[h + 1] === -1 || heVertex[hePrev[h]] !== heVertex[hePrev[h + 1]];
  }

  /** Step 1: splits every edge longer than 4/3 L at its midpoint, pass after pass until none is left. */
  splitLongEdges(w: PointerWriter): void {
    const mesh = this.mesh;
    this.p = mesh.positions;
    for (let pass = 0; pass < MAX_SPLIT_PASSES; pass++) {
      // the edges of this pass (those its splits add wait for the next), and room for their splits
      const E = mesh.edgeSlots;
      let count = 0;
      for (let e = 0; e < E; e++) if (this.splittable(e)) count++;
      if (count === 0) return;
      // a split adds a vertex, three edges and two faces (inside; one face on the boundary)
      mesh.makeRoom({ vertices: mesh.vertexSlots + count, edges: E + 3 * count, faces: mesh.faceSlots + 2 * count });
      this.reserveVertices(mesh.vertexSlots + count);
      this.p = mesh.positions;
      const guess = this.guess;
      for (let e = 0; e < E; e++) {
        if (!this.splittable(e)) continue;
        const a = mesh.heVertex[2 * e];
        const m = splitEdgeTriangulatedAt(w, e, 0.5);
        // the new vertex is on the edge: the triangle its end was nearest to is a good first guess
        guess[m] = guess[a];
      }
    }
  }

  /**
   * Step 2: collapses every edge shorter than 4/5 L where that keeps the surface valid, folds no
   * triangle over and makes no edge longer than 4/3 L.
   *
   * The short edges are listed in one pass over the edges and collapsed the shortest first (in
   * `LENGTH_CLASSES`); a collapse can leave a short edge at the merged vertex, or let a refused
   * neighbour go, so the short edges around each survivor make the list of another pass, while
   * passes collapse anything.
   */
  collapseShortEdges(w: PointerWriter): void {
    const mesh = this.mesh;
    const { hePrev, vHalfedge, eDeleted } = mesh; // a collapse never grows the arrays
    this.p = mesh.positions;
    const E = mesh.edgeSlots;
    let list = new Int32Array(E);
    let next = new Int32Array(E);
    // which pass listed each edge last (1, 2, …; 0: none), so that a pass lists an edge once
    const listed = new Int32Array(E);
    let count = 0;
    for (let e = 0; e < E; e++) if (!eDeleted[e] && this.lengthSquared(e) < this.shortSquared) list[count++] = e;
    // the shortest first, in classes of length, each class in id order (a stable counting sort):
    // sorted by length alone, the collapses jumped about memory and took twice as long
    const classes = new Int32Array(LENGTH_CLASSES + 1);
    const classOf = (e: number) => Math.min(LENGTH_CLASSES - 1, Math.floor(Math.sqrt(this.lengthSquared(e) / this.shortSquared) * LENGTH_CLASSES));
    for (let i = 0; i < count; i++) classes[classOf(list[i]) + 1]++;
    for (let k = 0; k < LENGTH_CLASSES; k++) classes[k + 1] += classes[k];
    for (let i = 0; i < count; i++) next[classes[classOf(list[i])]++] = list[i];
    [list, next] = [next, list];
    for (let pass = 1; pass <= MAX_COLLAPSE_PASSES && count > 0; pass++) {
      let nextCount = 0;
      for (let i = 0; i < count; i++) {
        const e = list[i];
        if (eDeleted[e] || this.lengthSquared(e) >= this.shortSquared) continue;
        const a = this.tryCollapse(w, e);
        if (a < 0) continue;
        // the short edges around the survivor, for the next pass
        const start = vHalfedge[a];
        let h = start;
        do {
          const f = h >> 1;
          if (listed[f] !== pass && this.lengthSquared(f) < this.shortSquared) {
            listed[f] = pass;
            next[nextCount++] = f;
          }
          h = hePrev[h] ^ 1;
        } while (h !== start);
      }
      [list, next] = [next, list];
      count = nextCount;
    }
  }

  /** Collapses edge `e` if the rules above allow it; returns the vertex it kept, or -1. */
  private tryCollapse(w: PointerWriter, e: number): number {
    const mesh = this.mesh;
    const { heVertex, heFace, vHalfedge } = mesh;
    const { p, point } = this;
    const h = 2 * e;
    const a = heVertex[h]; // the collapse keeps a, at the point chosen here
    const b = heVertex[h + 1];
    const aOnRim = heFace[vHalfedge[a]] === -1;
    const bOnRim = heFace[vHalfedge[b]] === -1;
    // where the merged vertex goes: the end to keep in place (a or b), or the midpoint (-1)
    let keep = -1;
    // one end on the rim: onto that end, so the rim stays where it is
    if (aOnRim !== bOnRim) keep = aOnRim ? a : b;
    // both on the rim: only along it (inside it would pinch), dropping an end on a straight stretch
    else if (aOnRim) {
      if (heFace[h] !== -1 && heFace[h + 1] !== -1) return -1;
      if (this.onStraightRim(b)) keep = a;
      else if (this.onStraightRim(a)) keep = b;
      else return -1;
    }
    if (keep === -1) {
      for (let k = 0; k < 3; k++) point[k] = (p[3 * a + k] + p[3 * b + k]) / 2;
      // the midpoint too far from a neighbour: one end may be near enough to all of them
      if (!this.ringsWithin(a, b, point[0], point[1], point[2])) {
        if (this.ringsWithin(a, b, p[3 * a], p[3 * a + 1], p[3 * a + 2])) keep = a;
        else if (this.ringsWithin(a, b, p[3 * b], p[3 * b + 1], p[3 * b + 2])) keep = b;
        else return -1;
        for (let k = 0; k < 3; k++) point[k] = p[3 * keep + k];
      }
    } else {
      for (let k = 0; k < 3; k++) point[k] = p[3 * keep + k];
      if (!this.ringsWithin(a, b, point[0], point[1], point[2])) return -1;
    }
    if (canCollapseEdge(mesh, e) !== null || !keepsOrientation(mesh, e, point[0], point[1], point[2])) return -1;
    if (keep === b) this.guess[a] = this.guess[b];
    collapseEdgeAt(w, e, point);
    return a;
  }

  /** True when every neighbour of a and b (but themselves) is within 4/3 L of (x, y, z). */
  private ringsWithin(a: number, b: number, x: number, y: number, z: number): boolean {
    return this.ringWithin(a, a, b, x, y, z) && this.ringWithin(b, a, b, x, y, z);
  }

  /** True when every neighbour of v but a and b is within 4/3 L of (x, y, z). */
  private ringWithin(v: number, a: number, b: number, x: number, y: number, z: number): boolean {
    const { hePrev, heVertex, vHalfedge } = this.mesh;
    const p = this.p;
    const limit = this.longSquared;
    const start = vHalfedge[v];
    let h = start;
    do {
      const u = heVertex[h ^ 1];
      if (u !== a && u !== b) {
        const dx = p[3 * u] - x;
        const dy = p[3 * u + 1] - y;
        const dz = p[3 * u + 2] - z;
        if (dx * dx + dy * dy + dz * dz > limit) return false;
      }
      h = hePrev[h] ^ 1;
    } while (h !== start);
    return true;
  }

  /** True for a rim vertex whose two rim edges run on in one straight line. */
  private onStraightRim(v: number): boolean {
    const { hePrev, heVertex, vHalfedge } = this.mesh;
    const p = this.p;
    const h = vHalfedge[v]; // v's outgoing rim halfedge
    const o = 3 * v;
    const n = 3 * heVertex[h ^ 1]; // the next vertex along the rim
    const q = 3 * heVertex[hePrev[h]]; // the one before
    const ux = p[o] - p[q];
    const uy = p[o + 1] - p[q + 1];
    const uz = p[o + 2] - p[q + 2];
    const vx = p[n] - p[o];
    const vy = p[n + 1] - p[o + 1];
    const vz = p[n + 2] - p[o + 2];
    const dot = ux * vx + uy * vy + uz * vz;
    if (dot <= 0) return false;
    const cx = uy * vz - uz * vy;
    const cy = uz * vx - ux * vz;
    const cz = ux * vy - uy * vx;
    // |u × v|² ≤ sin²θ · |u|²|v|²
    return cx * cx + cy * cy + cz * cz <= STRAIGHT * STRAIGHT * (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
  }

  /**
   * Step 3: flips each edge whose flip brings the valences of its four vertices nearer 6 (4 on the
   * rim), summed, where `canFlipEdge` allows it and neither new triangle turns over.
   */
  flipToValence(w: PointerWriter): void {
    const mesh = this.mesh;
    const { heVertex, heFace, hePrev, vHalfedge, eDeleted } = mesh; // a flip never grows the arrays
    this.p = mesh.positions;
    const valence = this.valence;
    valence.fill(0, 0, mesh.vertexSlots);
    for (let e = 0; e < mesh.edgeSlots; e++) {
      if (eDeleted[e]) continue;
      valence[heVertex[2 * e]]++;
      valence[heVertex[2 * e + 1]]++;
    }
    const ideal = (v: number) => (heFace[vHalfedge[v]] === -1 ? 4 : 6);
    for (let e = 0; e < mesh.edgeSlots; e++) {
      const h = 2 * e;
      if (eDeleted[e] || heFace[h] === -1 || heFace[h + 1] === -1) continue;
      const a = heVertex[h];
      const b = heVertex[h + 1];
      const c = heVertex[hePrev[h]]; // the corner facing e in each triangle
      const d = heVertex[hePrev[h + 1]];
      const da = valence[a] - ideal(a);
      const db = valence[b] - ideal(b);
      const dc = valence[c] - ideal(c);
      const dd = valence[d] - ideal(d);
      // a and b lose an edge, c and d gain one
      const before = Math.abs(da) + Math.abs(db) + Math.abs(dc) + Math.abs(dd);
      const after = Math.abs(da - 1) + Math.abs(db - 1) + Math.abs(dc + 1) + Math.abs(dd + 1);
      if (after >= before) continue;
      // the new edge c–d longer than 4/3 L? The next split would undo the flip
      if (this.distanceSquared(c, d) > this.longSquared) continue;
      if (canFlipEdge(mesh, e) !== null || !this.flipKeepsFacing(a, b, c, d)) continue;
      flipEdgeAt(w, e);
      valence[a]--;
      valence[b]--;
      valence[c]++;
      valence[d]++;
    }
  }

  /**
   * True when the triangles (a, d, c) and (d, b, c) that flipping edge a–b makes both face the way
   * the pair (a, b, c), (b, a, d) faced: false where the quad a, d, b, c is not convex, and the
   * flip would fold the surface over.
   */
  private flipKeepsFacing(a: number, b: number, c: number, d: number): boolean {
    const p = this.p;
    const ax = p[3 * a];
    const ay = p[3 * a + 1];
    const az = p[3 * a + 2];
    const bx = p[3 * b];
    const by = p[3 * b + 1];
    const bz = p[3 * b + 2];
    const cx = p[3 * c];
    const cy = p[3 * c + 1];
    const cz = p[3 * c + 2];
    const dx = p[3 * d];
    const dy = p[3 * d + 1];
    const dz = p[3 * d + 2];
    // the pair's normal, weighted by area: (b − a) × (c − a) + (a − b) × (d − b)
    const n1x = (by - ay) * (cz - az) - (bz - az) * (cy - ay);
    const n1y = (bz - az) * (cx - ax) - (bx - ax) * (cz - az);
    const n1z = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    const n2x = (ay - by) * (dz - bz) - (az - bz) * (dy - by);
    const n2y = (az - bz) * (dx - bx) - (ax - bx) * (dz - bz);
    const n2z = (ax - bx) * (dy - by) - (ay - by) * (dx - bx);
    const nx = n1x + n2x;
    const ny = n1y + n2y;
    const nz = n1z + n2z;
    // (a, d, c): (d − a) × (c − a)
    const m1x = (dy - ay) * (cz - az) - (dz - az) * (cy - ay);
    const m1y = (dz - az) * (cx - ax) - (dx - ax) * (cz - az);
    const m1z = (dx - ax) * (cy - ay) - (dy - ay) * (cx - ax);
    // (d, b, c): (b − d) × (c − d)
    const m2x = (by - dy) * (cz - dz) - (bz - dz) * (cy - dy);
    const m2y = (bz - dz) * (cx - dx) - (bx - dx) * (cz - dz);
    const m2z = (bx - dx) * (cy - dy) - (by - dy) * (cx - dx);
    return m1x * nx + m1y * ny + m1z * nz > 0 && m2x * nx + m2y * ny + m2z * nz > 0;
  }

  /**
   * Step 4: tangential smoothing, then projection onto the input surface; `distances`, given, gets
   * how far each vertex went.
   */
  smoothAndProject(distances: Float32Array | null): void {
    const mesh = this.mesh;
    const V = mesh.vertexSlots;
    this.reserveVertices(V);
    const { heVertex, heFace, hePrev, vHalfedge, vDeleted } = mesh;
    const p = (this.p = mesh.positions);
    const { targets, roles, guess, surface } = this;
    let movable = 0;

    // compute every new place from the old ones
    for (let v = 0; v < V; v++) {
      roles[v] = 0;
      const start = vHalfedge[v];
      if (vDeleted[v] || start < 0) continue;
      const o = 3 * v;
      const px = p[o];
      const py = p[o + 1];
      const pz = p[o + 2];
      // on the rim: along a straight stretch towards the middle of its two rim neighbours; corners stay
      if (heFace[start] === -1) {
        if (!this.onStraightRim(v)) continue;
        const n = 3 * heVertex[start ^ 1];
        const q = 3 * heVertex[hePrev[start]];
        targets[o] = px + TANGENTIAL_STEP * ((p[n] + p[q]) / 2 - px);
        targets[o + 1] = py + TANGENTIAL_STEP * ((p[n + 1] + p[q + 1]) / 2 - py);
        targets[o + 2] = pz + TANGENTIAL_STEP * ((p[n + 2] + p[q + 2]) / 2 - pz);
        roles[v] = 2;
        movable++;
        continue;
      }
      // inside: the centroid of the neighbours and the area-weighted normal, in one walk around v
      let sx = 0;
      let sy = 0;
      let sz = 0;
      let nx = 0;
      let ny = 0;
      let nz = 0;
      let count = 0;
      let h = start;
      do {
        const u = 3 * heVertex[h ^ 1]; // the neighbour h leads to
        const t = 3 * heVertex[hePrev[h]]; // the next neighbour counter-clockwise, in h's triangle
        const ux = p[u] - px;
        const uy = p[u + 1] - py;
        const uz = p[u + 2] - pz;
        const tx = p[t] - px;
        const ty = p[t + 1] - py;
        const tz = p[t + 2] - pz;
        sx += ux;
        sy += uy;
        sz += uz;
        nx += uy * tz - uz * ty;
        ny += uz * tx - ux * tz;
        nz += ux * ty - uy * tx;
        count++;
        h = hePrev[h] ^ 1;
      } while (h !== start);
      // the step towards the centroid, less its part along the normal
      sx /= count;
      sy /= count;
      sz /= count;
      const length = Math.sqrt(nx * nx + ny * ny + nz * nz);
      if (length > 0) {
        const along = (sx * nx + sy * ny + sz * nz) / (length * length);
        sx -= along * nx;
        sy -= along * ny;
        sz -= along * nz;
      }
      targets[o] = px + TANGENTIAL_STEP * sx;
      targets[o + 1] = py + TANGENTIAL_STEP * sy;
      targets[o + 2] = pz + TANGENTIAL_STEP * sz;
      roles[v] = 1;
      movable++;
    }

    // move them all, and put the inside ones back on the input surface
    for (let v = 0; v < V; v++) {
      const role = roles[v];
      if (role === 0) continue;
      const o = 3 * v;
      let x = targets[o];
      let y = targets[o + 1];
      let z = targets[o + 2];
      if (role === 1 && surface.nearest(x, y, z, guess[v]) < Infinity) {
        x = surface.x;
        y = surface.y;
        z = surface.z;
        guess[v] = surface.triangle;
      }
      if (distances) distances[v] = Math.hypot(x - p[o], y - p[o + 1], z - p[o + 2]);
      p[o] = x;
      p[o + 1] = y;
      p[o + 2] = z;
    }
  }
}

/** The mean length of the live edges of `mesh` (0 when it has none). */
export function meanEdgeLength(mesh: HalfedgeMesh): number {
  const { heVertex, eDeleted } = mesh;
  const p = mesh.positions;
  let sum = 0;
  let count = 0;
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (eDeleted[e]) continue;
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    sum += Math.hypot(p[a] - p[b], p[a + 1] - p[b + 1], p[a + 2] - p[b + 2]);
    count++;
  }
  return count === 0 ? 0 : sum / count;
}
