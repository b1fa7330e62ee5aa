/**
 * Since which write each invariant still broken at the end has been broken: the write that began
 * its last unbroken run of failing (a correct solution passes through half-wired states, and
 * those are not blamed). Found in one replay of the writes, whatever their number and the mesh's
 * size, without validating the whole mesh after each write.
 *
 * Every violation `validate` names comes from one check of one element: the halfedge check of its
 * first halfedge, the face check of its face, the vertex check or the parallel-edge check of its
 * first vertex. A check gives what it gave before unless a field it read has changed since. So the
 * replay watches the checks of the elements the final violations name: it runs each on the mesh
 * before the writes, noting every field the check reads, and runs it again after any write that
 * changes one of those fields. A violation's run begins at the write after which its check named
 * it without having named it just before.
 *
 * ```
 *   check of h7 reads  next(h7), prev(h7), origin(h7), face(h7), prev(next(h7)), origin(next(h7)), …
 *   w0  next(h3) = h9        not read: h7's check is not run
 *   w1  origin(h8) = v2      h8 is next(h7): run again, it now names twin-origin at h7   (since w1)
 *   w2  origin(h6) = v2      h6 is twin(h7): run again, it names nothing
 *   w3  origin(h8) = v5      run again, it names twin-origin at h7 again                  (since w3)
 * ```
 *
 * Nothing here assumes the mesh valid between writes, as `validateAround` does: around a write it
 * checks the elements a valid mesh links to what was written, but in a half-wired mesh the check
 * of h reads origin(next(h)) while prev(next(h)) may be another halfedge, so a write to that
 * origin would go unseen. Following the fields each check really read misses nothing.
 *
 * What a check reads beside fields: the halfedges leaving a vertex (the vertex and parallel-edge
 * checks), which any origin write may change, so each origin write counts as a change to the
 * halfedges leaving its old and its new vertex; and the slot counts, which need no watching: a
 * pointer holds -1 or an element that existed when it was written, and slots are never given
 * back, so a test of a pointer against a slot count comes out the same after any later write.
 */
import { checkFace, checkHalfedge, checkParallelEdges, checkVertex, type Fail, VertexMap, type Violation } from '../invariants.js';
import type { HalfedgeMesh } from '../mesh.js';
import { type ElementKind, elementKinds, meshArrayIndex, type MeshArrayName, meshArrays } from '../mesh-arrays.js';
import { lowerEnd } from '../validate.js';
import { applyWrite, pointerArrayOf, type PracticeWrite, replayWriter } from './writes.js';

/** How a violation is told apart from another: its invariant and the elements it names. */
export function keyOf(v: Violation): string {
  return `${v.invariant}|${v.halfedges ?? ''}|${v.vertices ?? ''}|${v.faces ?? ''}`;
}

/**
 * For each of `final` (violations of the mesh `before` leaves after every write), the index in
 * `writes` of the write that began its last unbroken run of failing, or -1 when it was failing
 * before the first write.
 * @example const since = brokenSince(fixture, output.writes, validate(after, { limit: 50 }));
 */
