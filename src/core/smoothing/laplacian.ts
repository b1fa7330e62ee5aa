/**
 * One Laplacian step, the building block of every smoothing method here:
 *
 *     p_i ← p_i + s · (Σ_j w_ij p_j / Σ_j w_ij − p_i)
 *
 * Each vertex moves a fraction `s` of the way from where it is towards a weighted mean of its
 * neighbours j (s < 0 moves it away). All vertices move at once, from the old positions (a Jacobi
 * step), so the result does not depend on the order of the vertices.
 *
 * The weights live on the edges, one number each, the same seen from both ends:
 *   - uniform: every edge weighs 1, so the mean is the plain average of the neighbours (the
 *     "umbrella" operator). It smooths the mesh as a graph: on an irregular mesh it also slides
 *     vertices along the surface, towards where the triangles are smaller.
 *   - cotangent: edge ij weighs (cot α + cot β) / 2, α and β being the angles that face the edge
 *     in its two triangles (one on the boundary). The weighted mean then tracks the *geometry*: on
 *     a flat patch it is where the vertex already is, however irregular the triangles, and on a
 *     curved one the step points along the normal (it approximates mean curvature flow).
 * ```
 *            k
 *           ╱ α╲
 *          i ─── j        w_ij = (cot α + cot β) / 2
 *           ╲ β╱
 *            l
 * ```
 * A negative cotangent weight (α + β > π, an edge that a Delaunay flip would turn) is clamped to
 * 0, as pmp-library does: with every weight ≥ 0 the mean is a convex combination of the neighbours,
 * so a step with 0 ≤ s ≤ 1 cannot overshoot. A degenerate triangle (zero area, where a cotangent
 * is infinite) adds no weight.
 *
 * Boundary vertices either stay (`fixed`) or are smoothed along the boundary curve (`smooth`):
 * their mean is that of their two neighbours along the boundary, so the rim is smoothed as a
 * polygon of its own and is not pulled into the surface.
 */
import type { HalfedgeMesh } from '../mesh.js';

export type BoundaryRule = 'fixed' | 'smooth';

/*
 * What a step does with a vertex, known once (smoothing moves vertices but never changes the
 * connectivity): an isolated or deleted one stays; a boundary one stays, or follows its two
 * neighbours along the boundary; an interior one goes towards the weighted mean of its neighbours.
 */
const ISOLATED = 0;
const BOUNDARY = 1;
const INTERIOR = 2;

/** Scratch arrays for repeated steps on one mesh, sized from its slot counts once. */
export class LaplacianSmoother {
  /** Weight of each edge slot. */
  readonly weights: Float64Array;
  /** Σ w_ij p_j per vertex, then the new positions. */
  private readonly sums: Float64Array;
  /** Σ w_ij per vertex. */
  private readonly weightSums: Float64Array;
  /** Each vertex's role (ISOLATED, BOUNDARY, INTERIOR): read in order, where looking at its halfedge's face would be a read at random. */
  private readonly roles: Uint8Array;

