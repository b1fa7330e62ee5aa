/**
 * Face collapse: face f of k corners shrinks to one vertex m at its centroid. Its corners merge
 * into m (v_0 survives as m), its k edges and f itself go, and each face g_i across side i loses
 * that side: a face of four or more sides keeps the rest, a triangle disappears, and its two other
 * edges, which now join the same two vertices, become one.
 *
 * ```
 *          x3                 x2                      x3                 x2
 *            ╲       g2      ╱                          ╲       g2      ╱
 *              v3 ───────── v2                            ╲           ╱
 *              │            │                               ╲       ╱
 *       g3     │     f      │     g1        ──►       g3        m         g1
 *              │            │                               ╱       ╲
 *              v0 ───────── v1                            ╱           ╲
 *            ╱       g0      ╲                          ╱       g0      ╲
 *          x0                 x1                      x0                 x1
 * ```
 * Counts, with T the number of triangles beside f: k − 1 vertices, k + T edges and 1 + T faces
 * fewer; the Euler characteristic does not change.
 *
 * Around m, the halfedges that left the corners (other than f's own edges) come one corner after
 * the other, counter-clockwise, and where a triangle beside f vanishes the two on either side of
 * it become one. The collapse is refused (`canCollapseFace` says why) when that ring would not be
 * a disk's (or, on the boundary, a half-disk's), the link condition of an edge collapse, for a
 * whole face:
 *   - a face along several sides of f left with fewer than 3 (a face along a run of sides, whose
 *     corners between them have only those two edges, such as a split edge's point, loses the
 *     whole run; along two runs apart, it would pass m twice, as below);
 *   - an edge between two corners of f that is not a side of f: it would become a loop at m;
 *   - a vertex joined to two corners, other than the far corner of a triangle beside f (whose two
 *     edges merge): it would be joined to m twice;
 *   - a face, other than those beside f, with corners at two corners of f (or the same face at
 *     two places around m): it would pass through m twice;
 *   - the boundary at two places around f (a hole along two sides that do not follow each other,
 *     or one touching a corner): the surface would be pinched at m; a hole along one run of
 *     consecutive sides (a corner of a grid) is fine, and simply loses those sides;
 *   - triangles on every side of f meeting at one vertex (a tetrahedron, a pyramid): all that
 *     would be left is one edge with no face; nor may m be left with a single edge;
 *   - two triangles left on m and two neighbours (a face of a triangular bipyramid): the part
 *     would flatten into two triangles on the same three corners, which the edge collapse
 *     refuses too;
 *   - f on its own (a part of the mesh with no other face): there is nothing to collapse into.
 * Each check is a walk around the corners or the faces beside f: the work is O(the sum of the
 * corners' degrees and of those faces' sides).
 *
 * Attributes: m takes the average of the corners' vertex attributes (the centroid for positions).
 * Each halfedge that left a corner keeps its corner value; where a face loses sides, its corners
 * at their ends become one with the average of their values; where a triangle's two edges merge,
 * the kept one takes the value of the one it replaces (as the edge collapse does).
 */
import { faceHalfedges } from '../circulators.js';
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { replaceParallel } from './collapse.js';
import { isTriangleLoop, missingFace } from './find.js';
import { type EditOptions, PointerWriter, type VertexEditResult } from '../change/writer.js';

/** What the checks found, for the collapse to use. */
interface CollapsePlan {
  /** f's halfedges, side i from corner i to corner i + 1. */
  sides: number[];
  corners: number[];
  /** The face across each side, -1 for the hole. */
  across: number[];
  /** Whether the face across each side is a triangle (which disappears). */
  triangles: boolean[];
  /** For each corner, the halfedges leaving it other than f's two edges there, counter-clockwise. */
  spokes: number[][];
}

/**
 * Why face `f` cannot be collapsed to a vertex, or null when it can (the rules are listed above).
 * @example canCollapseFace(mesh, f) // "the triangles on every side of f0 meet at v3: …"
 */
export function canCollapseFace(mesh: HalfedgeMesh, f: number): string | null {
  const plan = planCollapse(mesh, f);
  return typeof plan === 'string' ? plan : null;
}

