/**
 * The invariants of the halfedge convention (see `mesh.ts`), checked one element at a time. Two
 * passes share these checks: `validate` runs them on every element, `validateAround` on the
 * elements a change touched, so the two name the same fault in the same words.
 *
 * Each check reads raw arrays with plain, bounded loops (never the circulators it vouches for), so
 * it terminates on any corrupted mesh. What a check needs to know about the rest of the mesh (how
 * many halfedges leave a vertex, which vertices a walk has met) its caller works out, over the
 * whole mesh or around the change.
 */
import type { HalfedgeMesh } from './mesh.js';

export type Invariant =
  | 'reference-in-range'
  | 'next-prev-inverse'
  | 'twin-origin'
  | 'self-loop'
  | 'face-along-next'
  | 'edge-without-face'
  | 'face-halfedge'
  | 'face-degree'
  | 'face-repeats-vertex'
  | 'vertex-halfedge'
  | 'isolated-vertex'
  | 'boundary-vertex-halfedge'
  | 'vertex-fan'
  | 'parallel-edge'
  | 'cycle-closes';

export interface Violation {
  invariant: Invariant;
  message: string;
  halfedges?: number[];
  vertices?: number[];
  faces?: number[];
}

export interface ValidateOptions {
  /** Stop after this many violations (default 1000). */
  limit?: number;
}

export type Fail = (violation: Violation) => void;

class TooMany extends Error {}

/** Runs `checks`, collecting what they report (`found`, so far) until `options.limit` violations are found. */
export function collectViolations(options: ValidateOptions, checks: (fail: Fail, found: readonly Violation[]) => void): Violation[] {
  const limit = options.limit ?? 1000;
  const violations: Violation[] = [];
  try {
    checks((violation) => {
      violations.push(violation);
      if (violations.length >= limit) throw new TooMany();
    }, violations);
  } catch (error) {
    if (!(error instanceof TooMany)) throw error;
  }
  return violations;
}

/** A set of ids: a `Set`, or flags over every slot (`SlotFlags`) for a pass over the whole mesh. */
export interface IdSet {
  has(id: number): boolean;
  add(id: number): unknown;
}

export class SlotFlags implements IdSet {
  private readonly flags: Uint8Array;
  constructor(slots: number) {
    this.flags = new Uint8Array(slots);
  }
  has(id: number): boolean {
    return this.flags[id] === 1;
  }
  add(id: number): void {
    this.flags[id] = 1;
  }
}

/**
 * Which vertices one walk has met (a face's corners, a vertex's targets), and through which
 * halfedge first: `begin(owner)` starts a walk, `meet(v, h)` returns the halfedge through which
 * the walk met `v` before, or -1 the first time. Stamped arrays over every vertex for a pass over
 * the whole mesh (`VertexStamps`), a map for a few vertices (`VertexMap`).
 */
export interface VertexMeetings {
  begin(owner: number): void;
  meet(v: number, h: number): number;
}

export class VertexStamps implements VertexMeetings {
  private owner = -1;
  private readonly stampedBy: Int32Array;
  private readonly first: Int32Array;
  constructor(vertexSlots: number) {
    this.stampedBy = new Int32Array(vertexSlots).fill(-1);
    this.first = new Int32Array(vertexSlots);
  }
  begin(owner: number): void {
    this.owner = owner;
  }
  meet(v: number, h: number): number {
    if (this.stampedBy[v] === this.owner) return this.first[v];
    this.stampedBy[v] = this.owner;
    this.first[v] = h;
    return -1;
  }
}

export class VertexMap implements VertexMeetings {
  private readonly first = new Map<number, number>();
  begin(): void {
    this.first.clear();
  }
  meet(v: number, h: number): number {
    const before = this.first.get(v);
    if (before !== undefined) return before;
    this.first.set(v, h);
    return -1;
  }
}

