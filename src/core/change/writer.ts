/**
 * How the local edits write: every pointer, flag and attribute value an edit changes goes through
 * a `PointerWriter`, so the edit's change record is written as it happens.
 *
 * When recording, the writer remembers each field's value before its first write (and each
 * element's attribute values before their first write); at the end, `result()` gives the change
 * record (which undoes and redoes the edit, and patches the page's copy of the mesh) and the
 * pointer fields whose value really changed, old → new, in the same form and order as
 * `diffPointers(before, after)` would list them. A phase made of many edits (a batch of
 * collapses) gives its writers one recorder to share; run straight through, it records nothing and
 * a write is just the store.
 *
 * ```
 *   next(h) is 7
 *   write next(h) = 4   ──► remember that next(h) was 7 (only at the first write)
 *   write next(h) = 9   ──► (already remembered)
 *   result()            ──► { halfedge h, next: 7 → 9 }  (nothing at all had it ended as 7)
 * ```
 */
import { type ChangeRecord, pointerDiffOf } from './record.js';
import { ChangeRecorder } from './recorder.js';
import type { PointerChange } from './diff.js';
import type { HalfedgeMesh } from '../mesh.js';
import { attributeSetOf, type ElementKind, meshArrayIndex } from '../mesh-arrays.js';
import type { ElementIds } from './operation.js';

export interface EditOptions {
  /**
   * List every pointer the edit changes in `changes` (default true). Callers that edit in bulk
   * (decimation) pass false: the edit then costs only its stores.
   */
  record?: boolean;
  /**
   * Write the record here instead of one of the edit's own: a phase made of many edits (a batch
   * of collapses, the cut's splits) keeps one record of them all. The edit's `record` is then null.
   */
  recorder?: ChangeRecorder | null;
  /** List the elements the edit adds and deletes in `created` and `removed` (default true). */
  ids?: boolean;
}

/** What a local edit did. */
export interface EditResult {
  /** Every pointer field that changed, old → new, as `diffPointers` lists them; empty when not recording. */
  changes: PointerChange[];
  /** The whole change (pointers, flags, slots, attribute values), null when not recording. */
  record: ChangeRecord | null;
  /** Elements the edit added. */
  created: ElementIds;
  /** Elements the edit deleted (marked deleted, not compacted: the other ids stay valid). */
  removed: ElementIds;
}

/** An edit that makes or keeps one vertex of interest: the new vertex of a split, the survivor of a collapse. */
export interface VertexEditResult extends EditResult {
  vertex: number;
}

/** An edit that makes or keeps one face of interest: the merged face of a dissolve. */
export interface FaceEditResult extends EditResult {
  face: number;
}

/** An edit that names one halfedge of interest: a boundary halfedge of the hole `makeBoundary` made. */
export interface HalfedgeEditResult extends EditResult {
  halfedge: number;
}

/** An edit that makes or keeps one edge of interest: the edge two boundary edges were welded into. */
export interface EdgeEditResult extends EditResult {
  edge: number;
}

const { heNext: NEXT, hePrev: PREV, heVertex: ORIGIN, heFace: FACE, vHalfedge: VERTEX_HALFEDGE, fHalfedge: FACE_HALFEDGE } = meshArrayIndex;
const { vDeleted: VERTEX_DELETED, eDeleted: EDGE_DELETED, fDeleted: FACE_DELETED } = meshArrayIndex;

export class PointerWriter {
  private readonly recorder: ChangeRecorder | null;
  /** Whether the record is this writer's own (else a phase's, which its caller reads). */
  private readonly ownRecord: boolean;
  private readonly createdIds: IdLists | null;
  private readonly removedIds: IdLists | null;

  constructor(
    readonly mesh: HalfedgeMesh,
    options: EditOptions = {},
  ) {
    this.ownRecord = options.recorder === undefined && options.record !== false;
    this.recorder = options.recorder !== undefined ? options.recorder : options.record === false ? null : new ChangeRecorder(mesh);
    const ids = options.ids !== false;
    this.createdIds = ids ? { vertices: [], edges: [], faces: [] } : null;
    this.removedIds = ids ? { vertices: [], edges: [], faces: [] } : null;
  }

  /** `next(h) = n` and `prev(n) = h`: the two always change together. */
  link(h: number, n: number): void {
    this.recorder?.field(NEXT, h);
    this.recorder?.field(PREV, n);
    this.mesh.heNext[h] = n;
    this.mesh.hePrev[n] = h;
  }