/**
 * Shrinks face `f` to one vertex at its centroid (see the diagram above). Returns that vertex:
 * the corner f's halfedge started from.
 * @example if (!canCollapseFace(mesh, f)) collapseFace(mesh, f);
 * @throws TopologyError with `canCollapseFace`'s sentence when the collapse does not apply.
 */
export function collapseFace(mesh: HalfedgeMesh, f: number, options: EditOptions = {}): VertexEditResult {
  const plan = planCollapse(mesh, f);
  if (typeof plan === 'string') throw new TopologyError(`collapseFace: ${plan}`);
  const { sides, corners, across, triangles, spokes } = plan;
  const k = sides.length;
  const w = new PointerWriter(mesh, options);
  const { heNext, hePrev, fHalfedge, heFace, eDeleted } = mesh; // a collapse never grows the arrays
  const m = corners[0];

  w.blend('vertex', m, corners, corners.map(() => 1 / k));
  // everything that left another corner now leaves m
  for (let i = 1; i < k; i++) for (const s of spokes[i]) w.setOrigin(s, m);
  // a face that loses sides had a corner at each end of them: one stays, with their average
  const twinsIn = new Map<number, number[]>(); // face → the twins of f's sides in it
  for (let i = 0; i < k; i++) {
    if (across[i] === -1 || triangles[i]) continue;
    const list = twinsIn.get(across[i]) ?? [];
    list.push(sides[i] ^ 1);
    twinsIn.set(across[i], list);
  }
  for (const twins of twinsIn.values()) {
    // the corner that stays: after the last twin along the face (it leaves a corner of f, now m)
    const kept = twins.map((t) => heNext[t]).find((h) => !twins.includes(h))!;
    w.blend('halfedge', kept, [kept, ...twins], [kept, ...twins].map(() => 1 / (twins.length + 1)));
  }
  // each side's twin leaves the loop across it (read afresh: a merge before may have relinked it)
  for (let i = 0; i < k; i++) {
    const t = sides[i] ^ 1;
    if (triangles[i]) {
      // a triangle (v_i+1, v_i, c): c → v_i+1 turns around to run parallel to v_i → c; one edge stays
      replaceParallel(w, hePrev[t] ^ 1, heNext[t]);
      continue;
    }
    if (across[i] !== -1 && fHalfedge[across[i]] === t) w.setFaceHalfedge(across[i], heNext[t]);
    w.link(hePrev[t], heNext[t]);
  }

  for (let i = 0; i < k; i++) w.deleteEdge(sides[i] >> 1);
  w.deleteFace(f);
  for (let i = 0; i < k; i++) if (triangles[i]) w.deleteFace(across[i]);
  for (let i = 1; i < k; i++) w.deleteVertex(corners[i]);

  // m's handle: its boundary halfedge if it has one, else any that survived
  let handle = -1;
  for (let i = 0; i < k; i++) {
    for (const s of spokes[i]) {
      if (eDeleted[s >> 1]) continue;
      if (handle === -1 || heFace[s] === -1) handle = s;
    }
  }
  w.setVertexHalfedge(m, handle);
  return { ...w.result(), vertex: m };
}

