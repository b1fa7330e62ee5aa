/**
 * The mesh a solution sees: the lecture's vocabulary (`next`, `twin`, `origin`, `setNext`, …) over
 * a `HalfedgeMesh`, where every write is logged with the line that made it and every read counts
 * against a budget, so code that walks a broken cycle forever is stopped with what it was doing.
 *
 * Every id is checked before use: a solution that asks for `next(h99)` on a mesh of 36 halfedges,
 * or writes to a deleted face, gets an error at its own line instead of a corrupted array.
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { PointerWriteField, PracticeWrite } from './writes.js';

export interface PracticeBudget {
  /** Pointer reads before the code is stopped. */
  reads: number;
  /** Milliseconds before the code is stopped (checked while it reads). */
  milliseconds: number;
  /** New vertices, edges and faces, of each kind, the code may make. */
  newElements: number;
}

/** The budget of a run on a small fixture, and the least any run gets. */
export const DEFAULT_BUDGET: PracticeBudget = { reads: 1_000_000, milliseconds: 2000, newElements: 10_000 };

/**
 * The budget of a run on `mesh`: `DEFAULT_BUDGET`, or more in proportion to its halfedges on a
 * large fixture. An operation over the whole mesh (a subdivision level) reads, writes and makes a
 * fixed amount per halfedge: about 20 reads, 25 writes and 1.5 new edges. The writes take the
 * time, each logged with its line (a stack trace of tens of microseconds): 0.7 ms per halfedge
 * in Node on a busy machine, 45 s for a Loop level on 20,000 triangles. The budget leaves room
 * above each, a few times over.
 */
export function budgetFor(mesh: HalfedgeMesh): PracticeBudget {
  const halfedges = mesh.nHalfedges;
  return {
    reads: Math.max(DEFAULT_BUDGET.reads, 100 * halfedges),
    milliseconds: Math.max(DEFAULT_BUDGET.milliseconds, 2 * halfedges),
    newElements: Math.max(DEFAULT_BUDGET.newElements, 2 * halfedges),
  };
}

/** Thrown when code runs past a budget; the message says what it was doing. */
export class BudgetError extends Error {
  override readonly name = 'BudgetError';
}

/** A mistake in the use of the API (a missing element, a wrong argument), thrown at the student's line. */
export class PracticeApiError extends Error {
  override readonly name = 'PracticeApiError';
}

/** What the API saw the code do. */
export interface PracticeTrace {
  writes: PracticeWrite[];
  /** Halfedges the code read a pointer of, in order (the first `MAX_VISITS`). */
  visits: number[];
  reads: number;
}

export const MAX_VISITS = 10_000;

/** The functions a solution calls, as `mesh.next(h)`; each is a plain function (no `this`). */
export type PracticeMesh = ReturnType<typeof practiceMesh>['api'];

/** How often the clock is read while the code reads pointers. */
const CLOCK_EVERY = 4096;
/** The last halfedges read, kept to say which cycle an endless loop goes round. */
const RECENT = 64;

/**
 * The API over `mesh` (which the code's writes change), the trace it fills, and `lineOf()`, which
 * says which line of the solution is running (from a stack trace; null when unknown).
 */
