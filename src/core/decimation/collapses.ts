/**
 * The machinery of quadric decimation: each vertex's quadric, each edge's planned collapse (where
 * the merged vertex goes and what that costs), and the passes that collapse the cheapest edges.
 * `index.ts` runs it in phases.
 *
 * A pass collapses many edges at once, cheapest first, but none that shares a vertex with another
 * collapse of the same pass (as meshoptimizer's simplifier does): an edge whose ends no collapse
 * has touched still has the quadrics and positions it was planned with, so its plan is exact
 * without asking again. Each pass:
 *   1. plans again the edges of the vertices the last pass touched, in edge order (the rest keep
 *      their plans), and counts the costs (`candidates.ts`);
 *   2. collects the cheapest, about as many as the pass is to collapse, in order of cost to within
 *      an eighth (`candidates.ts`);
 *   3. chooses them in that order, skipping an edge with an end already chosen, until the chosen
 *      would take the pass's faces, or the costs climb past 1.5 times the cost the pass expected
 *      to reach (once a sixth of its faces are chosen: on a mesh where most of the cheap edges
 *      share vertices it still makes progress);
 *   4. collapses the chosen in id order, each that the checks below allow: in a mesh in spatial
 *      order (`spatialOrder`) each is near the one before, whose neighbourhood is in the cache.
 * A collapse touches its two ends; their other edges wait for the next pass, planned again.
 *
 * Boundaries: a boundary vertex stays exactly where it is, so an open surface keeps its rim.
 *   - An edge with one end on the boundary collapses onto that end (the interior end moves).
 *   - A boundary edge collapses onto one of its two ends (whichever costs less): the rim loses a
 *     vertex but every vertex left on it is an original one.
 *   - An interior edge with both ends on the boundary never collapses (it would pinch the surface).
 * On top of that, each boundary edge adds a *constraint plane* to the quadrics of its ends (the
 * plane through the edge, perpendicular to its face, weighted heavily), as Garland and Heckbert
 * do: moving a rim vertex off the line of its boundary edges costs a lot, so the rim is simplified
 * only where it is straight, or when nothing cheaper is left.
 *
 * Before each collapse, `canCollapseEdge` checks the topology (the link condition, no pinch, no
 * dangling edge) and `keepsOrientation` the geometry: no triangle around the two ends may turn
 * its normal by 90° or more, or lose all its area, so the surface never folds over itself. A
 * refused edge is out until one of its ends is touched by a later collapse, and, should no edge
 * be left before the target, every edge gets one more chance (as long as something collapsed
 * since the last chance).
 */
import { canCollapseEdge, collapseEdgeAt } from '../edits/collapse.js';
import { PointerWriter } from '../change/writer.js';
import type { HalfedgeMesh } from '../mesh.js';
import { zeros } from '../memory.js';
import type { ChangeRecorder } from '../change/recorder.js';
import { Candidates } from './candidates.js';
import { AREA, addPlane, optimalPoint, QUADRIC_SIZE, quadricError, sumQuadrics } from './quadric.js';

/** Weight of a boundary edge's constraint plane, per unit of the edge's squared length. */
const BOUNDARY_WEIGHT = 1000;
/** A pass stops at costs this many times the one it expected to reach (see above). */
const COST_OVERSHOOT = 1.5;

export class Decimator {
  readonly mesh: HalfedgeMesh;
  /** The mesh's positions (a collapse never reallocates them). */
  private readonly positions: Float64Array;
  /** QUADRIC_SIZE numbers per vertex slot (see `quadric.ts`). */
  private readonly quadrics: Float64Array;
  /** 1 where the vertex is on the boundary: the mesh says so too, but in two cache misses. */
  private readonly onBoundary: Uint8Array;
  /**
   * Each edge's cost as last planned, as float32 (the bits order them as the costs do): Infinity
   * where it may not collapse now (never, past the error limit, or refused until an end is touched).
   */
  private readonly costs: Float32Array;
  private readonly costBits: Uint32Array;
  /** The edges alive at the last pass, in id order (the first `liveCount`). */
  private readonly live: Int32Array;
  private liveCount = 0;
  /**
   * 1 for each end of an edge the pass chose (0 again when its collapse is refused): no other
   * collapse of the pass may touch it, and the next pass plans its edges again.
   */
  private readonly touched: Uint8Array;
  /** The next scan plans every live edge, not only those the last pass touched. */
  private planEveryEdge = true;
  private readonly candidates = new Candidates();
  /** 1 for each edge the pass chose to collapse. */
  private readonly chosen: Uint8Array;
  /** Largest mean squared distance a merged vertex may have from its original planes. */
  private readonly maxSquaredError: number;
  /** Collapses made, and refused by a check that a later collapse could change, since every edge was last planned. */
  private collapsedSinceReplan = 0;
  private refusedSinceReplan = 0;
  /** True once no allowed collapse is left. */
  exhausted = false;

