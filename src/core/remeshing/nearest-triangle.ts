/**
 * The nearest point on a fixed set of triangles (the input surface of a remeshing), found through
 * a uniform grid of cells built once: each triangle is listed in every cell its bounding box
 * touches, so the triangles near a point are those of the cells near it.
 * ```
 *   ┌───┬───┬───┬───┐
 *   │   │ ╱╲│   │   │     a query at p with a guess (the triangle its vertex was on last time,
 *   ├───┼╱──┼╲──┼───┤     at distance d) looks only at the cells that the box p ± d touches: a
 *   │  ╱│ p·│ ╲ │   │     nearer triangle must reach into that box. A vertex that moved a little
 *   ├───┴───┴───┴───┤     has a small d, and so one to eight cells to look at.
 * ```
 * The grid is sparse: a surface fills few of the cells of its bounding box (a sphere of a million
 * triangles would touch 0.1% of a dense grid at this cell size), so cells are found by hashing
 * their integer coordinates into a table about twice as long as there are listings. Two cells
 * that hash alike share a list: a query then looks at a few triangles more, never fewer. The
 * lists are one array (`items`), each table slot's list starting at `starts[slot]`.
 *
 * A triangle met again in another cell is skipped by its stamp (the number of the query that last
 * looked at it), and one whose bounding box is farther than the best distance so far is skipped
 * before the exact test (Ericson, *Real-Time Collision Detection*, §5.1.5: the region of the
 * triangle the point projects to, from six dot products).
 */
import type { HalfedgeMesh } from '../mesh.js';

/** Mixes a cell's integer coordinates into a table slot (the multipliers are large odd primes). */
function cellHash(ix: number, iy: number, iz: number, mask: number): number {
  return (Math.imul(ix, 73856093) ^ Math.imul(iy, 19349663) ^ Math.imul(iz, 83492791)) & mask;
}

export class NearestTriangle {
  /** Triangles listed. */
  readonly count: number;
  /** Corners a, b, c of each triangle, nine numbers each. */
  private readonly corners: Float64Array;
  /** Bounding box of each triangle: min x, y, z, max x, y, z. */
  private readonly boxes: Float64Array;
  private readonly cellSize: number;
  private readonly mask: number;
  /** Where each table slot's list of triangles starts in `items` (its end: the next slot's start). */
  private readonly starts: Int32Array;
  private readonly items: Int32Array;
  /** The query that last looked at each triangle. */
  private readonly stamps: Int32Array;
  private stamp = 0;
  /** The cells the triangles touch, inclusive: a query's box is clipped to them. */
  private readonly cellMin = [0, 0, 0];
  private readonly cellMax = [0, 0, 0];

  /** The nearest point of the last query, and its triangle. */
  x = 0;
  y = 0;
  z = 0;
  triangle = -1;