export function practiceMesh(mesh: HalfedgeMesh, lineOf: () => number | null, budget: PracticeBudget = budgetFor(mesh), now: () => number = Date.now) {
  const trace: PracticeTrace = { writes: [], visits: [], reads: 0 };
  const recent: number[] = [];
  const recentFields: string[] = [];
  const started = now();
  const created = { vertex: 0, edge: 0, face: 0 };

  const read = (field: string, h: number) => {
    if (trace.visits.length < MAX_VISITS) trace.visits.push(h);
    recent.push(h);
    recentFields.push(field);
    if (recent.length > RECENT) {
      recent.shift();
      recentFields.shift();
    }
    tick();
  };
  const tick = () => {
    trace.reads++;
    if (trace.reads > budget.reads) throw new BudgetError(`your code read ${budget.reads.toLocaleString('en')} pointers without returning${describeCycle(recent, recentFields)}`);
    if (trace.reads % CLOCK_EVERY === 0 && now() - started > budget.milliseconds) {
      throw new BudgetError(`your code ran for ${budget.milliseconds / 1000} s without returning${describeCycle(recent, recentFields)}`);
    }
  };

  const halfedge = (h: unknown, what: string) => checkId(h, mesh.halfedgeSlots, (i) => mesh.eDeleted[i >> 1] === 1, 'h', what, 'halfedge');
  const vertex = (v: unknown, what: string) => checkId(v, mesh.vertexSlots, (i) => mesh.vDeleted[i] === 1, 'v', what, 'vertex');
  const face = (f: unknown, what: string) => checkId(f, mesh.faceSlots, (i) => mesh.fDeleted[i] === 1, 'f', what, 'face');
  const edge = (e: unknown, what: string) => checkId(e, mesh.edgeSlots, (i) => mesh.eDeleted[i] === 1, 'e', what, 'edge');
  /** A halfedge or -1 (a value a pointer may be set to). */
  const halfedgeOrNone = (h: unknown, what: string) => (h === -1 ? -1 : halfedge(h, what));

  const log = (field: PracticeWrite['field'], index: number, old: PracticeWrite['old'], value: PracticeWrite['new']) => {
    // a literal with the same five keys every time: a spread made each of a million writes an
    // object of its own shape, five times the memory and the time
    trace.writes.push({ field, index, old, new: value, line: lineOf() } as PracticeWrite);
  };
  const writePointer = (field: PointerWriteField, array: Int32Array, index: number, value: number) => {
    log(field, index, array[index], value);
    array[index] = value;
  };
  const make = (kind: keyof typeof created) => {
    if (++created[kind] > budget.newElements) {
      throw new BudgetError(`your code made more than ${budget.newElements.toLocaleString('en')} new ${kind === 'vertex' ? 'vertices' : `${kind}s`}: far more than this exercise needs (a loop that keeps adding?)`);
    }
  };

  const api = {
    next: (h: number) => (read('next', halfedge(h, 'next')), mesh.heNext[h]),
    prev: (h: number) => (read('prev', halfedge(h, 'prev')), mesh.hePrev[h]),
    twin: (h: number) => (read('twin', halfedge(h, 'twin')), h ^ 1),
    origin: (h: number) => (read('origin', halfedge(h, 'origin')), mesh.heVertex[h]),
    target: (h: number) => {
      read('target', halfedge(h, 'target'));
      const n = mesh.heNext[h];
      return n < 0 ? -1 : mesh.heVertex[n];
    },
    face: (h: number) => (read('face', halfedge(h, 'face')), mesh.heFace[h]),
    edge: (h: number) => (read('edge', halfedge(h, 'edge')), h >> 1),
    isBoundary: (h: number) => (read('isBoundary', halfedge(h, 'isBoundary')), mesh.heFace[h] === -1),
    vertexHalfedge: (v: number) => (vertex(v, 'vertexHalfedge'), tick(), mesh.vHalfedge[v]),
    faceHalfedge: (f: number) => (face(f, 'faceHalfedge'), tick(), mesh.fHalfedge[f]),
    edgeHalfedge: (e: number) => (edge(e, 'edgeHalfedge'), 2 * e),
    position: (v: number) => {
      vertex(v, 'position');
      const p = mesh.positions;
      return [p[3 * v], p[3 * v + 1], p[3 * v + 2]];
    },

    setNext: (h: number, n: number) => {
      halfedge(h, 'setNext');
      halfedge(n, 'setNext');
      writePointer('next', mesh.heNext, h, n);
      writePointer('prev', mesh.hePrev, n, h);
    },
    setOrigin: (h: number, v: number) => {
      halfedge(h, 'setOrigin');
      vertex(v, 'setOrigin');
      writePointer('origin', mesh.heVertex, h, v);
    },
    setFace: (h: number, f: number) => {
      halfedge(h, 'setFace');
      if (f !== -1) face(f, 'setFace');
      writePointer('face', mesh.heFace, h, f);
    },
    setVertexHalfedge: (v: number, h: number) => {
      vertex(v, 'setVertexHalfedge');
      writePointer('vertexHalfedge', mesh.vHalfedge, v, halfedgeOrNone(h, 'setVertexHalfedge'));
    },
    setFaceHalfedge: (f: number, h: number) => {
      face(f, 'setFaceHalfedge');
      writePointer('faceHalfedge', mesh.fHalfedge, f, halfedge(h, 'setFaceHalfedge'));
    },
    setPosition: (v: number, p: number[]) => {
      vertex(v, 'setPosition');
      const to = point(p, 'setPosition');
      const old = api.position(v);
      log('position', v, old, to);
      mesh.setPosition(v, to[0], to[1], to[2]);
    },

    newVertex: (p: number[] = [0, 0, 0]) => {
      const at = point(p, 'newVertex');
      make('vertex');
      const v = mesh.addVertex(at[0], at[1], at[2]);
      log('newVertex', v, null, at);
      return v;
    },
    /** A new edge; returns its first halfedge h (the other is twin(h)); every pointer of both is -1. */
    newEdge: () => {
      make('edge');
      const e = mesh.addEdge();
      log('newEdge', e, null, null);
      return 2 * e;
    },
    newFace: () => {
      make('face');
      const f = mesh.addFace();
      log('newFace', f, null, null);
      return f;
    },
    deleteVertex: (v: number) => {
      vertex(v, 'deleteVertex');
      log('deleteVertex', v, null, null);
      mesh.deleteVertex(v);
    },
    deleteEdge: (e: number) => {
      edge(e, 'deleteEdge');
      log('deleteEdge', e, null, null);
      mesh.deleteEdge(e);
    },
    deleteFace: (f: number) => {
      face(f, 'deleteFace');
      log('deleteFace', f, null, null);
      mesh.deleteFace(f);
    },

    vertexCount: () => mesh.nVertices,
    edgeCount: () => mesh.nEdges,
    faceCount: () => mesh.nFaces,
    halfedgeCount: () => mesh.nHalfedges,
    vertices: () => [...mesh.vertices()],
    edges: () => [...mesh.edges()],
    faces: () => [...mesh.faces()],
    halfedges: () => [...mesh.halfedges()],
  };
  return { api, trace };
}