  /** Scratch: the summed quadric of an edge's ends, the points a plan weighs, and the best of them. */
  private readonly sum = new Float64Array(QUADRIC_SIZE);
  private readonly tried = new Float64Array(9);
  private readonly point = new Float64Array(3);

  constructor(mesh: HalfedgeMesh, maxError: number) {
    this.mesh = mesh;
    this.positions = mesh.positions;
    this.quadrics = vertexQuadrics(mesh);
    this.onBoundary = new Uint8Array(mesh.vertexSlots);
    for (let v = 0; v < mesh.vertexSlots; v++) this.onBoundary[v] = mesh.isBoundaryVertex(v) ? 1 : 0;
    this.costs = new Float32Array(mesh.edgeSlots);
    this.costBits = new Uint32Array(this.costs.buffer);
    this.live = new Int32Array(mesh.edgeSlots);
    for (let e = 0; e < mesh.edgeSlots; e++) if (!mesh.eDeleted[e]) this.live[this.liveCount++] = e;
    this.touched = new Uint8Array(mesh.vertexSlots);
    this.chosen = new Uint8Array(mesh.edgeSlots);
    this.maxSquaredError = maxError * maxError;
  }

  /**
   * Collapses the cheapest allowed edges, pass after pass, until the mesh has at most `faceGoal`
   * faces or nothing allowed is left, writing every collapse into `recorder` (null: no record).
   */
  collapseUntil(faceGoal: number, recorder: ChangeRecorder | null): void {
    // one writer for all the passes, no ids listed
    const w = new PointerWriter(this.mesh, { recorder, ids: false });
    // Bounded: a pass that collapses nothing refuses at least one edge, which stays out until a
    // collapse (or plans every edge again, which needs a collapse since the last time), or ends.
    while (this.mesh.nFaces > faceGoal && !this.exhausted) this.pass(w, faceGoal);
  }

  /** One pass (see above). */
  private pass(w: PointerWriter, faceGoal: number): void {
    const { mesh, costs, costBits, touched, candidates, quadrics: q, point } = this;
    const { heVertex, eDeleted } = mesh; // a collapse never reallocates them

    // 1. plan again where the last pass touched, drop the deleted edges, count the costs
    const live = this.live;
    let n = 0;
    for (let i = 0; i < this.liveCount; i++) {
      const e = live[i];
      if (eDeleted[e]) continue;
      live[n++] = e;
      if (this.planEveryEdge || touched[heVertex[2 * e]] || touched[heVertex[2 * e + 1]]) this.plan(e);
      candidates.count(costBits[e]);
    }
    this.liveCount = n;
    touched.fill(0);
    if (this.planEveryEdge) {
      this.planEveryEdge = false;
      this.collapsedSinceReplan = 0;
      this.refusedSinceReplan = 0;
    }
    // no edge allowed: once more with every edge, if a collapse may have freed a refused one
    if (candidates.counted === 0) {
      if (this.collapsedSinceReplan === 0 || this.refusedSinceReplan === 0) this.exhausted = true;
      else this.planEveryEdge = true;
      return;
    }

    // 2. the cheapest, in order: most collapses take two faces
    const facesToGo = mesh.nFaces - faceGoal;
    const wanted = Math.ceil(facesToGo / 2);
    candidates.collect(live, n, costBits, wanted);
    const { edges, size } = candidates;
    const expectedCost = wanted <= size ? candidates.costAt(wanted - 1) : Infinity;

    // 3. choose them, cheapest first, no two sharing a vertex
    const chosen = this.chosen;
    let nChosen = 0;
    for (let i = 0, facesChosen = 0; i < size && facesChosen < facesToGo; i++) {
      if (candidates.costAt(i) > COST_OVERSHOOT * expectedCost && facesChosen > facesToGo / 6) break;
      const e = edges[i];
      const a = heVertex[2 * e];
      const b = heVertex[2 * e + 1];
      if (touched[a] || touched[b]) continue;
      touched[a] = 1;
      touched[b] = 1;
      chosen[e] = 1;
      nChosen++;
      facesChosen += 2;
    }
    // 4. collapse them in id order (the live edges are): in a mesh in spatial order, one after its
    // neighbours. A chosen edge is never deleted by another's collapse, which only deletes edges
    // at its own ends
    for (let i = 0; i < n && nChosen > 0; i++) {
      const e = live[i];
      if (chosen[e] === 0) continue;
      chosen[e] = 0;
      nChosen--;
      if (mesh.nFaces <= faceGoal) continue;
      const a = heVertex[2 * e];
      const b = heVertex[2 * e + 1];
      this.plan(e);
      if (canCollapseEdge(mesh, e) !== null || !keepsOrientation(mesh, e, point[0], point[1], point[2])) {
        costs[e] = Infinity;
        this.refusedSinceReplan++;
        // nothing changed at its ends: their other edges keep their plans
        touched[a] = 0;
        touched[b] = 0;
        continue;
      }
      // collapse: a survives at the planned point and stands for the planes of both ends
      collapseEdgeAt(w, e, point);
      sumQuadrics(q, QUADRIC_SIZE * a, QUADRIC_SIZE * b, q, QUADRIC_SIZE * a);
      this.onBoundary[a] |= this.onBoundary[b];
      this.collapsedSinceReplan++;
    }
  }

