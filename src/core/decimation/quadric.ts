/**
 * Quadrics (Garland & Heckbert 1997): the squared distance of a point x to a plane n·x + d = 0
 * is (n·x + d)² = [x 1] (q qᵀ) [x 1]ᵀ with q = (n, d), a quadratic form. A sum of such forms,
 * one 4×4 symmetric matrix Q, measures the (weighted) sum of squared distances to many planes at
 * once, and adding two sums is adding their matrices: so a vertex can carry "the planes of every
 * original triangle I stand for" in ten numbers, however many collapses it has absorbed.
 *
 * Layout: QUADRIC_SIZE numbers per vertex at offset `o`, the upper triangle of Q row by row,
 *   xx xy xz xw  yy yz yw  zz zw  ww
 * and then the area of the triangles it stands for (so an error can be turned into a mean).
 *
 * The point where the error is smallest solves A x = −b, A the upper-left 3×3 block and b the
 * last column. A is singular when the planes do not pin a point down: all parallel (a flat
 * region: any point on the plane is as good) or all through one line (a crease or a cylinder);
 * `optimalPoint` refuses those, and the caller tries a few points on the edge instead.
 */

export const QUADRIC_SIZE = 11;
/** Offset of the area within a quadric. */
export const AREA = 10;

/**
 * `A x = −b` is solved only when det A > CONDITION · (trace A / 3)³. The ratio is 1 when the
 * planes point in all directions evenly and goes to 0 as they line up (for a symmetric positive
 * semi-definite A it is the product of the eigenvalues over the cube of their mean), so it
 * measures how firmly the point is held, whatever the scale of the mesh. Flat regions and straight
 * creases give 0 up to rounding (1e-15 and less); curved ones give more the more they bend: about
 * 1e-5 for two neighbours on a sphere of ten thousand triangles, 1e-9 on a sphere of a million,
 * and more as merged vertices gather planes from further apart. The optimum is the better point
 * wherever it can be trusted (on a sphere, the fallback points leave long slivers), so the bar
 * is low, yet five orders of magnitude above rounding. At 1e-9 it sat where a million-triangle
 * sphere's neighbours do, and half of their plans weighed the fallback points instead: decimating
 * the 1.3M-triangle icosphere took 1695–1750 ms that way against 1646–1650 at 1e-10 (medians of
 * 10 by turns), the 269k-triangle Igea scan of the corpus 680 against 585 ms, and the results
 * stray about as far from the input: the icosphere at most 5.75e-5 against 5.81e-5, the
 * latitude–longitude sphere of the benchmark 7.81e-5 against 7.63e-5 (1.5e-5 and 2.05e-5 on
 * average, both ways), twelve meshes of the corpus the same to three digits.
 */
const CONDITION = 1e-10;

/** Adds `weight` × the plane n·x + d = 0 (n of unit length) to the quadric at `o`. */
export function addPlane(q: Float64Array, o: number, nx: number, ny: number, nz: number, d: number, weight: number): void {
  q[o] += weight * nx * nx;
  q[o + 1] += weight * nx * ny;
  q[o + 2] += weight * nx * nz;
  q[o + 3] += weight * nx * d;
  q[o + 4] += weight * ny * ny;
  q[o + 5] += weight * ny * nz;
  q[o + 6] += weight * ny * d;
  q[o + 7] += weight * nz * nz;
  q[o + 8] += weight * nz * d;
  q[o + 9] += weight * d * d;
}

/**
 * Writes the sum of the quadrics at `oa` and `ob` of `q` to `out` at `o` (which may be `oa`).
 * Spelled out: decimation sums a few million pairs, and a loop over the numbers took a sixth longer.
 */
export function sumQuadrics(q: Float64Array, oa: number, ob: number, out: Float64Array, o: number): void {
  out[o] = q[oa] + q[ob];
  out[o + 1] = q[oa + 1] + q[ob + 1];
  out[o + 2] = q[oa + 2] + q[ob + 2];
  out[o + 3] = q[oa + 3] + q[ob + 3];
  out[o + 4] = q[oa + 4] + q[ob + 4];
  out[o + 5] = q[oa + 5] + q[ob + 5];
  out[o + 6] = q[oa + 6] + q[ob + 6];
  out[o + 7] = q[oa + 7] + q[ob + 7];
  out[o + 8] = q[oa + 8] + q[ob + 8];
  out[o + 9] = q[oa + 9] + q[ob + 9];
  out[o + AREA] = q[oa + AREA] + q[ob + AREA];
}

/** The quadric at `o` evaluated at (x, y, z): the weighted sum of squared distances, ≥ 0. */
export function quadricError(q: Float64Array, o: number, x: number, y: number, z: number): number {
  const error =
    q[o] * x * x +
    2 * q[o + 1] * x * y +
    2 * q[o + 2] * x * z +
    q[o + 4] * y * y +
    2 * q[o + 5] * y * z +
    q[o + 7] * z * z +
    2 * (q[o + 3] * x + q[o + 6] * y + q[o + 8] * z) +
    q[o + 9];
  return error > 0 ? error : 0; // rounding may leave a tiny negative
}

/**
 * Writes into `out` the point where the quadric at `o` is smallest and returns true, or returns
 * false when the planes do not hold a point firmly (see CONDITION).
 */
export function optimalPoint(q: Float64Array, o: number, out: Float64Array): boolean {
  const xx = q[o];
  const xy = q[o + 1];
  const xz = q[o + 2];
  const yy = q[o + 4];
  const yz = q[o + 5];
  const zz = q[o + 7];
  // cofactors of A (symmetric, so the adjugate is too)
  const cxx = yy * zz - yz * yz;
  const cxy = xz * yz - xy * zz;
  const cxz = xy * yz - xz * yy;
  const det = xx * cxx + xy * cxy + xz * cxz;
  const mean = (xx + yy + zz) / 3;
  if (!(det > CONDITION * mean * mean * mean)) return false;
  const cyy = xx * zz - xz * xz;
  const cyz = xy * xz - xx * yz;
  const czz = xx * yy - xy * xy;
  // x = A⁻¹ (−b) = adj(A) (−b) / det
  const bx = -q[o + 3];
  const by = -q[o + 6];
  const bz = -q[o + 8];
  out[0] = (cxx * bx + cxy * by + cxz * bz) / det;
  out[1] = (cxy * bx + cyy * by + cyz * bz) / det;
  out[2] = (cxz * bx + cyz * by + czz * bz) / det;
  return true;
}
