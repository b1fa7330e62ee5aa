/**
 * Modified Butterfly subdivision (Zorin, Schröder and Sweldens, 1996), for triangle meshes. It is
 * *interpolating*: the old vertices never move, and only the new edge points are placed by
 * stencils, so the limit surface passes through every vertex of every level. The topology is
 * Loop's (each triangle becomes four); only the weights differ.
 *
 * The edge point of edge ab depends on its ends. An end is *regular* when it is an interior vertex
 * with 6 neighbours or a boundary vertex with 4 (three triangles); a boundary vertex with n
 * neighbours spans k = n − 1 triangles. Between two interior vertices:
 * - both regular: the ten-point butterfly,
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
 * - both ends extraordinary: the mean of the two extraordinary stencils.
 *
 * On and next to the boundary, the rules of Zorin and Schröder (*Subdivision for Modeling and
 * Animation*, SIGGRAPH 2000 course notes, ch. 4), with the weights that open implementations
 * (vcglib, MESH, jMonkeyEngine) transcribe alike:
 * 1. a boundary edge ab: the four-point rule 9/16 (a + b) − 1/16 (a′ + b′), where a′ and b′ are the
 *    next boundary vertices beyond a and b (one and the same on a boundary of three vertices), so
 *    the boundary is refined as a curve of its own, from the boundary alone;
 * 2. an interior edge from a regular boundary vertex B to a regular interior vertex I
 *    ("interior–crease"):
 *    ```
 *                   q
 *                 ╱ │        3/8 B, 5/8 I, 1/16 b_a, 3/16 x, −1/16 b_c, −1/16 p, −1/8 q, where
 *         p ── I ── x        b_a is B's boundary neighbour in a triangle with I, x the corner of
 *         │  ╱ │  ╱ │        the other triangle, p the vertex across side I–b_a and q the one
 *        b_a ─ B ─ b_c       across side I–x (I's sixth neighbour gets 0);
 *    ```
 *    the stencil is not symmetric: with p and q swapped it would not even reproduce planes;
 * 3. an interior edge lr between two regular boundary vertices ("crease–crease"): the notes' rule 1
 *    when the third corner e of one of its triangles is a corner of the boundary (2 neighbours),
 *    ```
 *                   c
 *                 ╱ │        1/2 l, 1/2 r, 1/4 d, −1/8 a, −1/8 c (0 for e), where a and c are
 *              d ── r        the boundary neighbours of l and of r other than e;
 *            ╱ │  ╱ │
 *         a ── l ── e
 *    ```
 *    and the midpoint 1/2 l + 1/2 r in the other configurations, where the transcriptions differ;
 * 4. an interior edge at a boundary vertex v that is not regular ("extraordinary crease"), to v's
 *    neighbour i, the neighbours numbered 0 … k from one boundary neighbour to the other, θ = π/k:
 *    1 − sin θ sin iθ / (k(1 − cos θ)) for v; c_0 = ¼cos iθ − sin 2θ sin 2iθ / (4k(cos θ − cos 2θ))
 *    for neighbour 0 and −c_0 for neighbour k; (sin iθ sin jθ + ½ sin 2iθ sin 2jθ)/k for neighbour
 *    j in between. These are the corrected weights (Attene et al.): the notes' printed ones do not
 *    sum to 1; these do, and reproduce linear functions;
 * 5. mixed ends, as between interior vertices: when one end is regular, the other end's stencil
 *    alone (an interior one's s_j, or rule 4); when neither is, the mean of the two. So an edge from
 *    a regular boundary vertex to an extraordinary boundary vertex takes rule 4 alone: a case the
 *    transcriptions leave out, decided by the same logic.
 *
 * Degenerate ends take the midpoint's share (1/2 for each end of the edge) in place of a stencil:
 * an interior vertex of valence below 3 (only a degenerate closed mesh has one), and a boundary
 * vertex with fewer than 3 neighbours, which a valid mesh never puts at an interior edge (a corner
 * of one triangle has two boundary edges). Every stencil's weights sum to 1, so planes and affine
 * maps are reproduced everywhere.
 *
 * Phases: split every edge · cut the corners · place the edge points.
 * Counts after one level, as Loop: V' = V + E, E' = 2E + 3F, F' = 4F.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { zeros } from '../memory.js';
import type { Operation } from '../change/operation.js';
import { levelOperation, type SchemeLevel } from './level.js';
import { cutEveryCorner, loopLevel, splitEveryEdge } from './loop.js';
import { addScaled } from './stencil.js';

/**
 * One level of Modified Butterfly subdivision, as a steppable operation that edits `mesh` in place.
 * @example runOperation(butterflySubdivision(mesh)); // F → 4F triangles through the same vertices
 * @throws TopologyError when a face is not a triangle (nothing is changed).
 */