  /** For each vertex slot, the cost of the cheapest collapse of its edges as planned now (NaN: none). */
  cheapestCollapses(): Float32Array {
    const { mesh } = this;
    const cheapest = new Float32Array(mesh.vertexSlots).fill(Infinity);
    for (let e = 0; e < mesh.edgeSlots; e++) {
      if (mesh.eDeleted[e]) continue;
      this.plan(e);
      const cost = this.costs[e];
      const a = mesh.heVertex[2 * e];
      const b = mesh.heVertex[2 * e + 1];
      if (cost < cheapest[a]) cheapest[a] = cost;
      if (cost < cheapest[b]) cheapest[b] = cost;
    }
    for (let v = 0; v < cheapest.length; v++) if (cheapest[v] === Infinity) cheapest[v] = NaN;
    return cheapest;
  }

  /**
   * Plans the collapse of edge `e`: puts where its merged vertex goes into `point` and what that
   * costs (the summed quadric of the two ends, evaluated there) into `costs[e]`, or Infinity when
   * the edge may not collapse: never, or not within the error limit (which only grows more
   * certain, as the ends only gain planes). The cost is stored rather than returned: returned, it
   * was a new heap number for every plan the engine did not inline (79 MB of them a decimation of
   * the 1.3M-triangle icosphere), and over a few decimations the young generation grew from 16 to
   * 32 MB to hold them (peak 390 MB against 407 in three decimations by a process; the same time).
   */
  private plan(e: number): void {
    const { mesh, quadrics: q, sum, positions: p } = this;
    const { heVertex, heFace } = mesh;
    const a = heVertex[2 * e];
    const b = heVertex[2 * e + 1];
    const aOnBoundary = this.onBoundary[a] === 1;
    const bOnBoundary = this.onBoundary[b] === 1;
    sumQuadrics(q, QUADRIC_SIZE * a, QUADRIC_SIZE * b, sum, 0);
    // the points to weigh: one end, either end, the optimum, or (when the planes allow a range of
    // points) both ends and the middle; weighed in one place, so the engine inlines the weighing
    const tried = this.tried;
    let n = 0;
    // one end on the boundary: onto that end
    if (aOnBoundary !== bOnBoundary) {
      n = this.tryVertex(aOnBoundary ? a : b, n);
    }
    // both ends on the boundary: along a boundary edge onto either end, across the surface never
    else if (aOnBoundary) {
      if (heFace[2 * e] === -1 || heFace[2 * e + 1] === -1) n = this.tryVertex(b, this.tryVertex(a, n));
    }
    // inside: the best point, or the best of the ends and the middle
    else if (optimalPoint(sum, 0, tried)) {
      n = 1;
    } else {
      n = this.tryVertex(b, this.tryVertex(a, n));
      for (let k = 0; k < 3; k++) tried[3 * n + k] = (p[3 * a + k] + p[3 * b + k]) / 2;
      n++;
    }
    const point = this.point;
    let best = Infinity;
    for (let i = 0; i < 3 * n; i += 3) {
      const cost = quadricError(sum, 0, tried[i], tried[i + 1], tried[i + 2]);
      if (cost < best) {
        best = cost;
        point[0] = tried[i];
        point[1] = tried[i + 1];
        point[2] = tried[i + 2];
      }
    }
    // too far from the original surface?
    this.costs[e] = best > this.maxSquaredError * sum[AREA] ? Infinity : best;
  }

  /** Adds vertex `v`'s position to the points tried, after the first `n`; returns their new count. */
  private tryVertex(v: number, n: number): number {
    const p = this.positions;
    for (let k = 0; k < 3; k++) this.tried[3 * n + k] = p[3 * v + k];
    return n + 1;
  }
}