  constructor(
    readonly mesh: HalfedgeMesh,
    readonly boundary: BoundaryRule,
  ) {
    this.weights = new Float64Array(mesh.edgeSlots).fill(1);
    this.sums = new Float64Array(3 * mesh.vertexSlots);
    this.weightSums = new Float64Array(mesh.vertexSlots);
    this.roles = new Uint8Array(mesh.vertexSlots);
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const h = mesh.vHalfedge[v];
      this.roles[v] = h === -1 ? ISOLATED : mesh.heFace[h] === -1 ? BOUNDARY : INTERIOR;
    }
  }

  /** Sets every edge's weight to (cot α + cot β) / 2 at the current positions (triangles only). */
  useCotangentWeights(): void {
    const { heNext, heVertex, fHalfedge, fDeleted } = this.mesh;
    const p = this.mesh.positions;
    const w = this.weights;
    w.fill(0);
    for (let f = 0; f < this.mesh.faceSlots; f++) {
      if (fDeleted[f]) continue;
      const h0 = fHalfedge[f];
      const h1 = heNext[h0];
      const h2 = heNext[h1];
      const i = 3 * heVertex[h0];
      const j = 3 * heVertex[h1];
      const k = 3 * heVertex[h2];
      // twice the area: every corner's cotangent is (its dot product) / (this)
      const ux = p[j] - p[i];
      const uy = p[j + 1] - p[i + 1];
      const uz = p[j + 2] - p[i + 2];
      const vx = p[k] - p[i];
      const vy = p[k + 1] - p[i + 1];
      const vz = p[k + 2] - p[i + 2];
      const cx = uy * vz - uz * vy;
      const cy = uz * vx - ux * vz;
      const cz = ux * vy - uy * vx;
      const doubleArea = Math.sqrt(cx * cx + cy * cy + cz * cz);
      // degenerate triangle? its angles say nothing
      if (doubleArea === 0) continue;
      const half = 0.5 / doubleArea;
      // each corner's angle faces the edge of the halfedge opposite it
      w[h1 >> 1] += half * cornerDot(p, i, j, k); // corner i faces j → k
      w[h2 >> 1] += half * cornerDot(p, j, k, i); // corner j faces k → i
      w[h0 >> 1] += half * cornerDot(p, k, i, j); // corner k faces i → j
    }
    for (let e = 0; e < w.length; e++) if (w[e] < 0) w[e] = 0;
  }

  /**
   * Moves every free vertex by `step` times (weighted mean of its neighbours − itself), and writes
   * how far each vertex moved into `distances` when it is given.
   */
  step(step: number, distances?: Float32Array): void {
    const { heNext, hePrev, heVertex, vHalfedge, eDeleted } = this.mesh;
    const p = this.mesh.positions;
    const { weights, sums, weightSums, roles } = this;
    const fixed = this.boundary === 'fixed';
    const V = this.mesh.vertexSlots;

    // sum each vertex's weighted neighbours, edge by edge
    sums.fill(0);
    weightSums.fill(0);
    for (let e = 0; e < this.mesh.edgeSlots; e++) {
      if (eDeleted[e]) continue;
      const w = weights[e];
      const a = heVertex[2 * e];
      const b = heVertex[2 * e + 1];
      sums[3 * a] += w * p[3 * b];
      sums[3 * a + 1] += w * p[3 * b + 1];
      sums[3 * a + 2] += w * p[3 * b + 2];
      sums[3 * b] += w * p[3 * a];
      sums[3 * b + 1] += w * p[3 * a + 1];
      sums[3 * b + 2] += w * p[3 * a + 2];
      weightSums[a] += w;
      weightSums[b] += w;
    }

    // the new positions, into `sums` (each vertex reads only its own sum and old positions)
    for (let v = 0; v < V; v++) {
      const o = 3 * v;
      const role = roles[v];
      let mx = p[o];
      let my = p[o + 1];
      let mz = p[o + 2];
      if (role === BOUNDARY) {
        if (!fixed) {
          const h = vHalfedge[v];
          const a = 3 * heVertex[heNext[h]];
          const b = 3 * heVertex[hePrev[h]];
          mx = (p[a] + p[b]) / 2;
          my = (p[a + 1] + p[b + 1]) / 2;
          mz = (p[a + 2] + p[b + 2]) / 2;
        }
      }
      // (it stays if every weight is 0)
      else if (role === INTERIOR && weightSums[v] > 0) {
        const w = weightSums[v];
        mx = sums[o] / w;
        my = sums[o + 1] / w;
        mz = sums[o + 2] / w;
      }
      sums[o] = p[o] + step * (mx - p[o]);
      sums[o + 1] = p[o + 1] + step * (my - p[o + 1]);
      sums[o + 2] = p[o + 2] + step * (mz - p[o + 2]);
    }

    if (distances) {
      for (let v = 0; v < V; v++) {
        const o = 3 * v;
        const dx = sums[o] - p[o];
        const dy = sums[o + 1] - p[o + 1];
        const dz = sums[o + 2] - p[o + 2];
        // not Math.hypot, which costs ten times as much; a distance is only a colour here
        distances[v] = Math.sqrt(dx * dx + dy * dy + dz * dz);
      }
    }
    p.set(sums);
  }
}

/** (a − corner) · (b − corner), for vertex offsets into the positions. */
function cornerDot(p: Float64Array, corner: number, a: number, b: number): number {
  return (
    (p[a] - p[corner]) * (p[b] - p[corner]) +
    (p[a + 1] - p[corner + 1]) * (p[b + 1] - p[corner + 1]) +
    (p[a + 2] - p[corner + 2]) * (p[b + 2] - p[corner + 2])
  );
}