export function butterflySubdivision(mesh: HalfedgeMesh): Operation {
  return levelOperation(mesh, butterflyLevel);
}

/** A level of Butterfly subdivision, for `level.ts` to run: Loop's topology, the edge points by the butterfly stencil. */
export const butterflyLevel: SchemeLevel = {
  scheme: 'butterfly',
  counts: loopLevel.counts,
  edgePoints: butterflyEdgePoints,
  phases: [
    {
      name: 'split every edge',
      explanation:
        'Each edge gets a new vertex at its midpoint, so every triangle becomes a hexagon whose corners alternate between old and new vertices. ' +
        'Butterfly refines the mesh exactly as Loop does; only where the new points go differs.',
      topology: splitEveryEdge,
    },
    {
      name: 'cut the corners',
      explanation:
        'Three new edges join the edge points of each face, cutting off its corners: one triangle becomes four. ' +
        'The surface is still the old flat one, with every old vertex where it was.',
      topology: cutEveryCorner,
    },
    {
      name: 'place the edge points',
      explanation:
        'Each edge point moves by the butterfly stencil: 1/2 of the edge’s ends, 1/8 of the two facing corners and ' +
        '−1/16 of the four wing vertices (other weights near vertices without six neighbours and next to the boundary, which is refined by a four-point rule of its own). ' +
        'The old vertices never move, so every level passes through the points of the level before: the scheme interpolates.',
      moves: 'edge points',
    },
  ],
};

/**
 * The new point of each edge e, three numbers per edge, written to `points` as the values of
 * vertex `first + e`. The rules add up their terms in `out`, zeros in doubles of its own, so an
 * attribute of 32-bit floats is rounded once.
 */
