/**
 * Stencils: each scheme places a vertex at a weighted sum of old vertices nearby (its *stencil*),
 * with weights that add up to 1, so that moving or scaling the mesh first gives the same result.
 *
 * Like pmp-library, a scheme computes all its new values from the old mesh before it changes any
 * pointer (the old one-rings are easy to walk then, and the old positions are still in place), and
 * stores them in the phase that shows them. The same weights apply to every vertex attribute of
 * three floats that interpolates linearly: positions, and normals or colours stored as floats. A
 * stencil function takes such values `x` (x, y, z per vertex) and returns its results, three per
 * target; its loops spell out the three components, which runs twice as fast as a loop over them.
 */
import type { Attribute, AttributeArray } from '../attributes.js';
import type { HalfedgeMesh } from '../mesh.js';
import { zeros } from '../memory.js';

/** A vertex attribute the weights apply to. */
export interface BlendedAttribute extends Attribute {
  data: Extract<AttributeArray, Float64Array | Float32Array>;
}

/**
 * True for the vertex attributes the weights apply to: three floats that interpolate linearly.
 * The others (labels, integer colours, texture coordinates) keep their value on old vertices and
 * take one source's on new ones.
 */
export function isBlended(attribute: Attribute): attribute is BlendedAttribute {
  const { data } = attribute;
  return attribute.interpolation === 'linear' && attribute.itemSize === 3 && (data instanceof Float64Array || data instanceof Float32Array);
}

/** The vertex attributes the weights apply to, positions first. */
export function blendedAttributes(mesh: HalfedgeMesh): BlendedAttribute[] {
  const position = mesh.vertexAttributes.get('position') as BlendedAttribute;
  return [position, ...[...mesh.vertexAttributes].filter((a) => a !== position).filter(isBlended)];
}

/** Stores per-vertex results (three numbers each) as the values of vertices `first, first + 1, …`. */
export function storeValues(attributes: BlendedAttribute[], values: Float64Array[], first: number): void {
  attributes.forEach((attribute, i) => attribute.data.set(values[i], 3 * first));
}

/** `out[o … o + 3) += w · x[3v … 3v + 3)`: one term of a stencil. */
export function addScaled(out: Float64Array, o: number, x: ArrayLike<number>, v: number, w: number): void {
  out[o] += w * x[3 * v];
  out[o + 1] += w * x[3 * v + 1];
  out[o + 2] += w * x[3 * v + 2];
}

/**
 * The sum of the neighbours' values of vertices `0 … vertices − 1` and their number, edge by edge:
 * a pass in memory order, where walking each one-ring would jump around the arrays. Given
 * `firstFacePoint`, each vertex also adds the values of the points of its faces (vertex
 * `firstFacePoint + f` for face f): a face around v is the face of exactly one halfedge leaving v.
 */
export function neighbourSums(
  mesh: HalfedgeMesh,
  x: ArrayLike<number>,
  vertices: number,
  firstFacePoint = -1,
): { sums: Float64Array; valence: Int32Array } {
  const { heVertex, heFace } = mesh;
  const sums = zeros(Float64Array, 3 * vertices);
  const valence = zeros(Int32Array, vertices);
  for (let e = 0; e < mesh.edgeSlots; e++) {
    const a = heVertex[2 * e];
    const b = heVertex[2 * e + 1];
    valence[a]++;
    valence[b]++;
    const pa = 3 * a;
    const pb = 3 * b;
    sums[pa] += x[pb];
    sums[pa + 1] += x[pb + 1];
    sums[pa + 2] += x[pb + 2];
    sums[pb] += x[pa];
    sums[pb + 1] += x[pa + 1];
    sums[pb + 2] += x[pa + 2];
    if (firstFacePoint < 0) continue;
    const fa = heFace[2 * e]; // the face of the halfedge leaving a
    const fb = heFace[2 * e + 1]; // … and of the one leaving b
    if (fa !== -1) {
      const p = 3 * (firstFacePoint + fa);
      sums[pa] += x[p];
      sums[pa + 1] += x[p + 1];
      sums[pa + 2] += x[p + 2];
    }
    if (fb !== -1) {
      const p = 3 * (firstFacePoint + fb);
      sums[pb] += x[p];
      sums[pb + 1] += x[p + 1];
      sums[pb + 2] += x[p + 2];
    }
  }
  return { sums, valence };
}

