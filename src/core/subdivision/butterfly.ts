/**
 * Modified Butterfly subdivision (Zorin, Schröder and Sweldens, 1996), for triangle meshes. It is
 * *interpolating*: the old vertices never move, and only the new edge points are placed by
 * stencils, so the limit surface passes through every vertex of every level. The topology is
 * Loop's (each triangle becomes four); only the weights differ.
 *
 * The edge point of edge ab, by the valences (numbers of neighbours) of a and b:
 * - both interior with valence 6: the ten-point butterfly,
 *   ```
 *        w ─── c ─── w         1/2 for a and b, 1/8 for the corners c, d facing the edge,
 *         ╲   ╱ ╲   ╱          −1/16 for the four "wing" vertices w across the triangles' other
 *          a ───── b           sides;
 *         ╱   ╲ ╱   ╲
 *        w ─── d ─── w
 *   ```
 * - one end extraordinary (valence K ≠ 6), the other regular: 3/4 of the extraordinary end v plus
 *   s_j of its neighbours v_0 … v_(K−1), counter-clockwise from v_0 = the other end, with
 *   K = 3: 5/12, −1/12, −1/12; K = 4: 3/8, 0, −1/8, 0; K ≥ 5: s_j = (1/4 + cos(2πj/K) + ½cos(4πj/K))/K;
 * - both ends extraordinary: the mean of the two extraordinary stencils;
 * - a boundary edge: the four-point curve rule −1/16, 9/16, 9/16, −1/16 along the boundary, so the
 *   boundary is refined as a curve of its own.
 *
 * Interior edges touching the boundary need a rule for one-rings that are cut open. The one used
 * here: when exactly one end is interior, that end's stencil above (any valence, 6 included),
 * because its whole one-ring exists; when both ends lie on the boundary, the ten-point butterfly,
 * with each wing that would lie beyond the boundary replaced by its mirror image (for the missing
 * wing across side xy of a triangle xyz: x + y − z). Both keep the weights' sum at 1, so planes and
 * affine maps are still reproduced. (Zorin's thesis gives a finer case analysis of these edges.)
 * An interior vertex of valence below 3 (only a degenerate closed mesh has one) contributes the
 * plain midpoint.
 *
 * Phases: split every edge · cut the corners · place the edge points.
 * Counts after one level, as Loop: V' = V + E, E' = 2E + 3F, F' = 4F.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { zeros } from '../memory.js';
import type { Operation } from '../operation.js';
import { compactAtOnce, requireApplicable, startLevel } from './preconditions.js';
import { addScaled, blendedAttributes, storeValues } from './stencil.js';
import { growForLevel, handOver } from './helper-thread.js';
import { loopSteps } from './loop.js';
import { range } from './topology.js';

/**
 * One level of Modified Butterfly subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(butterflySubdivision(mesh)); // F → 4F triangles through the same vertices
 * @throws TopologyError when a face is not a triangle (nothing is changed).
 */
export function butterflySubdivision(mesh: HalfedgeMesh): Operation {
  requireApplicable(mesh, 'butterfly');
  compactAtOnce(mesh);
  return butterflyLevel(mesh, true);
}

/** The phases of one level; `listIds` false leaves the phases' id lists out (a run straight through). */
export function* butterflyLevel(mesh: HalfedgeMesh, listIds: boolean): Operation {
  startLevel(mesh);
  const V = mesh.vertexSlots;
  const E = mesh.edgeSlots;
  const F = mesh.faceSlots;

  // reserve memory; straight through, a helper thread (when there is one) does Loop's topology
  // steps in the new arrays while this one works out the edge points from the old ones
  const { helper, old } = growForLevel(mesh, listIds, { vertices: V + E, edges: 2 * E + 3 * F, faces: 4 * F });
  const handed = handOver(helper, mesh, 'loop', V);

  // compute the edge points while the old one-rings are intact
  const attributes = blendedAttributes(mesh);
  const edgePoints = attributes.map((a) => butterflyEdgePoints(old, a.data));
  const step = handed.take(loopSteps, listIds);

  // split edges
  yield {
    name: 'split every edge',
    explanation:
      'Each edge gets a new vertex at its midpoint, so every triangle becomes a hexagon whose corners alternate between old and new vertices. ' +
      'Butterfly refines the mesh exactly as Loop does; only where the new points go differs.',
    ...step(0),
  };

  // split faces
  yield {
    name: 'cut the corners',
    explanation:
      'Three new edges join the edge points of each face, cutting off its corners: one triangle becomes four. ' +
      'The surface is still the old flat one, with every old vertex where it was.',
    ...step(1),
  };

  // place the new vertices
  storeValues(attributes, edgePoints, V);
  yield {
    name: 'place the edge points',
    explanation:
      'Each edge point moves by the butterfly stencil: 1/2 of the edge’s ends, 1/8 of the two facing corners and ' +
      '−1/16 of the four wing vertices (other weights near vertices without six neighbours, a four-point rule on the boundary). ' +
      'The old vertices never move, so every level passes through the points of the level before: the scheme interpolates.',
    moved: { vertices: range(listIds, V, V + E) },
  };
}