  /** `next(h) = n` alone (a student's code writes `next` and `prev` apart; an edit links both). */
  setNext(h: number, n: number): void {
    this.recorder?.field(NEXT, h);
    this.mesh.heNext[h] = n;
  }

  /** `prev(h) = p` alone. */
  setPrev(h: number, p: number): void {
    this.recorder?.field(PREV, h);
    this.mesh.hePrev[h] = p;
  }

  setOrigin(h: number, v: number): void {
    this.recorder?.field(ORIGIN, h);
    this.mesh.heVertex[h] = v;
  }

  setFace(h: number, f: number): void {
    this.recorder?.field(FACE, h);
    this.mesh.heFace[h] = f;
  }

  setVertexHalfedge(v: number, h: number): void {
    this.recorder?.field(VERTEX_HALFEDGE, v);
    this.mesh.vHalfedge[v] = h;
  }

  setFaceHalfedge(f: number, h: number): void {
    this.recorder?.field(FACE_HALFEDGE, f);
    this.mesh.fHalfedge[f] = h;
  }

  setPosition(v: number, x: number, y: number, z: number): void {
    this.recorder?.element('vertex', v);
    this.mesh.setPosition(v, x, y, z);
  }

  /** Element `dst` of a kind takes the blend of `sources` for every attribute (see `AttributeSet.blend`). */
  blend(kind: ElementKind, dst: number, sources: ArrayLike<number>, weights: ArrayLike<number>): void {
    this.recorder?.element(kind, dst);
    attributeSetOf(this.mesh, kind).blend(dst, sources, weights);
  }

  /** Element `dst` of a kind takes every attribute value of element `src`. */
  copy(kind: ElementKind, dst: number, src: number): void {
    this.recorder?.element(kind, dst);
    attributeSetOf(this.mesh, kind).copy(dst, src);
  }

  /** A new isolated vertex (attributes zero until the edit blends them). */
  addVertex(): number {
    const v = this.mesh.addVertex();
    this.recorder?.element('vertex', v);
    this.createdIds?.vertices.push(v);
    return v;
  }

  /** A new edge, halfedges `2e` and `2e + 1`, every pointer -1. */
  addEdge(): number {
    const e = this.mesh.addEdge();
    this.recorder?.element('edge', e);
    this.recorder?.element('halfedge', 2 * e);
    this.recorder?.element('halfedge', 2 * e + 1);
    this.createdIds?.edges.push(e);
    return e;
  }

  addFace(): number {
    const f = this.mesh.addFace();
    this.recorder?.element('face', f);
    this.createdIds?.faces.push(f);
    return f;
  }

  deleteVertex(v: number): void {
    this.recorder?.field(VERTEX_HALFEDGE, v);
    this.recorder?.field(VERTEX_DELETED, v);
    this.mesh.deleteVertex(v);
    this.removedIds?.vertices.push(v);
  }

  /** Deletes both halfedges of `e` (every pointer of theirs becomes -1). */
  deleteEdge(e: number): void {
    const recorder = this.recorder;
    if (recorder) {
      for (let h = 2 * e; h < 2 * e + 2; h++) for (const field of [NEXT, PREV, ORIGIN, FACE]) recorder.field(field, h);
      recorder.field(EDGE_DELETED, e);
    }
    this.mesh.deleteEdge(e);
    this.removedIds?.edges.push(e);
  }

  deleteFace(f: number): void {
    this.recorder?.field(FACE_HALFEDGE, f);
    this.recorder?.field(FACE_DELETED, f);
    this.mesh.deleteFace(f);
    this.removedIds?.faces.push(f);
  }

  /** The change record and the pointer changes (old → new, unchanged fields left out), and the elements added and deleted. */
  result(): EditResult {
    const record = this.ownRecord ? this.recorder!.record() : null;
    return {
      changes: record ? pointerDiffOf(record, Infinity).changes : [],
      record,
      created: toIds(this.createdIds),
      removed: toIds(this.removedIds),
    };
  }
}

interface IdLists {
  vertices: number[];
  edges: number[];
  faces: number[];
}

function toIds(lists: IdLists | null): ElementIds {
  const ids: ElementIds = {};
  if (!lists) return ids;
  if (lists.vertices.length) ids.vertices = Int32Array.from(lists.vertices);
  if (lists.edges.length) ids.edges = Int32Array.from(lists.edges);
  if (lists.faces.length) ids.faces = Int32Array.from(lists.faces);
  return ids;
}