/** Live halfedge `h`: its references are live, `next` and `prev` are inverse, the twin starts at its target, the face holds along `next`. */
export function checkHalfedge(mesh: HalfedgeMesh, h: number, fail: Fail): void {
  const { heNext, hePrev, heVertex, heFace, eDeleted, vDeleted, fDeleted } = mesh;
  const nH = 2 * mesh.edgeSlots;
  const next = heNext[h];
  const prev = hePrev[h];
  const origin = heVertex[h];
  const face = heFace[h];
  // messages spell h${h} out only on failure: a name built for every halfedge took as long as the checks
  if (!(next >= 0 && next < nH && eDeleted[next >> 1] === 0) || !(prev >= 0 && prev < nH && eDeleted[prev >> 1] === 0)) {
    fail({
      invariant: 'reference-in-range',
      message: `h${h}: next h${next} / prev h${prev} is not a live halfedge`,
      halfedges: [h],
    });
    return;
  }
  if (!(origin >= 0 && origin < mesh.vertexSlots && vDeleted[origin] === 0)) {
    fail({ invariant: 'reference-in-range', message: `h${h}: origin v${origin} is not a live vertex`, halfedges: [h] });
    return;
  }
  if (face !== -1 && !(face >= 0 && face < mesh.faceSlots && fDeleted[face] === 0)) {
    fail({ invariant: 'reference-in-range', message: `h${h}: face f${face} is not a live face`, halfedges: [h] });
    return;
  }
  if (hePrev[next] !== h) {
    fail({
      invariant: 'next-prev-inverse',
      message: `prev(next(h${h})) is h${hePrev[next]}, not h${h}`,
      halfedges: [h, next],
    });
  }
  if (heNext[prev] !== h) {
    fail({
      invariant: 'next-prev-inverse',
      message: `next(prev(h${h})) is h${heNext[prev]}, not h${h}`,
      halfedges: [h, prev],
    });
  }
  const target = heVertex[next];
  if (heVertex[h ^ 1] !== target) {
    fail({
      invariant: 'twin-origin',
      message: `origin(twin(h${h})) is v${heVertex[h ^ 1]}, but target(h${h}) = origin(next) is v${target}`,
      halfedges: [h, h ^ 1, next],
    });
  }
  if (target === origin) {
    fail({ invariant: 'self-loop', message: `h${h} starts and ends at v${origin}`, halfedges: [h], vertices: [origin] });
  }
  if (heFace[next] !== face) {
    fail({
      invariant: 'face-along-next',
      message: `h${h} is in ${faceName(face)} but next(h${h}) = h${next} is in ${faceName(heFace[next])}`,
      halfedges: [h, next],
    });
  }
  if (face === -1 && heFace[h ^ 1] === -1 && (h & 1) === 0) {
    fail({
      invariant: 'edge-without-face',
      message: `both halfedges of e${h >> 1} (h${h}, h${h ^ 1}) are boundary: an edge must border a face`,
      halfedges: [h, h ^ 1],
    });
  }
}

/** The `next` cycle from live halfedge `start` closes within as many steps as there are halfedges; marks its halfedges in `seen`. */
export function checkCycle(mesh: HalfedgeMesh, start: number, seen: IdSet, fail: Fail): void {
  const { heNext } = mesh;
  const nH = mesh.halfedgeSlots;
  let h = start;
  let steps = 0;
  do {
    seen.add(h);
    h = heNext[h];
    steps++;
  } while (h !== start && steps <= nH);
  if (h !== start) {
    fail({ invariant: 'cycle-closes', message: `the next cycle from h${start} never returns to it`, halfedges: [start] });
  }
}

/**
 * Live face `f` has a live halfedge of its own, at least 3 sides, and passes through each vertex
 * once: a file lists a face by its corners, and a reader drops a face that repeats one (which is
 * how a dangling edge or a face touching itself at a vertex would look), so such a face does not
 * survive save and reload.
 */
