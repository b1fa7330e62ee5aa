/**
 * Phase 6 of the plane cut: close each side's cut with flat caps.
 *
 * After the separation, the cut edges of a side form closed loops of boundary halfedges. A loop
 * runs with its hole on the left, which is the way a cap face filling it must run, so the loops
 * are the caps' outlines as they are. Seen from outside the cap (from below for the side above
 * the plane, from above for the side below), an outer loop turns counter-clockwise and the loop
 * of a cavity inside turns clockwise:
 *
 * ```
 *     ┌──────────────┐     cutting a hollow ball: the outer sphere gives the outer loop,
 *     │   ┌──────┐   │     the inner sphere (facing inwards) a clockwise loop inside it,
 *     │   │ hole │   │     and the cap is the ring between them
 *     │   └──────┘   │
 *     └──────────────┘
 * ```
 * So each clockwise loop becomes a hole of the smallest counter-clockwise loop around it (tested
 * geometrically, in the plane), and each outer loop with its holes is triangulated by ear
 * clipping and filled. A loop that also runs along the mesh's own boundary (an open input) is not
 * the outline of a cap and stays open, as does a clockwise loop inside no other. An outline that
 * crosses itself (it happens when faces lie within the tolerance of the plane, so the cut through
 * them is decided by rounding) cannot be ear-clipped: without holes, it is closed by a fan from
 * one corner, which may fold over but keeps the mesh closed and its volume right.
 *
 * A cap's diagonal may join two vertices that an edge of the mesh already joins (on a coarse mesh,
 * two corners of the cut are often neighbours round the other way): it gets a vertex halfway,
 * joined to the third corners of its two triangles, since no file can hold two edges between the
 * same two vertices.
 */
import { splitEdgeTriangulatedAt } from '../edits/split-edge.js';
import { fillRings, planeBasis, triangulatePolygon } from '../edits/triangulate.js';
import type { PointerWriter } from '../change/writer.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { UnitPlane } from './plane.js';

export interface Caps {
  /** The cap faces made. */
  faces: number[];
  /** How many caps (outer loops with their holes) were made. */
  caps: number;
  /** How many of them are fans, closing an outline that crosses itself. */
  fanned: number;
  /** One boundary halfedge of each loop of cut edges left open, and why. */
  open: Array<{ halfedge: number; reason: string }>;
}

/**
 * Caps the loops formed by the boundary halfedges of `cutEdges` on the sides listed in `sides`
 * (+1 above, −1 below). `faceSide` gives the side of each face.
 */
export function capLoops(
  w: PointerWriter,
  cutEdges: ArrayLike<number>,
  faceSide: Int8Array,
  plane: UnitPlane,
  sides: number[],
): Caps {
  const mesh = w.mesh;
  const { heNext, heFace, eDeleted } = mesh;
  const onCut = new Uint8Array(mesh.edgeSlots);
  for (let i = 0; i < cutEdges.length; i++) onCut[cutEdges[i]] = 1;
  const result: Caps = { faces: [], caps: 0, fanned: 0, open: [] };

  // the loops, by side
  const loops = new Map<number, number[][]>(sides.map((s) => [s, []]));
  const seen = new Uint8Array(mesh.halfedgeSlots);
  for (let i = 0; i < cutEdges.length; i++) {
    const e = cutEdges[i];
    if (eDeleted[e]) continue;
    for (let b = 2 * e; b < 2 * e + 2; b++) {
      if (heFace[b] !== -1 || seen[b]) continue;
      const loop: number[] = [];
      let pure = true;
      let h = b;
      do {
        seen[h] = 1;
        loop.push(h);
        pure &&= onCut[h >> 1] === 1;
        h = heNext[h];
      } while (h !== b);
      const side = faceSide[heFace[b ^ 1]];
      if (!pure) result.open.push({ halfedge: b, reason: 'it runs along the boundary the mesh already had' });
      else loops.get(side)?.push(loop);
    }
  }

  for (const [side, sideLoops] of loops) {
    if (sideLoops.length) capSide(w, sideLoops, side, plane, result);
  }
  splitDoubledDiagonals(w, result.faces);
  return result;
}

