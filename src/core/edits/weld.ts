/**
 * Weld edges: two boundary edges become one interior edge, their ends merged pairwise. The
 * pairing is the one that keeps the orientation: e1's boundary halfedge h1 runs a1 → b1 and e2's
 * h2 runs a2 → b2, so the faces along them (on their twins) meet as twins do when b1 meets a2
 * and a1 meets b2.
 *
 * ```
 *    x ◄──────── a1   b2 ◄──────── y            x ◄──────── a1 ◄──────── y
 *    │           ▲ │  ▲ │           ▲            │           ▲│           ▲
 *    │    f1  t1 │ │h1│ │t2   f2    │    ──►     │    f1  t1 ││h1   f2    │
 *    ▼           │ ▼ h2 ▼           │            ▼           │▼           │
 *    p ────────► b1   a2 ────────► q            p ────────► b1 ────────► q
 * ```
 * Above, h1 runs down the gap beside f1 and h2 up the gap beside f2, so a1 meets b2 and b1 meets
 * a2. e1 stays, and its boundary halfedge h1 takes the place of t2 in f2; e2, b2 and a2 are
 * deleted (e1, a1 and b1 keep their ids). Merged ends go to their **midpoints**, with every vertex
 * attribute averaged; h1 takes t2's corner values. The original assignment's figure joins a quad
 * and a triangle lying side by side this way, and its test moves the merged ends to midpoints.
 *
 * The cases:
 *   - two edges of different loops (of two pieces, or two holes of one piece): the loops become
 *     one (χ − 1; two pieces become one);
 *   - two edges of one hole, apart: the hole splits in two loops (a strip rolls into a tube: χ − 1);
 *   - two edges of one hole that meet at a vertex (a *zip*, b1 = a2 or a1 = b2): only their other
 *     ends merge, and the shared vertex moves off the boundary (χ unchanged);
 *   - refused, not both on the boundary, or the same edge twice;
 *   - refused, two ends that would merge are already joined by an edge (it would become a loop);
 *     this is also what refuses zipping a hole of 3 sides shut;
 *   - refused, two ends that would merge are corners of one face (it would pass through the
 *     merged vertex twice): this refuses welding two edges of the same face;
 *   - refused, the merged vertices would be joined to one vertex, or to each other, by two edges
 *     (two ends that would merge are both joined to a third vertex; or a1 is joined to a2, or b1
 *     to b2): no file can hold a second edge between two vertices. This refuses zipping a hole
 *     of 4 sides shut.
 * A gluing that needs the other pairing (a strip's ends twisted into a Möbius strip) is never
 * made: the pairing always follows the orientation, so a weld cannot make a surface
 * non-orientable. Each merged vertex keeps one hole through it, the gaps of its two ends joined
 * at the weld, so the mesh stays manifold.
 *
 * O(valence² of the four ends): the one-rings of each merging pair are compared pairwise (a few
 * dozen comparisons at the usual valence), and the halfedges leaving a2 and b2 move to b1 and a1.
 */
import { TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { missingEdge, rotationFrom } from './find.js';
import { type EdgeEditResult, type EditOptions, PointerWriter } from '../change/writer.js';

/** The halves of a merged pair, blended half and half. */
const halves = [0.5, 0.5];

/** The boundary halfedge of boundary edge `e`. */
function boundaryHalfedge(mesh: HalfedgeMesh, e: number): number {
  return mesh.heFace[2 * e] === -1 ? 2 * e : 2 * e + 1;
}


/**
 * Why boundary edges `e1` and `e2` cannot be welded, or null when they can (the rules above).
 * @example canWeldEdges(mesh, e1, e2); // "v3 and v8 would merge, but they are both corners of f2: …"
 */
export function canWeldEdges(mesh: HalfedgeMesh, e1: number, e2: number): string | null {
  const missing = missingEdge(mesh, e1) ?? missingEdge(mesh, e2);
  if (missing) return missing;
  if (e1 === e2) return `e${e1} is given twice: a weld joins two different edges`;
  for (const e of [e1, e2]) {
    if (!mesh.isBoundaryEdge(e)) return `e${e} is not on the boundary: only boundary edges can be welded (it has faces on both sides)`;
  }
  const { heVertex } = mesh;
  const h1 = boundaryHalfedge(mesh, e1);
  const h2 = boundaryHalfedge(mesh, e2);
  const [a1, b1, a2, b2] = [heVertex[h1], heVertex[h1 ^ 1], heVertex[h2], heVertex[h2 ^ 1]];
  // two edges on the same two vertices cannot both exist in a valid mesh; said for safety
  if (a1 === b2 && b1 === a2) return `e${e1} and e${e2} already join the same two vertices`;
  // the merged pairs: b2 into a1, a2 into b1 (a pair whose ends are one vertex, a zip, merges nothing)
  const merged = (u: number) => (u === b2 ? a1 : u === a2 ? b1 : u);
  for (const [x, y] of [
    [a1, b2],
    [b1, a2],
  ]) {
    if (x === y) continue;
    const why = whyNotMerge(mesh, x, y, e2, merged);
    if (why) return why;
  }
  return null;
}

/**
 * Why vertex `y` cannot merge into `x` in the weld (whose other edge is `e2`, and `merged` maps a
 * vertex to the one it becomes): they are joined already, share a face, or the merged vertex
 * would be joined to one vertex by two edges.
 */
function whyNotMerge(mesh: HalfedgeMesh, x: number, y: number, e2: number, merged: (u: number) => number): string | null {
  const { heVertex, heFace } = mesh;
  const aroundX = rotationFrom(mesh, mesh.vHalfedge[x]);
  const aroundY = rotationFrom(mesh, mesh.vHalfedge[y]);
  // joined already: their edge would become a loop
  for (const g of aroundX) {
    if (heVertex[g ^ 1] === y) return `v${x} and v${y} would merge, but e${g >> 1} joins them: it would become a loop`;
  }
  // a face through both would pass through the merged vertex twice
  for (const g of aroundX) {
    const f = heFace[g];
    if (f === -1) continue;
    for (const k of aroundY) {
      if (heFace[k] === f) return `v${x} and v${y} would merge, but they are both corners of f${f}: it would pass through the merged vertex twice`;
    }
  }
  // the merged vertex's neighbours, as they will be, must all differ (e2 is welded onto e1: it
  // is no second edge)
  const edges: number[] = [];
  const ends: number[] = [];
  for (const g of aroundX.concat(aroundY)) {
    if (g >> 1 === e2) continue;
    const z = merged(heVertex[g ^ 1]);
    const before = ends.indexOf(z);
    if (before !== -1) {
      return `welding would join v${x} (merged with v${y}) to v${z} by two edges, e${edges[before]} and e${g >> 1}: a second edge between two vertices is not allowed`;
    }
    edges.push(g >> 1);
    ends.push(z);
  }
  return null;
}

/**
 * Welds boundary edges `e1` and `e2` into one interior edge: `e1` (see the diagram above). Merged
 * ends meet at their midpoints.
 * @example const { edge } = weldEdges(mesh, e1, e2); // two triangles side by side → a square
 * @throws TopologyError with `canWeldEdges`'s sentence when the weld does not apply.
 */
export function weldEdges(mesh: HalfedgeMesh, e1: number, e2: number, options: EditOptions = {}): EdgeEditResult {
  const why = canWeldEdges(mesh, e1, e2);
  if (why) throw new TopologyError(`weldEdges: ${why}`);
  const w = new PointerWriter(mesh, options);
  const { heNext, hePrev, heVertex, heFace, fHalfedge } = mesh; // a weld never grows the arrays
  const h1 = boundaryHalfedge(mesh, e1); // a1 → b1, on the hole
  const h2 = boundaryHalfedge(mesh, e2); // a2 → b2, on the hole
  const t2 = h2 ^ 1; // b2 → a2, in f2
  const [a1, b1, a2, b2] = [heVertex[h1], heVertex[h1 ^ 1], heVertex[h2], heVertex[t2]];
  // the hole on either side of each, the face of t2 and its neighbours there: read before writing
  const p1 = hePrev[h1];
  const n1 = heNext[h1];
  const p2 = hePrev[h2];
  const n2 = heNext[h2];
  const f2 = heFace[t2];
  const beforeT2 = hePrev[t2];
  const afterT2 = heNext[t2];
  // a zip: the edges follow one another along the hole, sharing an end that merges nothing
  const zipAtB1 = b1 === a2; // h1 then h2: next(h1) = h2
  const zipAtA1 = a1 === b2; // h2 then h1: next(h2) = h1
  // the halfedges that will leave a1 and b1 instead of b2 and a2 (not e2's: it goes)
  const fromB2 = zipAtA1 ? [] : rotationFrom(mesh, t2).slice(1);
  const fromA2 = zipAtB1 ? [] : rotationFrom(mesh, h2).slice(1);

  // merged ends at their midpoints, every vertex attribute averaged
  if (!zipAtA1) w.blend('vertex', a1, [a1, b2], halves);
  if (!zipAtB1) w.blend('vertex', b1, [b1, a2], halves);
  for (const g of fromB2) w.setOrigin(g, a1);
  for (const g of fromA2) w.setOrigin(g, b1);

  // h1 leaves the hole and takes t2's place in f2 (a1 → b1 is b2 → a2 merged)
  w.copy('halfedge', h1, t2);
  w.link(beforeT2, h1);
  w.link(h1, afterT2);
  w.setFace(h1, f2);
  if (fHalfedge[f2] === t2) w.setFaceHalfedge(f2, h1);

  // the hole: at b1 = a2 it runs from before h2 on to after h1, at a1 = b2 from before h1 on to
  // after h2; at a zip's shared vertex the gap closes, and that vertex is inside the mesh now
  if (!zipAtB1) w.link(p2, n1);
  if (!zipAtA1) w.link(p1, n2);

  w.deleteEdge(e2);
  if (!zipAtA1) w.deleteVertex(b2);
  if (!zipAtB1) w.deleteVertex(a2);
  chooseHandle(w, a1, h1);
  chooseHandle(w, b1, h1 ^ 1);
  return { ...w.result(), edge: e1 };
}

/**
 * Gives `v` its outgoing boundary halfedge as handle when it has one (rotating from `from`, which
 * leaves it), else keeps a live handle (or takes `from`).
 */
function chooseHandle(w: PointerWriter, v: number, from: number): void {
  const { heFace, vHalfedge, eDeleted } = w.mesh;
  const out = rotationFrom(w.mesh, from);
  const boundary = out.find((g) => heFace[g] === -1);
  if (boundary !== undefined) {
    if (vHalfedge[v] !== boundary) w.setVertexHalfedge(v, boundary);
  } else if (vHalfedge[v] < 0 || eDeleted[vHalfedge[v] >> 1]) {
    w.setVertexHalfedge(v, from);
  }
}