/** The sides, corners and spokes of `f`, or the sentence saying why it cannot collapse. */
function planCollapse(mesh: HalfedgeMesh, f: number): CollapsePlan | string {
  const missing = missingFace(mesh, f);
  if (missing) return missing;
  const { hePrev, heVertex, heFace } = mesh;
  const sides = [...faceHalfedges(mesh, f)];
  const k = sides.length;
  const corners = sides.map((h) => heVertex[h]);
  const across = sides.map((h) => heFace[h ^ 1]);

  // the faces along f's sides lose them all, and must keep 3
  const along = new Map<number, number>(); // face → how many sides of f it lies along
  for (const g of across) if (g !== -1) along.set(g, (along.get(g) ?? 0) + 1);
  for (const [g, count] of along) {
    const degree = mesh.faceDegree(g);
    if (count > 1 && degree - count < 3) {
      return `f${g} borders f${f} along ${count} sides and has ${degree}: collapsing f${f} would leave it ${degree - count}`;
    }
  }

  // a triangle along one side disappears, its two other edges merging
  const triangles = sides.map((h, i) => across[i] !== -1 && along.get(across[i]) === 1 && isTriangleLoop(mesh, h ^ 1));

  // the spokes of each corner: rotating from its edge to the corner before, up to its edge to the next
  const cornerSet = new Set(corners);
  const spokes: number[][] = [];
  let count = 0;
  for (let i = 0; i < k; i++) {
    const list: number[] = [];
    let s = hePrev[sides[(i + k - 1) % k] ^ 1] ^ 1;
    while (s !== sides[i]) {
      const far = heVertex[s ^ 1];
      if (cornerSet.has(far)) {
        return `v${corners[i]} and v${far}, corners of f${f}, are also joined by e${s >> 1}: collapsing f${f} would turn e${s >> 1} into a loop`;
      }
      list.push(s);
      s = hePrev[s] ^ 1;
      if (list.length > mesh.halfedgeSlots) throw new TopologyError(`the rotation around v${corners[i]} does not close`);
    }
    spokes.push(list);
    count += list.length;
  }
  if (count === 0) {
    return `f${f} is a part of the mesh on its own (no edge leads away from its corners): collapsing it would leave a lone vertex`;
  }

  // the ring around m: the spokes in order, each merged with the next across a triangle beside f
  const ring: number[] = []; // every spoke, corner after corner
  const mergesOn: boolean[] = []; // true when the spoke merges with the next one
  for (let i = 0; i < k; i++) {
    for (let j = 0; j < spokes[i].length; j++) {
      ring.push(spokes[i][j]);
      mergesOn.push(j === spokes[i].length - 1 && triangles[i]);
    }
  }
  const start = mergesOn.indexOf(false) + 1; // a group begins after a spoke that does not merge
  if (start === 0) {
    const apex = heVertex[ring[0] ^ 1];
    return `the triangles on every side of f${f} meet at v${apex}: collapsing f${f} would leave only an edge to v${apex}, with no face`;
  }
  const groupOf = new Map<number, number>(); // far vertex → the spoke that first reached it
  const wedgeAt = new Map<number, number>(); // face around m → the spoke before it
  let groups = 0;
  for (let n = 0; n < ring.length; n++) {
    const s = ring[(start + n) % ring.length];
    if (n > 0 && mergesOn[(start + n - 1) % ring.length]) continue; // merged into the group before
    groups++;
    const far = heVertex[s ^ 1];
    const first = groupOf.get(far);
    if (first !== undefined) {
      return `v${far} is joined to v${heVertex[first]} and v${heVertex[s]}, corners of f${f}, but not across a triangle beside f${f}: collapsing f${f} would join it to the new vertex twice (the link condition fails)`;
    }
    groupOf.set(far, s);
  }
  if (groups < 2) {
    return `collapsing f${f} would leave the new vertex with a single edge (to v${heVertex[ring[0] ^ 1]}), with the same face or hole on both sides`;
  }
  for (let n = 0; n < ring.length; n++) {
    const index = (start + n) % ring.length;
    if (mergesOn[index]) continue; // the triangle after this spoke vanishes: no wedge
    const s = ring[index];
    const wedge = heFace[s];
    const first = wedgeAt.get(wedge);
    if (first !== undefined) {
      return wedge === -1
        ? `the boundary meets f${f} at two places (at v${heVertex[first]} and v${heVertex[s]}): collapsing f${f} would pinch the surface at the new vertex`
        : `f${wedge} meets f${f} at two places (at v${heVertex[first]} and v${heVertex[s]}): collapsing f${f} would make f${wedge} pass through the new vertex twice`;
    }
    wedgeAt.set(wedge, s);
  }
  // two triangles left on m and its two neighbours: the part would flatten (as a tetrahedron's edge would)
  if (groups === 2) {
    const after = (g: number) => (g === -1 ? 0 : mesh.faceDegree(g) - (along.get(g) ?? 0));
    const [[w1, s1], [w2, s2]] = [...wedgeAt];
    if (after(w1) === 3 && after(w2) === 3) {
      return `collapsing f${f} would flatten what is left around it into two triangles (f${w1}, f${w2}) on the same three corners (v${heVertex[s1 ^ 1]}, v${heVertex[s2 ^ 1]} and the new vertex)`;
    }
  }
  return { sides, corners, across, triangles, spokes };
}