/**
 * Splits each cap diagonal that joins two vertices another edge already joins, at its middle,
 * joining the new vertex to the third corners of the cap triangles beside it (edges no other
 * edge doubles: the vertex is new). Adds the new faces to `faces`. Each split removes one doubled
 * edge, so a face is looked at again at most once per side.
 */
function splitDoubledDiagonals(w: PointerWriter, faces: number[]): void {
  const mesh = w.mesh;
  const capFaces = new Set(faces);
  for (let i = 0; i < faces.length; i++) {
    for (let side = 0; side < 3; side++) {
      const doubled = doubledDiagonal(mesh, faces[i], capFaces);
      if (doubled === -1) break;
      const before = mesh.faceSlots;
      splitEdgeTriangulatedAt(w, doubled >> 1, 0.5);
      for (let f = before; f < mesh.faceSlots; f++) {
        faces.push(f);
        capFaces.add(f);
      }
    }
  }
}

/** A halfedge of face `f` between two cap faces whose two ends another edge joins too, or -1. */
function doubledDiagonal(mesh: HalfedgeMesh, f: number, capFaces: Set<number>): number {
  const { heNext, hePrev, heVertex, heFace } = mesh;
  let h = mesh.fHalfedge[f];
  for (let k = 0; k < 3; k++, h = heNext[h]) {
    if (!capFaces.has(heFace[h ^ 1])) continue;
    const target = heVertex[h ^ 1];
    // rotate round the origin: another halfedge to the same target is a second edge
    for (let g = hePrev[h] ^ 1, steps = 0; g !== h && steps < mesh.halfedgeSlots; g = hePrev[g] ^ 1, steps++) {
      if (heVertex[g ^ 1] === target) return h;
    }
  }
  return -1;
}

/** Caps one side's loops: outer loops with the holes inside them, each triangulated and filled. */
function capSide(w: PointerWriter, loops: number[][], side: number, plane: UnitPlane, result: Caps): void {
  const { heVertex, positions: p } = w.mesh;
  // seen from outside the cap: from below (−n) for the side above, from above (+n) for below
  const [u, v] = planeBasis(plane.nx, plane.ny, plane.nz);
  const flip = side > 0 ? -1 : 1;
  const o = 3 * heVertex[loops[0][0]]; // coordinates from a corner, for precision far from the origin
  const flat = loops.map((loop) => {
    const coords = new Float64Array(2 * loop.length);
    for (let i = 0; i < loop.length; i++) {
      const a = 3 * heVertex[loop[i]];
      const x = p[a] - p[o];
      const y = p[a + 1] - p[o + 1];
      const z = p[a + 2] - p[o + 2];
      coords[2 * i] = x * u[0] + y * u[1] + z * u[2];
      coords[2 * i + 1] = flip * (x * v[0] + y * v[1] + z * v[2]);
    }
    return coords;
  });
  const areas = flat.map(signedArea);
  const outers = loops.map((_, i) => i).filter((i) => areas[i] > 0);
  const holesOf = new Map<number, number[]>(outers.map((i) => [i, []]));
  for (let i = 0; i < loops.length; i++) {
    if (areas[i] > 0) continue;
    // the smallest outer loop around this one, tested at the middle of its first side (its
    // corners may touch the outer loop, where the cut passes through a vertex)
    const [x, y] = [(flat[i][0] + flat[i][2]) / 2, (flat[i][1] + flat[i][3]) / 2];
    let around = -1;
    for (const o of outers) {
      if (contains(flat[o], x, y) && (around === -1 || areas[o] < areas[around])) around = o;
    }
    if (around === -1) result.open.push({ halfedge: loops[i][0], reason: 'it turns clockwise but lies inside no other loop' });
    else holesOf.get(around)!.push(i);
  }

  for (const [o, holes] of holesOf) {
    const rings = [o, ...holes];
    const coords = new Float64Array(rings.reduce((n, r) => n + flat[r].length, 0));
    const ring: number[] = [];
    const holeStarts: number[] = [];
    for (const r of rings) {
      if (r !== o) holeStarts.push(ring.length);
      coords.set(flat[r], 2 * ring.length);
      for (const h of loops[r]) ring.push(h);
    }
    const triangles = triangulatePolygon(coords, holeStarts);
    if (triangles) {
      // where the outline touches itself, the separation left a copy of a vertex per fan: the
      // cap joins them into one, or leaves them apart, as its triangles decide
      const copies = joinCopies(w, ring);
      for (const f of fillRings(w, ring, holeStarts, triangles, -1)) result.faces.push(f);
      for (const group of copies) splitFans(w, group);
    } else if (holes.length === 0) {
      // an outline that crosses itself, from faces lying within the tolerance of the plane:
      // still closed, by a fan from one corner (which may fold over, but holds the right area)
      for (const f of fillRings(w, ring, [], fan(ring.length), -1)) result.faces.push(f);
      result.fanned++;
    } else {
      for (const r of rings) result.open.push({ halfedge: loops[r][0], reason: 'its outline crosses itself in the plane' });
      continue;
    }
    result.caps++;
  }
}

