/**
 * How the local edits write pointers, and how they report what they wrote.
 *
 * Every edit changes the mesh through a `PointerWriter`. When recording, the writer remembers each
 * pointer field's value before its first write; at the end it lists the fields whose value really
 * changed, old → new, in the same form and order as `diffPointers(before, after)` would (so the
 * app can draw "what did this edit rewire?" without keeping a copy of the mesh). Without
 * recording, a write is just the store, which is what bulk callers (decimation, the plane cut)
 * want.
 *
 * ```
 *   next(h) is 7
 *   write next(h) = 4   ──► remember that next(h) was 7 (only at the first write)
 *   write next(h) = 9   ──► (already remembered)
 *   result()            ──► { halfedge h, next: 7 → 9 }  (nothing at all had it ended as 7)
 * ```
 */
import type { PointerChange, PointerField } from '../diff.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { ElementIds } from '../operation.js';

export interface EditOptions {
  /**
   * List every pointer the edit changes in `changes` (default true). Callers that edit in bulk
   * (decimation) pass false: the edit then costs only its stores.
   */
  record?: boolean;
  /** List the elements the edit adds and deletes in `created` and `removed` (default true). */
  ids?: boolean;
}

/** What a local edit did. */
export interface EditResult {
  /** Every pointer field that changed, old → new, as `diffPointers` lists them; empty when not recording. */
  changes: PointerChange[];
  /** Elements the edit added. */
  created: ElementIds;
  /** Elements the edit deleted (marked deleted, not compacted: the other ids stay valid). */
  removed: ElementIds;
}

/** An edit that makes or keeps one vertex of interest: the new vertex of a split, the survivor of a collapse. */
export interface VertexEditResult extends EditResult {
  vertex: number;
}

// Field slots: a remembered value is keyed by `8 · id + slot`.
const NEXT = 0;
const PREV = 1;
const ORIGIN = 2;
const FACE = 3;
const VERTEX_HALFEDGE = 4;
const FACE_HALFEDGE = 5;
const FIELD_NAMES: PointerField[] = ['next', 'prev', 'origin', 'face', 'halfedge', 'halfedge'];
/** diffPointers lists halfedges first, then vertices, then faces. */
const SLOT_ORDER = [0, 0, 0, 0, 1, 2];

export class PointerWriter {
  private readonly before: Map<number, number> | null;
  private readonly createdIds: IdLists | null;
  private readonly removedIds: IdLists | null;

  constructor(
    readonly mesh: HalfedgeMesh,
    options: EditOptions = {},
  ) {
    this.before = options.record === false ? null : new Map();
    const ids = options.ids !== false;
    this.createdIds = ids ? { vertices: [], edges: [], faces: [] } : null;
    this.removedIds = ids ? { vertices: [], edges: [], faces: [] } : null;
  }

  /** `next(h) = n` and `prev(n) = h`: the two always change together. */
  link(h: number, n: number): void {
    const { heNext, hePrev } = this.mesh;
    if (this.before) {
      this.remember(h, NEXT, heNext[h]);
      this.remember(n, PREV, hePrev[n]);
    }
    heNext[h] = n;
    hePrev[n] = h;
  }

  setOrigin(h: number, v: number): void {
    if (this.before) this.remember(h, ORIGIN, this.mesh.heVertex[h]);
    this.mesh.heVertex[h] = v;
  }

  setFace(h: number, f: number): void {
    if (this.before) this.remember(h, FACE, this.mesh.heFace[h]);
    this.mesh.heFace[h] = f;
  }

  setVertexHalfedge(v: number, h: number): void {
    if (this.before) this.remember(v, VERTEX_HALFEDGE, this.mesh.vHalfedge[v]);
    this.mesh.vHalfedge[v] = h;
  }

  setFaceHalfedge(f: number, h: number): void {
    if (this.before) this.remember(f, FACE_HALFEDGE, this.mesh.fHalfedge[f]);
    this.mesh.fHalfedge[f] = h;
  }

  /** A new isolated vertex (attributes zero until the edit blends them). */
  addVertex(): number {
    const v = this.mesh.addVertex();
    this.createdIds?.vertices.push(v);
    return v;
  }

  /** A new edge, halfedges `2e` and `2e + 1`, every pointer -1. */
  addEdge(): number {
    const e = this.mesh.addEdge();
    this.createdIds?.edges.push(e);
    return e;
  }

  addFace(): number {
    const f = this.mesh.addFace();
    this.createdIds?.faces.push(f);
    return f;
  }

  deleteVertex(v: number): void {
    if (this.before) this.remember(v, VERTEX_HALFEDGE, this.mesh.vHalfedge[v]);
    this.mesh.deleteVertex(v);
    this.removedIds?.vertices.push(v);
  }

  /** Deletes both halfedges of `e` (every pointer of theirs becomes -1). */
  deleteEdge(e: number): void {
    if (this.before) {
      const { heNext, hePrev, heVertex, heFace } = this.mesh;
      for (let h = 2 * e; h < 2 * e + 2; h++) {
        this.remember(h, NEXT, heNext[h]);
        this.remember(h, PREV, hePrev[h]);
        this.remember(h, ORIGIN, heVertex[h]);
        this.remember(h, FACE, heFace[h]);
      }
    }
    this.mesh.deleteEdge(e);
    this.removedIds?.edges.push(e);
  }

  deleteFace(f: number): void {
    if (this.before) this.remember(f, FACE_HALFEDGE, this.mesh.fHalfedge[f]);
    this.mesh.deleteFace(f);
    this.removedIds?.faces.push(f);
  }

  /** The changes (old → new, unchanged fields left out), and the elements added and deleted. */
  result(): EditResult {
    return { changes: this.changes(), created: toIds(this.createdIds), removed: toIds(this.removedIds) };
  }

  private remember(id: number, slot: number, value: number): void {
    const key = 8 * id + slot;
    if (!this.before!.has(key)) this.before!.set(key, value);
  }

  private changes(): PointerChange[] {
    if (!this.before) return [];
    const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge } = this.mesh;
    const current = [heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge];
    const keys = [...this.before.keys()].sort((p, q) => {
      const byKind = SLOT_ORDER[p % 8] - SLOT_ORDER[q % 8];
      return byKind !== 0 ? byKind : p - q;
    });
    const changes: PointerChange[] = [];
    for (const key of keys) {
      const id = Math.floor(key / 8);
      const slot = key % 8;
      const before = this.before.get(key)!;
      const after = current[slot][id];
      if (before === after) continue;
      const element = slot < VERTEX_HALFEDGE ? 'halfedge' : slot === VERTEX_HALFEDGE ? 'vertex' : 'face';
      changes.push({ element, id, field: FIELD_NAMES[slot], before, after });
    }
    return changes;
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