export function checkFace(mesh: HalfedgeMesh, f: number, corners: VertexMeetings, fail: Fail): void {
  const { heNext, heVertex, heFace, fHalfedge, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const nV = mesh.vertexSlots;
  const start = fHalfedge[f];
  if (start < 0 || start >= nH || eDeleted[start >> 1]) {
    fail({ invariant: 'face-halfedge', message: `f${f}: halfedge h${start} is not a live halfedge`, faces: [f] });
    return;
  }
  if (heFace[start] !== f) {
    fail({
      invariant: 'face-halfedge',
      message: `f${f}'s halfedge h${start} belongs to ${faceName(heFace[start])}`,
      faces: [f],
      halfedges: [start],
    });
    return;
  }
  corners.begin(f);
  let degree = 0;
  let repeated = -1;
  let h = start;
  do {
    degree++;
    const v = heVertex[h];
    if (v >= 0 && v < nV && corners.meet(v, h) !== -1 && repeated === -1) repeated = v;
    h = heNext[h];
  } while (h !== start && h >= 0 && degree <= nH);
  if (h === start && degree < 3) {
    fail({ invariant: 'face-degree', message: `f${f} has ${degree} sides; a face needs at least 3`, faces: [f] });
  } else if (h === start && repeated !== -1) {
    fail({
      invariant: 'face-repeats-vertex',
      message: `f${f} passes through v${repeated} twice: a mesh file lists a face by its corners and cannot hold that`,
      faces: [f],
      vertices: [repeated],
    });
  }
}

/** What a vertex's check needs to know of the halfedges leaving it, whoever counted them. */
export interface Leaving {
  /** How many live halfedges start at the vertex. */
  count: number;
  /** The highest-numbered of them that is a boundary halfedge, or -1. */
  boundary: number;
}

/**
 * Live vertex `v` has a halfedge that starts at it (none only when no halfedge does), a boundary
 * one when it is on the boundary, and one fan: rotating from it reaches every halfedge leaving `v`.
 */
export function checkVertex(mesh: HalfedgeMesh, v: number, leaving: Leaving, fail: Fail): void {
  const { hePrev, heVertex, heFace, vHalfedge, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const start = vHalfedge[v];
  if (start === -1) {
    if (leaving.count > 0) {
      fail({
        invariant: 'isolated-vertex',
        message: `v${v} has no halfedge but ${leaving.count} halfedges start from it`,
        vertices: [v],
      });
    }
    return;
  }
  if (start < 0 || start >= nH || eDeleted[start >> 1] || heVertex[start] !== v) {
    fail({ invariant: 'vertex-halfedge', message: `v${v}'s halfedge h${start} does not start at v${v}`, vertices: [v] });
    return;
  }
  if (leaving.boundary !== -1 && heFace[start] !== -1) {
    fail({
      invariant: 'boundary-vertex-halfedge',
      message: `v${v} is on the boundary (h${leaving.boundary} leaves it) but its halfedge h${start} is not a boundary halfedge`,
      vertices: [v],
      halfedges: [start, leaving.boundary],
    });
  }
  // rotate around v (twin of prev): the fan must reach every halfedge leaving v
  let count = 0;
  let h = start;
  do {
    count++;
    const p = hePrev[h];
    if (p < 0 || p >= nH) break;
    h = p ^ 1;
  } while (h !== start && heVertex[h] === v && count <= leaving.count);
  if (h !== start || count !== leaving.count) {
    fail({
      invariant: 'vertex-fan',
      message: `rotating around v${v} from h${start} reaches ${count} of its ${leaving.count} outgoing halfedges (several fans, or a broken rotation)`,
      vertices: [v],
      halfedges: [start],
    });
  }
}

/**
 * No two edges join the same two vertices. The pointers could hold such a pair, but no file can:
 * a face lists its corners, not its edges, so a reader would join the two into one edge (or none)
 * and read back a different mesh.
 *
 * Checks the halfedges leaving `v`, `outgoing[from … to - 1]` in increasing order, whose twins
 * start at a vertex in range. A pair is named from its lower vertex, with the first edge found
 * there; `reportsAt(v, target)` says whether this pass names the pair when it meets it at `v`
 * (a pass that meets it at both ends names it at the lower one).
 */
export function checkParallelEdges(
  mesh: HalfedgeMesh,
  v: number,
  outgoing: ArrayLike<number>,
  from: number,
  to: number,
  targets: VertexMeetings,
  reportsAt: (v: number, target: number) => boolean,
  fail: Fail,
): void {
  const { heVertex } = mesh;
  targets.begin(v);
  for (let k = from; k < to; k++) {
    const h = outgoing[k];
    const target = heVertex[h ^ 1];
    const other = targets.meet(target, h);
    if (other === -1 || !reportsAt(v, target)) continue;
    // from the lower vertex the same two edges leave as the twins, in the same order
    const [first, second, low, high] = v < target ? [other, h, v, target] : [other ^ 1, h ^ 1, target, v];
    fail({
      invariant: 'parallel-edge',
      message: `e${first >> 1} and e${second >> 1} both join v${low} and v${high}: a mesh file cannot tell two such edges apart`,
      halfedges: [first, second],
      vertices: [low, high],
    });
  }
}

function faceName(f: number): string {
  return f === -1 ? 'no face (boundary)' : `f${f}`;
}
