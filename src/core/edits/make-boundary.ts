/**
 * Make boundary: a face becomes a hole. Its halfedges lose their face and become boundary
 * halfedges; an edge that had a hole on its other side now has a hole on both and goes, so the
 * face's hole merges with that one; a corner left with no edge goes too.
 *
 * ```
 *    a ───── b ───── c ───── d            a ───── b       c ───── d
 *    │       │       │       │            │       ┆       ┆       │
 *    │   g   │   f   │   k   │    ──►     │   g   ┆       ┆   k   │    b–c and q–r (f | outside)
 *    │       │       │       │            │       ┆       ┆       │    are deleted, and f;
 *    p ───── q ───── r ───── s            p ───── q       r ───── s    b–q and c–r are boundary
 * ```
 * (┆: an edge now on the boundary.) Here f touched the outer hole along two separate edges, so
 * the strip falls in two pieces and the one hole becomes two loops, a b q p and c d s r, as in the
 * original assignment's figure and test ("merging adjacent boundary faces"; there the face itself
 * is handed back, marked boundary: here holes are not faces, so a halfedge of the hole is). Where
 * a face lies inside the mesh, it simply opens a new hole (χ drops by 1, one boundary loop more).
 *
 * The cases:
 *   - an interior face: every edge keeps a face on its other side; one new boundary loop;
 *   - a face along a hole: the edges between them are deleted and the two holes are one loop
 *     (or more, as above, where the face touched the hole along separate runs of edges);
 *   - a corner whose two edges on f both lay along a hole (a corner f alone had) loses both
 *     edges and is deleted: no isolated vertex is left behind;
 *   - refused, a *pinch*: a corner already on the boundary where neither of f's edges lies along
 *     the hole. Each boundary vertex of this library has one hole through it (one gap in its fan
 *     of faces); f's hole and the other would meet at that vertex only;
 *   - refused, a lone face (every edge along a hole: a component of one face): nothing would be
 *     left of it, and there would be no hole to hand back.
 *
 * O(degree of f): one walk round f to check, one to rewrite; each deleted edge is spliced out of
 * the holes with its four neighbours.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingFace } from './find.js';
import { type EditOptions, type HalfedgeEditResult, PointerWriter } from '../change/writer.js';

/**
 * Why face `f` cannot become a hole, or null when it can (a pinch at a corner, or a lone face;
 * see above).
 * @example canMakeBoundary(mesh, f); // "v4 is already on the boundary, but neither edge of f2 at v4 is: …"
 */
export function canMakeBoundary(mesh: HalfedgeMesh, f: number): string | null {
  const missing = missingFace(mesh, f);
  if (missing) return missing;
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const start = mesh.fHalfedge[f];
  let onHole = 0;
  let sides = 0;
  let h = start;
  do {
    // at corner v = origin(h), f's two edges are prev(h)'s and h's
    const v = heVertex[h];
    const holeBefore = heFace[hePrev[h] ^ 1] === -1;
    const holeAfter = heFace[h ^ 1] === -1;
    if (holeAfter) onHole++;
    if (!holeBefore && !holeAfter && mesh.isBoundaryVertex(v)) {
      return `v${v} is already on the boundary, but neither edge of f${f} at v${v} is: f${f}'s hole and the hole through v${v} would meet at v${v} alone (a pinch)`;
    }
    sides++;
    h = heNext[h];
  } while (h !== start && sides <= mesh.halfedgeSlots);
  if (onHole === sides) {
    return `every edge of f${f} is on the boundary (f${f} is a piece of one face): making it a hole would leave nothing of it`;
  }
  return null;
}

/**
 * Turns face `f` into a hole (see the diagram above). Returns a boundary halfedge of the hole:
 * one of f's own halfedges that stays (one with a face on its other side). Where the hole came
 * out as several loops, it lies on one of them.
 * @example const { halfedge } = makeBoundary(mesh, f); // mesh.loopLength(halfedge): the hole's sides
 * @throws TopologyError with `canMakeBoundary`'s sentence when `f` cannot become a hole.
 */