function butterflyEdgePoints(mesh: HalfedgeMesh, x: ArrayLike<number>, points: Float64Array | Float32Array, first: number): void {
  const { heNext, hePrev, heVertex, heFace, vHalfedge } = mesh;
  const E = mesh.edgeSlots;
  const out = zeros(Float64Array, 3 * E);
  const valence = zeros(Int32Array, mesh.vertexSlots);
  for (let h = 0; h < 2 * E; h++) valence[heVertex[h]]++;
  // a boundary vertex's halfedge is its outgoing boundary one
  const onBoundary = (v: number) => heFace[vHalfedge[v]] === -1;
  const regular = (v: number) => valence[v] === (onBoundary(v) ? 4 : 6);
  /** The vertex across side g of g's triangle: the third corner of the triangle on the other side. */
  const across = (g: number) => heVertex[hePrev[g ^ 1]];
  /** The boundary neighbour of boundary vertex v other than w. */
  const otherAlongBoundary = (v: number, w: number) => {
    const next = heVertex[vHalfedge[v] ^ 1];
    return next === w ? heVertex[hePrev[vHalfedge[v]]] : next;
  };
  let o = 0;

  /** `scale` × the midpoint of the edge of h: the share of an end without a stencil. */
  const midpoint = (h: number, scale: number) => {
    addScaled(out, o, x, heVertex[h], scale / 2);
    addScaled(out, o, x, heVertex[h ^ 1], scale / 2);
  };
  /** The ten-point butterfly around the edge of h, between two regular interior vertices. */
  const tenPoint = (h: number) => {
    const t = h ^ 1;
    addScaled(out, o, x, heVertex[h], 1 / 2);
    addScaled(out, o, x, heVertex[t], 1 / 2);
    addScaled(out, o, x, heVertex[hePrev[h]], 1 / 8);
    addScaled(out, o, x, heVertex[hePrev[t]], 1 / 8);
    addScaled(out, o, x, across(heNext[h]), -1 / 16);
    addScaled(out, o, x, across(hePrev[h]), -1 / 16);
    addScaled(out, o, x, across(heNext[t]), -1 / 16);
    addScaled(out, o, x, across(hePrev[t]), -1 / 16);
  };
  /** Rule 2 for the edge of h from a regular boundary vertex B = origin(h) to a regular interior vertex I. */
  const interiorCrease = (h: number) => {
    const t = h ^ 1;
    const B = heVertex[h];
    // the triangles B → I → y and I → B → z: b_a is y when the edge B–y is a boundary edge, else z
    const y = heVertex[hePrev[h]];
    const z = heVertex[hePrev[t]];
    const yIsBa = heFace[hePrev[h] ^ 1] === -1;
    const ba = yIsBa ? y : z;
    addScaled(out, o, x, B, 3 / 8);
    addScaled(out, o, x, heVertex[t], 5 / 8);
    addScaled(out, o, x, ba, 1 / 16);
    addScaled(out, o, x, yIsBa ? z : y, 3 / 16); // x
    addScaled(out, o, x, otherAlongBoundary(B, ba), -1 / 16); // b_c
    addScaled(out, o, x, across(yIsBa ? heNext[h] : hePrev[t]), -1 / 16); // p, across the side I–b_a
    addScaled(out, o, x, across(yIsBa ? hePrev[t] : heNext[h]), -1 / 8); // q, across the side I–x
  };
  /** A corner of the boundary: a boundary vertex with 2 neighbours (one triangle). */
  const corner = (v: number) => valence[v] === 2 && onBoundary(v);
  /**
   * The edge of h between two regular boundary vertices l and r: rule 1 of the notes when a
   * triangle of the edge has a corner of the boundary e as its third corner, the midpoint otherwise.
   */
  const creaseCrease = (h: number) => {
    const t = h ^ 1;
    const y = heVertex[hePrev[h]];
    const z = heVertex[hePrev[t]];
    const e = corner(y) ? y : corner(z) ? z : -1;
    if (e === -1) {
      midpoint(h, 1);
      return;
    }
    const l = heVertex[h];
    const r = heVertex[t];
    addScaled(out, o, x, l, 1 / 2);
    addScaled(out, o, x, r, 1 / 2);
    addScaled(out, o, x, e === y ? z : y, 1 / 4); // d
    addScaled(out, o, x, otherAlongBoundary(l, e), -1 / 8); // a
    addScaled(out, o, x, otherAlongBoundary(r, e), -1 / 8); // c
  };
  /** `scale` × the stencil of the interior extraordinary end v = origin(h) of the edge of h. */
  const extraordinary = (h: number, scale: number) => {
    const v = heVertex[h];
    const K = valence[v];
    if (K < 3) {
      midpoint(h, scale);
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
  /** `scale` × rule 4 for the edge of h at the boundary vertex v = origin(h), which has k + 1 neighbours. */
  const extraordinaryCrease = (h: number, scale: number) => {
    const v = heVertex[h];
    const k = valence[v] - 1;
    // turning counter-clockwise from h, k − i steps reach v's boundary halfedge, to neighbour k
    let g = h;
    let steps = 0;
    while (heFace[g] !== -1 && steps < k) {
      g = hePrev[g] ^ 1;
      steps++;
    }
    const i = k - steps;
    // k < 2 (or a rotation without a boundary halfedge): not an interior edge of a valid mesh
    if (heFace[g] !== -1 || i < 1 || i >= k) {
      midpoint(h, scale);
      return;
    }
    const weights = creaseWeights(k);
    addScaled(out, o, x, v, scale * creaseWeight(weights, i, -1));
    g = hePrev[g] ^ 1; // v → neighbour 0, across the hole
    for (let j = 0; j <= k; j++) {
      addScaled(out, o, x, heVertex[g ^ 1], scale * creaseWeight(weights, i, j));
      g = hePrev[g] ^ 1;
    }
  };
  /** `scale` × the stencil of the end origin(h) that is not regular: rule 4 on the boundary. */
  const endStencil = (h: number, scale: number) => {
    if (onBoundary(heVertex[h])) extraordinaryCrease(h, scale);
    else extraordinary(h, scale);
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
    // interior edge: by its ends, regular or not
    const a = heVertex[h];
    const b = heVertex[t];
    const aRegular = regular(a);
    const bRegular = regular(b);
    // both regular: the ten-point butterfly, rule 2, or rule 3 (crease–crease: the notes' rule 1
    // beside a corner of the boundary, the midpoint otherwise)
    if (aRegular && bRegular) {
      const aBoundary = onBoundary(a);
      const bBoundary = onBoundary(b);
      if (!aBoundary && !bBoundary) tenPoint(h);
      else if (!bBoundary) interiorCrease(h);
      else if (!aBoundary) interiorCrease(t);
      else creaseCrease(h);
    }
    // one regular: the other end's stencil alone; so a boundary end that is not regular takes
    // rule 4 alone even beside a regular boundary vertex (the transcriptions leave that case out)
    else if (bRegular) endStencil(h, 1);
    else if (aRegular) endStencil(t, 1);
    // neither: the mean of the two stencils
    else {
      endStencil(h, 1 / 2);
      endStencil(t, 1 / 2);
    }
  }
  points.set(out, 3 * first);
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

/**
 * What rule 4's weights at a boundary vertex of k sectors are made of, θ = π/k: sin jθ, sin 2jθ
 * and cos jθ for j = 0 … k, and the factors of v's weight and of c_0. A weight is a product or two
 * of these, so a vertex of many sectors costs memory in proportion to k, not k².
 */
export interface CreaseWeights {
  k: number;
  sin: Float64Array;
  sin2: Float64Array;
  cos: Float64Array;
  /** sin θ / (k(1 − cos θ)): v's weight is 1 − self · sin iθ. */
  self: number;
  /** sin 2θ / (4k(cos θ − cos 2θ)): c_0 = ¼cos iθ − end · sin 2iθ. */
  end: number;
}

const creaseWeightsBySectors: CreaseWeights[] = [];

/** Rule 4's factors for a boundary vertex of k ≥ 2 sectors (k + 1 neighbours), worked out once per k. */
export function creaseWeights(k: number): CreaseWeights {
  let weights = creaseWeightsBySectors[k];
  if (weights) return weights;
  const theta = Math.PI / k;
  const sin = new Float64Array(k + 1);
  const sin2 = new Float64Array(k + 1);
  const cos = new Float64Array(k + 1);
  for (let j = 0; j <= k; j++) {
    sin[j] = Math.sin(j * theta);
    sin2[j] = Math.sin(2 * j * theta);
    cos[j] = Math.cos(j * theta);
  }
  const self = Math.sin(theta) / (k * (1 - Math.cos(theta)));
  const end = Math.sin(2 * theta) / (4 * k * (Math.cos(theta) - Math.cos(2 * theta)));
  weights = { k, sin, sin2, cos, self, end };
  creaseWeightsBySectors[k] = weights;
  return weights;
}

/**
 * Rule 4's weight, for the edge to neighbour i (0 < i < k), of neighbour j (0 … k, numbered from
 * one boundary neighbour to the other), or of the vertex itself for j = −1.
 */
export function creaseWeight({ k, sin, sin2, cos, self, end }: CreaseWeights, i: number, j: number): number {
  if (j < 0) return 1 - self * sin[i];
  if (j === 0 || j === k) {
    const c0 = cos[i] / 4 - end * sin2[i];
    return j === 0 ? c0 : -c0;
  }
  return (sin[i] * sin[j] + (sin2[i] * sin2[j]) / 2) / k;
}