  /**
   * Lists the live faces of `mesh` (triangles) as they are now; triangle `i` is the i-th live face
   * in id order (`triangleOfFace` says which). `cellSize` about the length of their edges keeps a
   * few triangles in each cell.
   */
  constructor(mesh: HalfedgeMesh, cellSize: number) {
    const { heNext, heVertex, fHalfedge, fDeleted } = mesh;
    const p = mesh.positions;
    this.count = mesh.nFaces;
    const n = this.count;
    this.cellSize = cellSize;
    const corners = (this.corners = new Float64Array(9 * n));
    const boxes = (this.boxes = new Float64Array(6 * n));
    let t = 0;
    for (let f = 0; f < mesh.faceSlots; f++) {
      if (fDeleted[f]) continue;
      const h = fHalfedge[f];
      const a = 3 * heVertex[h];
      const b = 3 * heVertex[heNext[h]];
      const c = 3 * heVertex[heNext[heNext[h]]];
      for (let k = 0; k < 3; k++) {
        corners[9 * t + k] = p[a + k];
        corners[9 * t + 3 + k] = p[b + k];
        corners[9 * t + 6 + k] = p[c + k];
        boxes[6 * t + k] = Math.min(p[a + k], p[b + k], p[c + k]);
        boxes[6 * t + 3 + k] = Math.max(p[a + k], p[b + k], p[c + k]);
      }
      t++;
    }

    // count the listings of each triangle's cells, then the table: a power of two, about twice as long
    const inverse = 1 / cellSize;
    let listings = 0;
    this.cellMin.fill(Infinity);
    this.cellMax.fill(-Infinity);
    for (let i = 0; i < n; i++) {
      let cells = 1;
      for (let k = 0; k < 3; k++) {
        const lo = Math.floor(boxes[6 * i + k] * inverse);
        const hi = Math.floor(boxes[6 * i + 3 + k] * inverse);
        cells *= hi - lo + 1;
        if (lo < this.cellMin[k]) this.cellMin[k] = lo;
        if (hi > this.cellMax[k]) this.cellMax[k] = hi;
      }
      listings += cells;
    }
    let size = 1024;
    while (size < 2 * listings) size *= 2;
    this.mask = size - 1;
    const starts = (this.starts = new Int32Array(size + 1));
    const items = (this.items = new Int32Array(listings));
    this.stamps = new Int32Array(n);

    // each slot's count, then where its list ends, then the lists (each filled from its end)
    for (let pass = 0; pass < 2; pass++) {
      for (let i = 0; i < n; i++) {
        const x0 = Math.floor(boxes[6 * i] * inverse);
        const y0 = Math.floor(boxes[6 * i + 1] * inverse);
        const z0 = Math.floor(boxes[6 * i + 2] * inverse);
        const x1 = Math.floor(boxes[6 * i + 3] * inverse);
        const y1 = Math.floor(boxes[6 * i + 4] * inverse);
        const z1 = Math.floor(boxes[6 * i + 5] * inverse);
        for (let ix = x0; ix <= x1; ix++) {
          for (let iy = y0; iy <= y1; iy++) {
            for (let iz = z0; iz <= z1; iz++) {
              const slot = cellHash(ix, iy, iz, this.mask);
              if (pass === 0) starts[slot]++;
              else items[--starts[slot]] = i;
            }
          }
        }
      }
      // after the counts: each slot's end, which comes down to its start as its list is filled
      if (pass === 0) {
        for (let s = 1; s < size; s++) starts[s] += starts[s - 1];
        starts[size] = starts[size - 1];
      }
    }
  }

  /**
   * Finds the point of the triangles nearest (px, py, pz), looking first at triangle `guess`
   * (-1: none, then every cell may be looked at). Leaves the point in `x`, `y`, `z` and its
   * triangle in `triangle`; returns the squared distance (Infinity when there are no triangles).
   */
  nearest(px: number, py: number, pz: number, guess: number): number {
    const { boxes, items, starts, stamps, mask } = this;
    const stamp = ++this.stamp;
    let best = Infinity;
    if (guess >= 0 && guess < this.count) {
      best = this.test(guess, px, py, pz, Infinity);
      stamps[guess] = stamp;
    }
    // the cells of the box p ± √best, clipped to those the triangles touch
    const reach = Math.sqrt(best);
    const inverse = 1 / this.cellSize;
    const x0 = Math.max(this.cellMin[0], Math.floor((px - reach) * inverse));
    const y0 = Math.max(this.cellMin[1], Math.floor((py - reach) * inverse));
    const z0 = Math.max(this.cellMin[2], Math.floor((pz - reach) * inverse));
    const x1 = Math.min(this.cellMax[0], Math.floor((px + reach) * inverse));
    const y1 = Math.min(this.cellMax[1], Math.floor((py + reach) * inverse));
    const z1 = Math.min(this.cellMax[2], Math.floor((pz + reach) * inverse));
    for (let ix = x0; ix <= x1; ix++) {
      for (let iy = y0; iy <= y1; iy++) {
        for (let iz = z0; iz <= z1; iz++) {
          const slot = cellHash(ix, iy, iz, mask);
          const end = starts[slot + 1];
          for (let k = starts[slot]; k < end; k++) {
            const t = items[k];
            if (stamps[t] === stamp) continue;
            stamps[t] = stamp;
            // its bounding box farther than the best so far?
            const o = 6 * t;
            const dx = px < boxes[o] ? boxes[o] - px : px > boxes[o + 3] ? px - boxes[o + 3] : 0;
            const dy = py < boxes[o + 1] ? boxes[o + 1] - py : py > boxes[o + 4] ? py - boxes[o + 4] : 0;
            const dz = pz < boxes[o + 2] ? boxes[o + 2] - pz : pz > boxes[o + 5] ? pz - boxes[o + 5] : 0;
            if (dx * dx + dy * dy + dz * dz >= best) continue;
            best = this.test(t, px, py, pz, best);
          }
        }
      }
    }
    return best;
  }

