/**
 * The page's own copy of the session's mesh and render buffers: taken whole from a snapshot that
 * carries them, or changed in place by a snapshot's patch (the change record applied forwards, the
 * render writes copied in), so after an edit the page touches only what the edit changed.
 */
import { applyChange, type ChangeRecord, changesLiveIds, deserializeMesh, type HalfedgeMesh } from '../core/index.js';
import type { RenderBuffers, RenderPatch, Snapshot, SnapshotDetails } from './protocol.js';

/**
 * A snapshot as the page holds it: the mesh and the render buffers are the page's own, changed in
 * place when a snapshot comes as a patch (`renderPatch` then lists the ranges to upload again).
 * `pending`: the counts beyond V, E, F, χ and the boundary edges are the last full pass's until
 * `details()`, and `problems` the check of what the change touched (see `Snapshot.details`).
 */
export interface PageSnapshot extends Omit<Snapshot, 'mesh' | 'render' | 'patch' | 'details'>, Omit<SnapshotDetails, 'version'> {
  mesh: HalfedgeMesh;
  render: RenderBuffers;
  renderPatch: RenderPatch | null;
  /** The change record that led to `mesh` from the snapshot before, when this one came as a patch. */
  change: ChangeRecord | null;
  pending: boolean;
  /**
   * Changes whenever `mesh` may hold other live ids than at the snapshot before: a whole mesh
   * taken, or a patch that created or deleted elements. The same number on the same mesh object
   * means the same live ids (a view may keep what it listed of them).
   */
  idsVersion: number;
}

export class PageCopy {
  private held: { version: number; mesh: HalfedgeMesh; render: RenderBuffers } | null = null;
  private idsVersion = 0;

  /** The mesh held (null before the first snapshot). */
  get mesh(): HalfedgeMesh | null {
    return this.held?.mesh ?? null;
  }

  /** Whether `take` can use this snapshot: a whole one, or a patch of the version held. */
  accepts(snapshot: Snapshot): boolean {
    return !snapshot.patch || this.held?.version === snapshot.patch.from;
  }

  /**
   * Makes the snapshot's mesh and buffers the page's own: adopted whole, or patched in place.
   * @throws Error for a patch of another version than the one held (check `accepts` first).
   */
  take(snapshot: Snapshot): PageSnapshot {
    const { mesh, render, patch, details, ...rest } = snapshot;
    if (patch) {
      if (!this.held || this.held.version !== patch.from) throw new Error(`a patch of snapshot ${patch.from}, but the page holds ${this.held?.version}`);
      applyChange(this.held.mesh, patch.change, 'forward');
      if (changesLiveIds(patch.change)) this.idsVersion++;
      for (const { buffer, offset, data } of patch.render.writes) (this.held.render[buffer] as Float32Array).set(data as Float32Array, offset);
      this.held.render.counts = patch.render.counts;
      this.held.version = snapshot.version;
    } else {
      this.held = { version: snapshot.version, mesh: deserializeMesh(mesh!), render: render! };
      this.idsVersion++;
    }
    const { version: _, ...full } = details;
    return { ...rest, ...full, mesh: this.held.mesh, render: this.held.render, renderPatch: patch?.render ?? null, change: patch?.change ?? null, idsVersion: this.idsVersion };
  }
}