export function brokenSince(before: HalfedgeMesh, writes: readonly PracticeWrite[], final: readonly Violation[]): number[] {
  const mesh = before.clone();
  const watches = watchesOf(final);
  const leaving = new LeavingSets(mesh, watches);
  /** field → the watches whose check read it when it last ran */
  const watchers = new Map<number, Set<Watch>>();
  /** violation key → the write its run of failing began at, for each violation a watched check names now */
  const onset = new Map<string, number>();

  const run = (watch: Watch, at: number) => {
    for (const field of watch.reads) {
      const set = watchers.get(field)!;
      set.delete(watch);
      if (set.size === 0) watchers.delete(field);
    }
    const reads = new Set<number>();
    const failing = new Set<string>();
    runCheck(readingView(mesh, reads), watch, leaving, reads, (v) => failing.add(keyOf(v)));
    for (const key of failing) if (!watch.failing.has(key)) onset.set(key, at);
    for (const key of watch.failing) if (!failing.has(key)) onset.delete(key);
    watch.failing = failing;
    watch.reads = reads;
    for (const field of reads) {
      const set = watchers.get(field);
      if (set) set.add(watch);
      else watchers.set(field, new Set([watch]));
    }
  };
  for (const watch of watches) run(watch, -1);

  // per write: the fields it may change, and the old origin of each origin among them
  const changed: number[] = [];
  const oldOrigins: number[] = [];
  const note = (array: number, index: number) => {
    changed.push(fieldKey(array, index));
    // a halfedge not made yet leaves no vertex
    if (array === HE_VERTEX) oldOrigins.push(index, index < mesh.halfedgeSlots ? mesh.heVertex[index] : -1);
  };
  const due = new Set<Watch>();
  const writer = replayWriter(mesh);
  const wake = (field: number) => {
    const set = watchers.get(field);
    if (set) for (const watch of set) due.add(watch);
  };
  for (let i = 0; i < writes.length; i++) {
    const write = writes[i];
    changed.length = 0;
    oldOrigins.length = 0;
    fieldsOf(write, note);
    applyWrite(writer, write);
    for (let k = 0; k < changed.length; k++) wake(changed[k]);
    for (let k = 0; k < oldOrigins.length; k += 2) {
      const h = oldOrigins[k];
      const from = oldOrigins[k + 1];
      const to = mesh.heVertex[h];
      leaving.move(h, from, to);
      wake(fieldKey(LEAVING, from));
      wake(fieldKey(LEAVING, to));
    }
    if (due.size === 0) continue;
    for (const watch of due) run(watch, i);
    due.clear();
  }
  // each final violation is named at the end by its watched check, so it has an onset
  return final.map((v) => onset.get(keyOf(v))!);
}

type CheckKind = 'halfedge' | 'face' | 'vertex' | 'parallel';

/** One check of one element, with what it read and named when it last ran. */
interface Watch {
  kind: CheckKind;
  id: number;
  reads: Set<number>;
  failing: Set<string>;
}

/**
 * The checks that can name the violations: each violation's own check is among those of the
 * elements it lists (a pair of parallel edges is named from its lower vertex, listed first).
 */
function watchesOf(final: readonly Violation[]): Watch[] {
  const watches = new Map<string, Watch>();
  const watch = (kind: CheckKind, id: number) => {
    const key = `${kind}${id}`;
    if (!watches.has(key)) watches.set(key, { kind, id, reads: new Set(), failing: new Set() });
  };
  for (const v of final) {
    for (const h of v.halfedges ?? []) watch('halfedge', h);
    for (const f of v.faces ?? []) watch('face', f);
    for (const u of v.vertices ?? []) {
      watch('vertex', u);
      watch('parallel', u);
    }
  }
  return [...watches.values()];
}

/** Runs the check of `watch` as `validate` runs it, on `view`, noting in `reads` the halfedges leaving a vertex it looks at. */
function runCheck(view: HalfedgeMesh, watch: Watch, leaving: LeavingSets, reads: Set<number>, fail: Fail): void {
  const { id } = watch;
  // the flag is read before the slot count so that it is noted even before the element is made:
  // making it writes the flag, which wakes the check
  switch (watch.kind) {
    case 'halfedge':
      if (view.eDeleted[id >> 1] === 0 && id < view.halfedgeSlots) checkHalfedge(view, id, fail);
      return;
    case 'face':
      if (view.fDeleted[id] === 0 && id < view.faceSlots) checkFace(view, id, new VertexMap(), fail);
      return;
    case 'vertex': {
      if (view.vDeleted[id] !== 0 || id >= view.vertexSlots) return;
      const out = leaving.liveFrom(view, id, reads);
      let boundary = -1;
      for (const h of out) if (view.heFace[h] === -1) boundary = h;
      checkVertex(view, id, { count: out.length, boundary }, fail);
      return;
    }
    case 'parallel': {
      // validate looks for parallel edges at every vertex slot, deleted or not
      const nV = view.vertexSlots;
      const out = leaving.liveFrom(view, id, reads).filter((h) => view.heVertex[h ^ 1] >= 0 && view.heVertex[h ^ 1] < nV);
      checkParallelEdges(view, id, out, 0, out.length, new VertexMap(), lowerEnd, fail);
    }
  }
}