  /**
   * The squared distance from p to triangle `t`; when below `best`, the nearest point becomes the
   * result (`x`, `y`, `z`, `triangle`). Returns the smaller of the two distances.
   */
  private test(t: number, px: number, py: number, pz: number, best: number): number {
    const c = this.corners;
    const o = 9 * t;
    const ax = c[o];
    const ay = c[o + 1];
    const az = c[o + 2];
    const abx = c[o + 3] - ax;
    const aby = c[o + 4] - ay;
    const abz = c[o + 5] - az;
    const acx = c[o + 6] - ax;
    const acy = c[o + 7] - ay;
    const acz = c[o + 8] - az;
    const apx = px - ax;
    const apy = py - ay;
    const apz = pz - az;
    // the point is nearest some corner, some side or the inside: by the signs of six dot products
    const d1 = abx * apx + aby * apy + abz * apz;
    const d2 = acx * apx + acy * apy + acz * apz;
    let u: number; // the nearest point is a + u·ab + v·ac
    let v: number;
    if (d1 <= 0 && d2 <= 0) {
      u = 0; // corner a
      v = 0;
    } else {
      const bpx = px - c[o + 3];
      const bpy = py - c[o + 4];
      const bpz = pz - c[o + 5];
      const d3 = abx * bpx + aby * bpy + abz * bpz;
      const d4 = acx * bpx + acy * bpy + acz * bpz;
      const cpx = px - c[o + 6];
      const cpy = py - c[o + 7];
      const cpz = pz - c[o + 8];
      const d5 = abx * cpx + aby * cpy + abz * cpz;
      const d6 = acx * cpx + acy * cpy + acz * cpz;
      const vc = d1 * d4 - d3 * d2;
      const vb = d5 * d2 - d1 * d6;
      const va = d3 * d6 - d5 * d4;
      if (d3 >= 0 && d4 <= d3) {
        u = 1; // corner b
        v = 0;
      } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        u = d1 / (d1 - d3); // side ab
        v = 0;
      } else if (d6 >= 0 && d5 <= d6) {
        u = 0; // corner c
        v = 1;
      } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        u = 0; // side ac
        v = d2 / (d2 - d6);
      } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        v = (d4 - d3) / (d4 - d3 + (d5 - d6)); // side bc
        u = 1 - v;
      } else {
        const denominator = 1 / (va + vb + vc); // inside
        u = vb * denominator;
        v = vc * denominator;
      }
    }
    const qx = ax + u * abx + v * acx;
    const qy = ay + u * aby + v * acy;
    const qz = az + u * abz + v * acz;
    const distance = (px - qx) * (px - qx) + (py - qy) * (py - qy) + (pz - qz) * (pz - qz);
    if (distance >= best) return best;
    this.x = qx;
    this.y = qy;
    this.z = qz;
    this.triangle = t;
    return distance;
  }
}
