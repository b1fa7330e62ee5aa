/**
 * `validate(mesh)` checks every invariant of the halfedge convention (see `mesh.ts`) and returns
 * each violation with the ids involved; an empty list means the mesh is sound.
 *
 * It uses plain loops over the raw arrays, never the circulators it is meant to vouch for, and
 * every walk is bounded, so it terminates on any corrupted mesh. Tests run it after every
 * operation; the app runs it after every step.
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

class TooMany extends Error {}

export function validate(mesh: HalfedgeMesh, options: ValidateOptions = {}): Violation[] {
  const limit = options.limit ?? 1000;
  const violations: Violation[] = [];
  const fail = (v: Violation) => {
    violations.push(v);
    if (violations.length >= limit) throw new TooMany();
  };
  try {
    checkHalfedges(mesh, fail);
    if (violations.length === 0) checkCycles(mesh, fail);
    checkFaces(mesh, fail);
    checkVertices(mesh, fail);
    checkParallelEdges(mesh, fail);
  } catch (error) {
    if (!(error instanceof TooMany)) throw error;
  }
  return violations;
}

type Fail = (violation: Violation) => void;

function checkHalfedges(mesh: HalfedgeMesh, fail: Fail): void {
  const { heNext, hePrev, heVertex, heFace, eDeleted, vDeleted, fDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const liveHalfedge = (h: number) => h >= 0 && h < nH && eDeleted[h >> 1] === 0;
  const liveVertex = (v: number) => v >= 0 && v < mesh.vertexSlots && vDeleted[v] === 0;
  const liveFace = (f: number) => f >= 0 && f < mesh.faceSlots && fDeleted[f] === 0;

  for (let h = 0; h < nH; h++) {
    if (eDeleted[h >> 1]) continue;
    const next = heNext[h];
    const prev = hePrev[h];
    const origin = heVertex[h];
    const face = heFace[h];
    const name = `h${h}`;
    if (!liveHalfedge(next) || !liveHalfedge(prev)) {
      fail({
        invariant: 'reference-in-range',
        message: `${name}: next h${next} / prev h${prev} is not a live halfedge`,
        halfedges: [h],
      });
      continue;
    }
    if (!liveVertex(origin)) {
      fail({ invariant: 'reference-in-range', message: `${name}: origin v${origin} is not a live vertex`, halfedges: [h] });
      continue;
    }
    if (face !== -1 && !liveFace(face)) {
      fail({ invariant: 'reference-in-range', message: `${name}: face f${face} is not a live face`, halfedges: [h] });
      continue;
    }
    if (hePrev[next] !== h) {
      fail({
        invariant: 'next-prev-inverse',
        message: `prev(next(${name})) is h${hePrev[next]}, not ${name}`,
        halfedges: [h, next],
      });
    }
    if (heNext[prev] !== h) {
      fail({
        invariant: 'next-prev-inverse',
        message: `next(prev(${name})) is h${heNext[prev]}, not ${name}`,
        halfedges: [h, prev],
      });
    }
    const target = heVertex[next];
    if (heVertex[h ^ 1] !== target) {
      fail({
        invariant: 'twin-origin',
        message: `origin(twin(${name})) is v${heVertex[h ^ 1]}, but target(${name}) = origin(next) is v${target}`,
        halfedges: [h, h ^ 1, next],
      });
    }
    if (target === origin) {
      fail({ invariant: 'self-loop', message: `${name} starts and ends at v${origin}`, halfedges: [h], vertices: [origin] });
    }
    if (heFace[next] !== face) {
      fail({
        invariant: 'face-along-next',
        message: `${name} is in ${faceName(face)} but next(${name}) = h${next} is in ${faceName(heFace[next])}`,
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
}

/** Every `next` cycle closes within as many steps as there are halfedges. */
function checkCycles(mesh: HalfedgeMesh, fail: Fail): void {
  const { heNext, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const seen = new Uint8Array(nH);
  for (let start = 0; start < nH; start++) {
    if (seen[start] || eDeleted[start >> 1]) continue;
    let h = start;
    let steps = 0;
    do {
      seen[h] = 1;
      h = heNext[h];
      steps++;
    } while (h !== start && steps <= nH);
    if (h !== start) {
      fail({ invariant: 'cycle-closes', message: `the next cycle from h${start} never returns to it`, halfedges: [start] });
    }
  }
}

/**
 * Each face has a live halfedge of its own, at least 3 sides, and passes through each vertex
 * once: a file lists a face by its corners, and a reader drops a face that repeats one (which is
 * how a dangling edge or a face touching itself at a vertex would look), so such a face does not
 * survive save and reload.
 */
function checkFaces(mesh: HalfedgeMesh, fail: Fail): void {
  const { heNext, heVertex, heFace, fHalfedge, fDeleted, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const nV = mesh.vertexSlots;
  const visitedBy = new Int32Array(nV).fill(-1);
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const start = fHalfedge[f];
    if (start < 0 || start >= nH || eDeleted[start >> 1]) {
      fail({ invariant: 'face-halfedge', message: `f${f}: halfedge h${start} is not a live halfedge`, faces: [f] });
      continue;
    }
    if (heFace[start] !== f) {
      fail({
        invariant: 'face-halfedge',
        message: `f${f}'s halfedge h${start} belongs to ${faceName(heFace[start])}`,
        faces: [f],
        halfedges: [start],
      });
      continue;
    }
    let degree = 0;
    let repeated = -1;
    let h = start;
    do {
      degree++;
      const v = heVertex[h];
      if (v >= 0 && v < nV) {
        if (visitedBy[v] === f && repeated === -1) repeated = v;
        visitedBy[v] = f;
      }
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
}

function checkVertices(mesh: HalfedgeMesh, fail: Fail): void {
  const { hePrev, heVertex, heFace, vHalfedge, vDeleted, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const nV = mesh.vertexSlots;
  const outgoing = new Int32Array(nV);
  const boundaryOut = new Int32Array(nV).fill(-1);
  for (let h = 0; h < nH; h++) {
    if (eDeleted[h >> 1]) continue;
    const v = heVertex[h];
    if (v < 0 || v >= nV) continue; // reported with the halfedges
    outgoing[v]++;
    if (heFace[h] === -1) boundaryOut[v] = h;
  }
  for (let v = 0; v < nV; v++) {
    if (vDeleted[v]) continue;
    const start = vHalfedge[v];
    if (start === -1) {
      if (outgoing[v] > 0) {
        fail({
          invariant: 'isolated-vertex',
          message: `v${v} has no halfedge but ${outgoing[v]} halfedges start from it`,
          vertices: [v],
        });
      }
      continue;
    }
    if (start < 0 || start >= nH || eDeleted[start >> 1] || heVertex[start] !== v) {
      fail({ invariant: 'vertex-halfedge', message: `v${v}'s halfedge h${start} does not start at v${v}`, vertices: [v] });
      continue;
    }
    if (boundaryOut[v] !== -1 && heFace[start] !== -1) {
      fail({
        invariant: 'boundary-vertex-halfedge',
        message: `v${v} is on the boundary (h${boundaryOut[v]} leaves it) but its halfedge h${start} is not a boundary halfedge`,
        vertices: [v],
        halfedges: [start, boundaryOut[v]],
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
    } while (h !== start && heVertex[h] === v && count <= outgoing[v]);
    if (h !== start || count !== outgoing[v]) {
      fail({
        invariant: 'vertex-fan',
        message: `rotating around v${v} from h${start} reaches ${count} of its ${outgoing[v]} outgoing halfedges (several fans, or a broken rotation)`,
        vertices: [v],
        halfedges: [start],
      });
    }
  }
}

/**
 * No two edges join the same two vertices. The pointers could hold such a pair, but no file can:
 * a face lists its corners, not its edges, so a reader would join the two into one edge (or none)
 * and read back a different mesh. Linear: the halfedges are bucketed by origin (a counting sort),
 * then each vertex's targets are stamped with its id.
 */
function checkParallelEdges(mesh: HalfedgeMesh, fail: Fail): void {
  const { heVertex, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const nV = mesh.vertexSlots;
  const inRange = (v: number) => v >= 0 && v < nV;
  const start = new Int32Array(nV + 1);
  for (let h = 0; h < nH; h++) {
    if (!eDeleted[h >> 1] && inRange(heVertex[h]) && inRange(heVertex[h ^ 1])) start[heVertex[h] + 1]++;
  }
  for (let v = 0; v < nV; v++) start[v + 1] += start[v];
  const fill = start.slice(0, nV);
  const byOrigin = new Int32Array(start[nV]);
  for (let h = 0; h < nH; h++) {
    if (!eDeleted[h >> 1] && inRange(heVertex[h]) && inRange(heVertex[h ^ 1])) byOrigin[fill[heVertex[h]]++] = h;
  }
  const stampedBy = new Int32Array(nV).fill(-1);
  const firstTo = new Int32Array(nV);
  for (let v = 0; v < nV; v++) {
    for (let k = start[v]; k < start[v + 1]; k++) {
      const h = byOrigin[k];
      const target = heVertex[h ^ 1];
      if (stampedBy[target] !== v) {
        stampedBy[target] = v;
        firstTo[target] = h;
      } else if (v < target) {
        const other = firstTo[target];
        fail({
          invariant: 'parallel-edge',
          message: `e${other >> 1} and e${h >> 1} both join v${v} and v${target}: a mesh file cannot tell two such edges apart`,
          halfedges: [other, h],
          vertices: [v, target],
        });
      }
    }
  }
}

function faceName(f: number): string {
  return f === -1 ? 'no face (boundary)' : `f${f}`;
}
