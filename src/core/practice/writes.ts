/**
 * What a student's code wrote, one entry per store, in the order it happened, with the source line
 * that made it. The same list replays onto the mesh the code was given (`replayWrites`), so the
 * grader rebuilds the result outside the sandbox and the page shows the mesh after any write. A
 * replay writes through a `PointerWriter`, as the library's edits do: recorded (`recordWrites`),
 * the writes become a change record, which "Use my code" sends to the session as it sends an edit's.
 *
 * ```
 *   setNext(h4, h9) at line 12  ──►  { field: 'next', index: 4, old: 5, new: 9, line: 12 }
 *                                    { field: 'prev', index: 9, old: 8, new: 4, line: 12 }
 *   newEdge()       at line 13  ──►  { field: 'newEdge', index: 18, old: null, new: null, line: 13 }
 * ```
 */
import type { PointerChange } from '../change/diff.js';
import type { ChangeRecord } from '../change/record.js';
import { PointerWriter } from '../change/writer.js';
import type { HalfedgeMesh } from '../mesh.js';
import { type ElementKind, slotCount } from '../mesh-arrays.js';

/** The pointer fields a solution writes, named as the mesh API names them. */
export type PointerWriteField = 'next' | 'prev' | 'origin' | 'face' | 'vertexHalfedge' | 'faceHalfedge';

export type PracticeWrite =
  | { field: PointerWriteField; index: number; old: number; new: number; line: number | null }
  | { field: 'position'; index: number; old: number[]; new: number[]; line: number | null }
  /** A new element: `index` is its id (for an edge, halfedges 2·index and 2·index + 1); a vertex's `new` is its position. */
  | { field: 'newVertex'; index: number; old: null; new: number[]; line: number | null }
  | { field: 'newEdge' | 'newFace'; index: number; old: null; new: null; line: number | null }
  | { field: 'deleteVertex' | 'deleteEdge' | 'deleteFace'; index: number; old: null; new: null; line: number | null };

/** The mesh array each pointer field is stored in. */
export const pointerArrayOf = {
  next: 'heNext',
  prev: 'hePrev',
  origin: 'heVertex',
  face: 'heFace',
  vertexHalfedge: 'vHalfedge',
  faceHalfedge: 'fHalfedge',
} as const satisfies Record<PointerWriteField, keyof HalfedgeMesh>;

/** Applies one write through `w` to its mesh (which must be as it was before that write). */
export function applyWrite(w: PointerWriter, write: PracticeWrite): void {
  const { mesh } = w;
  switch (write.field) {
    case 'position':
      w.setPosition(write.index, write.new[0], write.new[1], write.new[2]);
      return;
    case 'newVertex': {
      const v = w.addVertex();
      expectId(v, write);
      w.setPosition(v, write.new[0], write.new[1], write.new[2]);
      return;
    }
    case 'newEdge':
      expectId(w.addEdge(), write);
      return;
    case 'newFace':
      expectId(w.addFace(), write);
      return;
    case 'deleteVertex':
      w.deleteVertex(write.index);
      return;
    case 'deleteEdge':
      w.deleteEdge(write.index);
      return;
    case 'deleteFace':
      w.deleteFace(write.index);
      return;
    default: {
      // the mesh API writes -1 or an element that exists (which the first-broken search relies on)
      const kind = pointerKindOf[write.field];
      if (write.new < -1 || write.new >= slotCount(mesh, kind)) throw new Error(`replaying ${describeWrite(write)}: there is no ${kind} ${write.new} yet`);
      setPointer[write.field](w, write.index, write.new);
    }
  }
}

/** Each pointer field's write, through the writer. */
const setPointer: Record<PointerWriteField, (w: PointerWriter, index: number, value: number) => void> = {
  next: (w, h, n) => w.setNext(h, n),
  prev: (w, h, p) => w.setPrev(h, p),
  origin: (w, h, v) => w.setOrigin(h, v),
  face: (w, h, f) => w.setFace(h, f),
  vertexHalfedge: (w, v, h) => w.setVertexHalfedge(v, h),
  faceHalfedge: (w, f, h) => w.setFaceHalfedge(f, h),
};

/** The kind of element each pointer field names. */
const pointerKindOf = {
  next: 'halfedge',
  prev: 'halfedge',
  origin: 'vertex',
  face: 'face',
  vertexHalfedge: 'halfedge',
  faceHalfedge: 'halfedge',
} as const satisfies Record<PointerWriteField, ElementKind>;

/** A writer that replays writes onto `mesh`, recording nothing. */
export function replayWriter(mesh: HalfedgeMesh): PointerWriter {
  return new PointerWriter(mesh, { record: false, ids: false });
}

/** `mesh` after the first `count` writes (all of them by default), applied in place. */
export function replayWrites(mesh: HalfedgeMesh, writes: readonly PracticeWrite[], count = writes.length): HalfedgeMesh {
  const w = replayWriter(mesh);
  for (let i = 0; i < count; i++) applyWrite(w, writes[i]);
  return mesh;
}

/**
 * Replays the writes onto `mesh` (in place) and returns their change record: every field and
 * value they changed, old → new, as an edit of the library's records it.
 */
export function recordWrites(mesh: HalfedgeMesh, writes: readonly PracticeWrite[]): ChangeRecord {
  const w = new PointerWriter(mesh, { ids: false });
  for (const write of writes) applyWrite(w, write);
  return w.result().record!;
}

function expectId(id: number, write: PracticeWrite): void {
  // slots are handed out in order, so a replay makes the same ids as the run did
  if (id !== write.index) throw new Error(`replaying ${write.field} made id ${id}, the run made ${write.index}`);
}

/** One write in words, as the student wrote it: `next(h4) = h9`, `newEdge() → h18, h19`. */
export function describeWrite(write: PracticeWrite): string {
  const name = (field: PointerWriteField, id: number) => {
    if (id === -1) return '-1';
    const prefix = field === 'origin' ? 'v' : field === 'face' ? 'f' : 'h';
    return `${prefix}${id}`;
  };
  switch (write.field) {
    case 'position':
      return `position(v${write.index}) = [${write.new.map(round).join(', ')}]`;
    case 'newVertex':
      return `newVertex() → v${write.index}`;
    case 'newEdge':
      return `newEdge() → h${2 * write.index}, h${2 * write.index + 1}`;
    case 'newFace':
      return `newFace() → f${write.index}`;
    case 'deleteVertex':
      return `deleteVertex(v${write.index})`;
    case 'deleteEdge':
      return `deleteEdge(e${write.index})`;
    case 'deleteFace':
      return `deleteFace(f${write.index})`;
    default: {
      const owner = write.field === 'vertexHalfedge' ? 'v' : write.field === 'faceHalfedge' ? 'f' : 'h';
      return `${write.field}(${owner}${write.index}) = ${name(write.field, write.new)}`;
    }
  }
}

function round(x: number): string {
  return String(Math.round(x * 1e4) / 1e4);
}

/** The write as the pointer diff draws it (null for a write that is not a pointer: a position, a new or deleted element). */
export function pointerChangeOf(write: PracticeWrite): PointerChange | null {
  switch (write.field) {
    case 'next':
    case 'prev':
    case 'origin':
    case 'face':
      return { element: 'halfedge', id: write.index, field: write.field, before: write.old, after: write.new };
    case 'vertexHalfedge':
      return { element: 'vertex', id: write.index, field: 'halfedge', before: write.old, after: write.new };
    case 'faceHalfedge':
      return { element: 'face', id: write.index, field: 'halfedge', before: write.old, after: write.new };
    default:
      return null;
  }
}
