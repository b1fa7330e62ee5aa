/**
 * The history of meshes a session went through, kept small. An entry is either a whole mesh (a file
 * opened, a subdivision or a cut, which change everything) or a change record (a local edit, a
 * smoothing run, which change a handful of pointers or only positions): the record, applied
 * forwards to the mesh of the entry before, gives this entry's mesh, and backwards gives it back.
 *
 * ```
 *   entries   [ open: mesh A ] [ flip: record ] [ split: record ] [ Loop: mesh B ] [ collapse: record ]
 *   segments  └──────────── mesh A, now at entry 2 ─────────────┘ └──── mesh B, now at entry 4 ────┘
 * ```
 *
 * A whole mesh and the records after it form a segment, and the segment's one mesh object is moved
 * through them in place: the current mesh is always that object, so an edit changes the current
 * mesh directly (no copy) and hands its record to `pushChange`, and undo and redo apply one record.
 */
import { applyChange, type ChangeRecord, changeBytes, type HalfedgeMesh } from '../core/index.js';
import { meshByteLength } from '../core/mesh-arrays.js';

/** Spare slots of each kind a whole mesh keeps, so that the edits after it rarely copy it to grow. */
export const EDIT_ROOM = 1024;

export interface HistoryEntry<Info> {
  label: string;
  info: Info;
  vertices: number;
  faces: number;
}

interface Stored<Info> extends HistoryEntry<Info> {
  /** The segment's mesh (for a whole-mesh entry), or null when `change` leads here from the entry before. */
  mesh: HalfedgeMesh | null;
  change: ChangeRecord | null;
  /** For a whole-mesh entry: the entry of its segment its mesh is at now. */
  at: number;
}

export class History<Info> {
  private entries: Stored<Info>[] = [];
  private index = -1;

  get position(): number {
    return this.index;
  }

  get length(): number {
    return this.entries.length;
  }

  items(): HistoryEntry<Info>[] {
    return this.entries.map(({ label, info, vertices, faces }) => ({ label, info, vertices, faces }));
  }

  entry(): HistoryEntry<Info> | null {
    return this.entries[this.index] ?? null;
  }

  /** The current mesh. Change it only to push what changed (`pushChange`). */
  mesh(): HalfedgeMesh | null {
    return this.index < 0 ? null : this.base(this.index).mesh;
  }

  /** The record that leads from the entry before to entry `index`, or null for a whole mesh. */
  changeAt(index: number): ChangeRecord | null {
    return this.entries[index]?.change ?? null;
  }

  /** Adds a whole mesh after the current entry (dropping any entries that were undone); the history owns it. */
  pushMesh(label: string, mesh: HalfedgeMesh, info: Info): void {
    this.dropRedo();
    mesh.trim(EDIT_ROOM); // kept for good: room for the edits that follow, none to waste
    this.entries.push({ label, info, vertices: mesh.nVertices, faces: mesh.nFaces, mesh, change: null, at: this.entries.length });
    this.index = this.entries.length - 1;
  }

  /**
   * Adds an entry for a change already made to the current mesh (in place), by its record.
   * @throws Error when there is no mesh to have changed.
   */
  pushChange(label: string, change: ChangeRecord, info: Info): void {
    if (this.index < 0) throw new Error('the history has no mesh to change yet');
    this.dropRedo();
    const base = this.base(this.index);
    this.entries.push({ label, info, vertices: base.mesh.nVertices, faces: base.mesh.nFaces, mesh: null, change, at: -1 });
    this.index = this.entries.length - 1;
    base.stored.at = this.index;
  }

  /** Makes entry `index` the current one. */
  moveTo(index: number): void {
    if (!Number.isInteger(index) || index < 0 || index >= this.entries.length) {
      throw new RangeError(`the history has entries 0..${this.entries.length - 1}, not ${index}`);
    }
    const { stored, mesh } = this.base(index);
    for (let i = stored.at; i > index; i--) applyChange(mesh, this.entries[i].change!, 'backward');
    for (let i = stored.at + 1; i <= index; i++) applyChange(mesh, this.entries[i].change!, 'forward');
    stored.at = index;
    this.index = index;
  }

  /** Bytes the history holds: whole meshes (their capacity) and change records. */
  bytes(): number {
    let total = 0;
    for (const { mesh, change } of this.entries) total += (change ? changeBytes(change) : 0) + (mesh ? meshByteLength(mesh) : 0);
    return total;
  }

  /** The whole-mesh entry whose segment holds entry `index`. */
  private base(index: number): { stored: Stored<Info>; mesh: HalfedgeMesh } {
    let i = index;
    while (!this.entries[i].mesh) i--;
    return { stored: this.entries[i], mesh: this.entries[i].mesh! };
  }

  /** Forgets the entries after the current one; the current segment's mesh is where it should be. */
  private dropRedo(): void {
    this.entries.length = this.index + 1;
  }
}