/** The new point of each edge e, three numbers per edge, in edge order. */
function butterflyEdgePoints(mesh: HalfedgeMesh, x: ArrayLike<number>): Float64Array {
  const { heNext, hePrev, heVertex, heFace, vHalfedge } = mesh;
  const E = mesh.edgeSlots;
  const out = zeros(Float64Array, 3 * E);
  const valence = zeros(Int32Array, mesh.vertexSlots);
  for (let h = 0; h < 2 * E; h++) valence[heVertex[h]]++;
  const interior = (v: number) => heFace[vHalfedge[v]] !== -1;
  let o = 0;

  /** The ten-point butterfly around the edge of h; a wing beyond the boundary is mirrored. */
  const tenPoint = (h: number) => {
    const t = h ^ 1;
    const a = heVertex[h];
    const b = heVertex[t];
    addScaled(out, o, x, a, 1 / 2);
    addScaled(out, o, x, b, 1 / 2);
    addScaled(out, o, x, heVertex[hePrev[h]], 1 / 8);
    addScaled(out, o, x, heVertex[hePrev[t]], 1 / 8);
    wing(heNext[h], a);
    wing(hePrev[h], b);
    wing(heNext[t], b);
    wing(hePrev[t], a);
  };
  /** −1/16 of the vertex across side g of a triangle whose third corner is `opposite`. */
  const wing = (g: number, opposite: number) => {
    const across = g ^ 1;
    if (heFace[across] !== -1) {
      addScaled(out, o, x, heVertex[hePrev[across]], -1 / 16);
      return;
    }
    // no triangle there: mirror the opposite corner across the side
    addScaled(out, o, x, heVertex[g], -1 / 16);
    addScaled(out, o, x, heVertex[across], -1 / 16);
    addScaled(out, o, x, opposite, 1 / 16);
  };
  /** `scale` × the stencil of the extraordinary end v = origin(h) of the edge of h. */
  const extraordinary = (h: number, scale: number) => {
    const v = heVertex[h];
    const K = valence[v];
    // degenerate valence: the midpoint
    if (K < 3) {
      addScaled(out, o, x, v, scale / 2);
      addScaled(out, o, x, heVertex[h ^ 1], scale / 2);
      return;
    }
    const s = extraordinaryWeights(K);
    addScaled(out, o, x, v, (3 / 4) * scale);
    let g = h;
    for (let j = 0; j < K; j++) {
      addScaled(out, o, x, heVertex[g ^ 1], s[j] * scale);
      g = hePrev[g] ^ 1;
    }
  };

  for (let e = 0; e < E; e++) {
    const h = 2 * e;
    const t = h + 1;
    o = 3 * e;
    // boundary edge: the four-point rule along the boundary halfedge g (u → w)
    if (heFace[h] === -1 || heFace[t] === -1) {
      const g = heFace[h] === -1 ? h : t;
      addScaled(out, o, x, heVertex[g], 9 / 16);
      addScaled(out, o, x, heVertex[heNext[g]], 9 / 16);
      addScaled(out, o, x, heVertex[hePrev[g]], -1 / 16);
      addScaled(out, o, x, heVertex[heNext[heNext[g]]], -1 / 16);
      continue;
    }
    const a = heVertex[h];
    const b = heVertex[t];
    const aInterior = interior(a);
    const bInterior = interior(b);
    // interior edge with both ends interior: by valence
    if (aInterior && bInterior) {
      if (valence[a] === 6 && valence[b] === 6) tenPoint(h);
      else if (valence[b] === 6) extraordinary(h, 1);
      else if (valence[a] === 6) extraordinary(t, 1);
      else {
        extraordinary(h, 1 / 2);
        extraordinary(t, 1 / 2);
      }
    }
    // one end on the boundary: the other end's one-ring is whole
    else if (aInterior) extraordinary(h, 1);
    else if (bInterior) extraordinary(t, 1);
    // both ends on the boundary
    else tenPoint(h);
  }
  return out;
}

const weightsByValence: Float64Array[] = [];

/** Zorin's weights s_0 … s_(K−1) of the neighbours of an extraordinary vertex of valence K ≥ 3. */
function extraordinaryWeights(K: number): Float64Array {
  let s = weightsByValence[K];
  if (s) return s;
  s = new Float64Array(K);
  if (K === 3) s.set([5 / 12, -1 / 12, -1 / 12]);
  else if (K === 4) s.set([3 / 8, 0, -1 / 8, 0]);
  else {
    for (let j = 0; j < K; j++) {
      const angle = (2 * Math.PI * j) / K;
      s[j] = (1 / 4 + Math.cos(angle) + Math.cos(2 * angle) / 2) / K;
    }
  }
  weightsByValence[K] = s;
  return s;
}