/**
 * The face point stencil: the mean of the corners of the i-th listed face (or of face i, for
 * every face), written to `out` as the values of vertex `first + i`. Only corners numbered below
 * `oldVertices` count (√3's triangles on the boundary have new ones by then).
 */
export function faceCentroids(
  mesh: HalfedgeMesh,
  faces: Int32Array | 'all',
  x: ArrayLike<number>,
  out: Float64Array | Float32Array,
  first: number,
  oldVertices = Infinity,
): void {
  const count = faces === 'all' ? mesh.faceSlots : faces.length;
  const { heNext, heVertex, fHalfedge } = mesh;
  for (let i = 0; i < count; i++) {
    const start = fHalfedge[faces === 'all' ? i : faces[i]];
    let sumX = 0;
    let sumY = 0;
    let sumZ = 0;
    let degree = 0;
    let h = start;
    do {
      if (heVertex[h] < oldVertices) {
        const v = 3 * heVertex[h];
        sumX += x[v];
        sumY += x[v + 1];
        sumZ += x[v + 2];
        degree++;
      }
      h = heNext[h];
    } while (h !== start);
    const o = 3 * (first + i);
    out[o] = sumX / degree;
    out[o + 1] = sumY / degree;
    out[o + 2] = sumZ / degree;
  }
}

/**
 * The boundary rule of Loop and Catmull-Clark for an old vertex `v` on the boundary, written to
 * `out[3v …]`: 3/4 of itself and 1/8 of each neighbour along the boundary, the cubic B-spline of
 * the boundary polygon, so the boundary of the limit surface depends on the boundary alone and two
 * meshes sharing it stay joined. A corner of valence 2 (one face) keeps its place, or an open quad
 * would round off.
 */
export function boundaryVertexRule(mesh: HalfedgeMesh, x: ArrayLike<number>, v: number, out: Float64Array): void {
  const h = mesh.vHalfedge[v]; // v's outgoing boundary halfedge
  const o = 3 * v;
  if (mesh.vertexDegree(v) === 2) {
    out[o] = x[o];
    out[o + 1] = x[o + 1];
    out[o + 2] = x[o + 2];
    return;
  }
  const next = 3 * mesh.heVertex[h ^ 1]; // the next vertex along the boundary
  const prev = 3 * mesh.heVertex[mesh.hePrev[h]]; // the one before
  out[o] = (3 / 4) * x[o] + (x[next] + x[prev]) / 8;
  out[o + 1] = (3 / 4) * x[o + 1] + (x[next + 1] + x[prev + 1]) / 8;
  out[o + 2] = (3 / 4) * x[o + 2] + (x[next + 2] + x[prev + 2]) / 8;
}

/**
 * The even rule shared by Loop and Catmull-Clark, for old vertices `0 … count − 1` given the
 * `sums` and `valence` of `neighbourSums`: an isolated vertex stays put, a boundary vertex follows
 * `boundaryVertexRule`, and an interior vertex with n neighbours moves to
 * `self(n) · itself + ring(n) · sum`. Writes over `sums`, and returns it.
 */
export function moveOldVertices(
  mesh: HalfedgeMesh,
  x: ArrayLike<number>,
  count: number,
  { sums: out, valence }: { sums: Float64Array; valence: Int32Array },
  weights: (n: number) => { self: number; ring: number },
): Float64Array {
  const { heFace, vHalfedge } = mesh;
  // the weights depend on the valence only: work them out once per valence
  const selfOf: number[] = [];
  const ringOf: number[] = [];
  for (let v = 0; v < count; v++) {
    const o = 3 * v;
    const start = vHalfedge[v];
    // isolated vertex?
    if (start === -1) {
      out[o] = x[o];
      out[o + 1] = x[o + 1];
      out[o + 2] = x[o + 2];
    }
    // boundary vertex?
    else if (heFace[start] === -1) {
      boundaryVertexRule(mesh, x, v, out);
    }
    // interior vertex
    else {
      const n = valence[v];
      if (selfOf[n] === undefined) ({ self: selfOf[n], ring: ringOf[n] } = weights(n));
      const self = selfOf[n];
      const ring = ringOf[n];
      out[o] = self * x[o] + ring * out[o];
      out[o + 1] = self * x[o + 1] + ring * out[o + 1];
      out[o + 2] = self * x[o + 2] + ring * out[o + 2];
    }
  }
  return out;
}