/**
 * The halfedges whose origin is each watched vertex (deleted ones included), kept as origins are
 * written, so that a vertex's check never needs a pass over the mesh.
 */
class LeavingSets {
  private readonly sets = new Map<number, Set<number>>();

  constructor(mesh: HalfedgeMesh, watches: readonly Watch[]) {
    for (const w of watches) if (w.kind === 'vertex' || w.kind === 'parallel') this.sets.set(w.id, new Set());
    if (this.sets.size === 0) return;
    for (let h = 0; h < mesh.halfedgeSlots; h++) this.sets.get(mesh.heVertex[h])?.add(h);
  }

  move(h: number, from: number, to: number): void {
    this.sets.get(from)?.delete(h);
    this.sets.get(to)?.add(h);
  }

  /** The live halfedges leaving `v`, in increasing order, as `view` reads them (noting that the check looked). */
  liveFrom(view: HalfedgeMesh, v: number, reads: Set<number>): number[] {
    reads.add(fieldKey(LEAVING, v));
    return Array.from(this.sets.get(v)!)
      .filter((h) => view.eDeleted[h >> 1] === 0)
      .sort((a, b) => a - b);
  }
}

const HE_VERTEX = meshArrayIndex.heVertex;
/** A field no array holds: "the halfedges leaving vertex v", changed by an origin write from or to v. */
const LEAVING = meshArrays.length;

/** One number per field of the mesh: array `array` (or `LEAVING`) at `index`. */
function fieldKey(array: number, index: number): number {
  return 16 * index + array;
}

/** Calls `visit` with every field `write` may change: the pointer it sets, or every field of the element it makes or deletes. */
function fieldsOf(write: PracticeWrite, visit: (array: number, index: number) => void): void {
  switch (write.field) {
    case 'position':
      return;
    case 'newVertex':
    case 'deleteVertex':
      return visitEach(OWNED.vertex, write.index, visit);
    case 'newEdge':
    case 'deleteEdge':
      visitEach(OWNED.edge, write.index, visit);
      visitEach(OWNED.halfedge, 2 * write.index, visit);
      return visitEach(OWNED.halfedge, 2 * write.index + 1, visit);
    case 'newFace':
    case 'deleteFace':
      return visitEach(OWNED.face, write.index, visit);
    default:
      visit(meshArrayIndex[pointerArrayOf[write.field]], write.index);
  }
}

function visitEach(arrays: readonly number[], index: number, visit: (array: number, index: number) => void): void {
  for (const array of arrays) visit(array, index);
}

/** The arrays each kind of element owns, by their place in `meshArrays`. */
const OWNED = Object.fromEntries(elementKinds.map((kind) => [kind, meshArrays.flatMap((spec, array) => (spec.owner === kind ? [array] : []))])) as Record<ElementKind, number[]>;

/**
 * `mesh` as the checks see it, noting in `reads` every entry of its arrays they read: the checks
 * of `invariants.ts` run on it unchanged, so what is noted is exactly what they read.
 */
function readingView(mesh: HalfedgeMesh, reads: Set<number>): HalfedgeMesh {
  return new Proxy(mesh, {
    get(target, name) {
      const value = Reflect.get(target, name);
      if (typeof name !== 'string' || !Object.hasOwn(meshArrayIndex, name)) return value;
      const array = meshArrayIndex[name as MeshArrayName];
      return new Proxy(value as Int32Array | Uint8Array, {
        get(entries, key) {
          const index = typeof key === 'string' ? Number(key) : NaN;
          if (Number.isInteger(index)) reads.add(fieldKey(array, index));
          return Reflect.get(entries, key);
        },
      });
    },
  });
}