/** The names of the API, in the order the panel documents them. */
export const PRACTICE_API_NAMES = Object.keys(
  practiceMesh({ halfedgeSlots: 0 } as HalfedgeMesh, () => null, DEFAULT_BUDGET).api,
) as (keyof PracticeMesh)[];

function checkId(id: unknown, slots: number, deleted: (i: number) => boolean, prefix: string, what: string, kind: string): number {
  if (typeof id !== 'number' || !Number.isInteger(id)) {
    throw new PracticeApiError(`${what}(…) was given ${describe(id)} where a ${kind} id (an integer) belongs`);
  }
  if (id < 0 || id >= slots) {
    const range = slots === 0 ? 'the mesh has none' : `the mesh has ${prefix}0 … ${prefix}${slots - 1}`;
    throw new PracticeApiError(`${what}(${id}): there is no ${kind} ${prefix}${id} (${range})${id === -1 ? '; -1 means "none": check for it before following it' : ''}`);
  }
  if (deleted(id)) throw new PracticeApiError(`${what}(${prefix}${id}): ${prefix}${id} has been deleted`);
  return id;
}

function point(p: unknown, what: string): number[] {
  if (!Array.isArray(p) || p.length !== 3 || !p.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new PracticeApiError(`${what}(…) was given ${describe(p)} where a position [x, y, z] of three finite numbers belongs`);
  }
  return [p[0], p[1], p[2]];
}

function describe(value: unknown): string {
  if (value === undefined) return 'undefined';
  if (typeof value === 'string') return `the string "${value.slice(0, 20)}"`;
  if (Array.isArray(value)) return `an array of ${value.length}`;
  return typeof value === 'object' && value !== null ? 'an object' : String(value);
}

/** ": its last reads went round h3 → h7 → h3 again and again, …" when the recent reads repeat. */
function describeCycle(recent: number[], fields: string[]): string {
  for (let period = 1; period <= recent.length / 3; period++) {
    let repeats = true;
    for (let i = period; i < recent.length && repeats; i++) repeats = recent[i] === recent[i - period];
    if (!repeats) continue;
    // a loop that reads origin(h) and next(h) reads each halfedge twice in a row: name it once
    const cycle = recent.slice(-period).filter((h, i, all) => h !== all[(i + period - 1) % period] || period === 1);
    const names = [...cycle, cycle[0]].map((h) => `h${h}`).join(' → ');
    const pointers = [...new Set(fields.slice(-period))].join(', ');
    return `: its last reads went round ${names} again and again (reading ${pointers}), a cycle that never reaches the halfedge the loop waits for`;
  }
  return '';
}