/**
 * Each vertex's quadric: the planes of its triangles weighted by their areas (a large triangle
 * says more about the surface than a sliver), plus a constraint plane for each boundary edge.
 */
function vertexQuadrics(mesh: HalfedgeMesh): Float64Array {
  const { heNext, heVertex, heFace, fHalfedge, fDeleted } = mesh;
  const p = mesh.positions;
  const q = zeros(Float64Array, QUADRIC_SIZE * mesh.vertexSlots);
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const h0 = fHalfedge[f];
    const a = 3 * heVertex[h0];
    const b = 3 * heVertex[heNext[h0]];
    const c = 3 * heVertex[heNext[heNext[h0]]];
    const ux = p[b] - p[a];
    const uy = p[b + 1] - p[a + 1];
    const uz = p[b + 2] - p[a + 2];
    const vx = p[c] - p[a];
    const vy = p[c + 1] - p[a + 1];
    const vz = p[c + 2] - p[a + 2];
    let nx = uy * vz - uz * vy;
    let ny = uz * vx - ux * vz;
    let nz = ux * vy - uy * vx;
    const length = Math.sqrt(nx * nx + ny * ny + nz * nz);
    // zero area: no plane to keep
    if (length === 0) continue;
    nx /= length;
    ny /= length;
    nz /= length;
    const d = -(nx * p[a] + ny * p[a + 1] + nz * p[a + 2]);
    const area = length / 2;
    let h = h0;
    do {
      const v = heVertex[h];
      addPlane(q, QUADRIC_SIZE * v, nx, ny, nz, d, area);
      q[QUADRIC_SIZE * v + AREA] += area;
      // boundary edge: the plane through it, perpendicular to the face, for both its ends
      if (heFace[h ^ 1] === -1) {
        const w = heVertex[heNext[h]];
        const ex = p[3 * w] - p[3 * v];
        const ey = p[3 * w + 1] - p[3 * v + 1];
        const ez = p[3 * w + 2] - p[3 * v + 2];
        const edgeLength = Math.sqrt(ex * ex + ey * ey + ez * ez);
        // (edge × normal) / |edge| has unit length: the normal is a unit vector perpendicular to the edge
        const mx = (ey * nz - ez * ny) / edgeLength;
        const my = (ez * nx - ex * nz) / edgeLength;
        const mz = (ex * ny - ey * nx) / edgeLength;
        const md = -(mx * p[3 * v] + my * p[3 * v + 1] + mz * p[3 * v + 2]);
        const weight = BOUNDARY_WEIGHT * edgeLength * edgeLength;
        addPlane(q, QUADRIC_SIZE * v, mx, my, mz, md, weight);
        addPlane(q, QUADRIC_SIZE * w, mx, my, mz, md, weight);
      }
      h = heNext[h];
    } while (h !== h0);
  }
  return q;
}

/**
 * True when moving both ends of edge `e` to (x, y, z) leaves every other triangle around them
 * facing within 90° of where it faced, with some area left. (The triangles beside `e` vanish.)
 */
export function keepsOrientation(mesh: HalfedgeMesh, e: number, x: number, y: number, z: number): boolean {
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const p = mesh.positions;
  const f0 = heFace[2 * e];
  const f1 = heFace[2 * e + 1];
  for (let start = 2 * e; start < 2 * e + 2; start++) {
    const o = 3 * heVertex[start];
    let h = start;
    do {
      const f = heFace[h];
      if (f !== -1 && f !== f0 && f !== f1) {
        // the triangle (v, u, w) around v = origin(h), before and after v moves
        const u = 3 * heVertex[heNext[h]];
        const w = 3 * heVertex[hePrev[h]];
        const ux = p[u] - p[o];
        const uy = p[u + 1] - p[o + 1];
        const uz = p[u + 2] - p[o + 2];
        const wx = p[w] - p[o];
        const wy = p[w + 1] - p[o + 1];
        const wz = p[w + 2] - p[o + 2];
        const sx = p[u] - x;
        const sy = p[u + 1] - y;
        const sz = p[u + 2] - z;
        const tx = p[w] - x;
        const ty = p[w + 1] - y;
        const tz = p[w + 2] - z;
        // normal before · normal after
        const turn =
          (uy * wz - uz * wy) * (sy * tz - sz * ty) + (uz * wx - ux * wz) * (sz * tx - sx * tz) + (ux * wy - uy * wx) * (sx * ty - sy * tx);
        if (turn <= 0) return false;
      }
      h = hePrev[h] ^ 1;
    } while (h !== start);
  }
  return true;
}