/** Triangles (0, i, i + 1) over the corners of one ring. */
function fan(corners: number): Uint32Array {
  const triangles = new Uint32Array(3 * (corners - 2));
  for (let i = 1; i + 1 < corners; i++) triangles.set([0, i, i + 1], 3 * (i - 1));
  return triangles;
}

/** Vertices at one point, and every halfedge that leaves them. */
interface Copies {
  vertices: number[];
  halfedges: number[];
}

/** Gives the vertices of `ring` that sit at one point a single id (the first of them), for the fill. */
function joinCopies(w: PointerWriter, ring: number[]): Copies[] {
  const { heVertex, hePrev, vHalfedge, positions: p } = w.mesh;
  const atPoint = new Map<string, number[]>();
  for (const h of ring) {
    const v = heVertex[h];
    const key = `${p[3 * v]},${p[3 * v + 1]},${p[3 * v + 2]}`;
    const list = atPoint.get(key);
    if (list) list.push(v);
    else atPoint.set(key, [v]);
  }
  const groups: Copies[] = [];
  for (const vertices of atPoint.values()) {
    if (vertices.length < 2) continue;
    const halfedges: number[] = [];
    for (const v of vertices) {
      const start = vHalfedge[v];
      let x = start;
      do {
        halfedges.push(x);
        x = hePrev[x] ^ 1;
      } while (x !== start);
    }
    for (const x of halfedges) w.setOrigin(x, vertices[0]);
    groups.push({ vertices, halfedges });
  }
  return groups;
}

/**
 * After the fill: one vertex per fan of faces around joined copies. The copies' ids are used
 * again in order; one left over (two fans that the cap made one) is deleted.
 */
function splitFans(w: PointerWriter, { vertices, halfedges }: Copies): void {
  const { hePrev } = w.mesh; // after the fill
  const seen = new Set<number>();
  let fans = 0;
  for (const start of halfedges) {
    if (seen.has(start)) continue;
    const v = vertices[fans++];
    let x = start;
    do {
      seen.add(x);
      w.setOrigin(x, v);
      x = hePrev[x] ^ 1;
    } while (x !== start);
    w.setVertexHalfedge(v, start);
  }
  for (let i = fans; i < vertices.length; i++) w.deleteVertex(vertices[i]);
}

/** Signed area of a closed 2D polygon (positive when counter-clockwise). */
function signedArea(c: Float64Array): number {
  let twice = 0;
  const n = c.length >> 1;
  for (let i = 0, j = n - 1; i < n; j = i++) twice += c[2 * j] * c[2 * i + 1] - c[2 * i] * c[2 * j + 1];
  return twice / 2;
}

/** Is (x, y) inside the polygon? (even–odd rule, a ray towards +x) */
function contains(c: Float64Array, x: number, y: number): boolean {
  let inside = false;
  const n = c.length >> 1;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const xi = c[2 * i];
    const yi = c[2 * i + 1];
    const xj = c[2 * j];
    const yj = c[2 * j + 1];
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}