export function makeBoundary(mesh: HalfedgeMesh, f: number, options: EditOptions = {}): HalfedgeEditResult {
  const why = canMakeBoundary(mesh, f);
  if (why) throw new TopologyError(`makeBoundary: ${why}`);
  const w = new PointerWriter(mesh, options);
  const halfedge = makeBoundaryAt(w, f);
  return { ...w.result(), halfedge };
}

/**
 * The change itself, through a caller's writer, for a caller that has asked `canMakeBoundary`
 * (`dissolveEdge` on a boundary edge). Returns a halfedge of f's that stays, now boundary.
 */
export function makeBoundaryAt(w: PointerWriter, f: number): number {
  const mesh = w.mesh;
  const { heNext, heVertex, heFace } = mesh;
  // f's halfedges, whether each corner was on the boundary, and whether each edge lay along a
  // hole: all read before the first write
  const sides: number[] = [];
  const cornerOnBoundary: boolean[] = [];
  const alongHole: boolean[] = [];
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    sides.push(h);
    cornerOnBoundary.push(mesh.isBoundaryVertex(heVertex[h]));
    alongHole.push(heFace[h ^ 1] === -1);
    h = heNext[h];
  } while (h !== start && sides.length <= mesh.halfedgeSlots);

  // f's loop is now a hole's: its halfedges keep their next/prev and lose their face
  for (const g of sides) w.setFace(g, -1);
  // a corner that was inside the mesh is on the boundary now: its handle is its outgoing
  // boundary halfedge, the one of f's that leaves it (its edge stays: both its faces were real)
  for (let i = 0; i < sides.length; i++) if (!cornerOnBoundary[i]) w.setVertexHalfedge(heVertex[sides[i]], sides[i]);
  // an edge with a hole on both sides goes, splicing the two loops into one (or one into two)
  for (let i = 0; i < sides.length; i++) if (alongHole[i]) removeEdgeBetweenHoles(w, sides[i]);
  w.deleteFace(f);
  for (let i = 0; i < sides.length; i++) if (!alongHole[i]) return sides[i];
  return -1; // a lone face, which canMakeBoundary refuses
}

/**
 * Deletes the edge of `g` when both its halfedges are boundary ones: each loop is joined to the
 * other where the edge was (or a loop splits in two, when both halfedges ran round the same
 * hole), and an end that had no other edge is deleted with it.
 * ```
 *      ╲ p          n ╱            ╲ p          n ╱
 *       ╲     g      ╱              ╲            ╱
 *        a ───────► b      ──►       a          b        next(p) = n′, next(p′) = n
 *       ╱  ◄─────── ╲               ╱            ╲
 *      ╱ n′   g′   p′╲             ╱ n′        p′ ╲
 * ```
 */
function removeEdgeBetweenHoles(w: PointerWriter, g: number): void {
  const { heNext, hePrev, heVertex, vHalfedge } = w.mesh;
  const t = g ^ 1;
  const a = heVertex[g];
  const b = heVertex[t];
  const n = heNext[g];
  const p = hePrev[g];
  const nt = heNext[t];
  const pt = hePrev[t];
  if (n === t && nt === g) {
    // a dangling edge on its own: both ends go (only a lone face would leave one)
    w.deleteVertex(a);
    w.deleteVertex(b);
  } else if (n === t) {
    // b has no other edge: the loop turns back at b, so b goes, and the loop skips the spike
    w.link(p, nt);
    if (vHalfedge[a] === g) w.setVertexHalfedge(a, nt);
    w.deleteVertex(b);
  } else if (nt === g) {
    // the same at a
    w.link(pt, n);
    if (vHalfedge[b] === t) w.setVertexHalfedge(b, n);
    w.deleteVertex(a);
  } else {
    // both ends keep other edges: each loop runs on into the other
    w.link(p, nt);
    w.link(pt, n);
    // the ends keep a boundary handle: n′ leaves a, n leaves b
    if (vHalfedge[a] === g) w.setVertexHalfedge(a, nt);
    if (vHalfedge[b] === t) w.setVertexHalfedge(b, n);
  }
  w.deleteEdge(g >> 1);
}
