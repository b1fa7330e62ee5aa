/**
 * One editing session: the current mesh, the history of meshes before it, and the operation being
 * stepped. Pure logic with no worker API in sight, so it is tested directly; `session.worker.ts`
 * exposes it to the page.
 *
 * Every change works on a copy: the meshes in the history are never edited, so undo is a move in
 * the history, cancel drops the copy, and a failing operation leaves the session as it was.
 */
import {
  type BuildReport,
  deserializeMesh,
  diffPointers,
  type HalfedgeMesh,
  type Operation,
  type Phase,
  type PointerDiff,
  type SerializedMesh,
  TopologyError,
} from '../core/index.js';
import { writeMesh, type WriteFormat } from '../core/io/index.js';
import { applyEdit, type EditRequest, operationLabel, type OperationRequest, startOperation } from './operations.js';
import { History } from './history.js';
import type { FileInfo, HistorySource, LoadedFile, ProgressListener, Snapshot } from './protocol.js';
import { makeSnapshot } from './snapshot.js';

/** What the session remembers with each mesh of the history, to show it again. */
interface EntryInfo {
  source: HistorySource;
  report: BuildReport | null;
  file: FileInfo | null;
  phase: Phase | null;
  diff: PointerDiff | null;
}

interface Stepping {
  label: string;
  /** The request as run (a subdivision with its level), which the history keeps for links. */
  request: OperationRequest;
  /** Phases the operation announced, when it knows. */
  total: number | null;
  /** The copy being changed, phase by phase. */
  working: HalfedgeMesh;
  operation: Operation;
  phases: number;
  phase: Phase | null;
  diff: PointerDiff | null;
}

/** Above this many halfedges, phases skip the pointer diff (it needs a copy of the whole mesh). */
const DIFF_HALFEDGE_LIMIT = 600_000;

export class EditingSession {
  private readonly history = new History<EntryInfo>();
  private stepping: Stepping | null = null;
  private cancelRequested = false;
  private version = 0;
  private progress: ProgressListener | null = null;

  setProgressListener(listener: ProgressListener | null): void {
    this.progress = listener;
  }

  /**
   * Makes a parsed file the current mesh (a new history entry; redo is dropped). `sample` names
   * the sample model it is (null: a file of the user's, which no link can carry).
   */
  adopt(loaded: LoadedFile, sample: string | null = null): Snapshot {
    const mesh = deserializeMesh(loaded.mesh);
    this.abandonStepping();
    const source: HistorySource = { kind: 'open', name: loaded.file.name, sample };
    this.history.push(`open ${loaded.file.name}`, mesh, { source, report: loaded.report, file: loaded.file, phase: null, diff: null });
    return this.snapshot();
  }

  restore(serialized: SerializedMesh, label: string): Snapshot {
    this.abandonStepping();
    this.history.push(label, deserializeMesh(serialized), { source: { kind: 'restore' }, report: null, file: null, phase: null, diff: null });
    return this.snapshot();
  }

  /** Starts stepping an operation on a copy of the current mesh; nothing changes until `step`. */
  start(request: OperationRequest): Snapshot {
    const current = this.currentMesh();
    this.abandonStepping();
    const working = current.clone();
    if (request.kind === 'subdivide' && request.level === undefined) {
      // how many levels of this scheme led to the current mesh (√3 alternates its boundary rule)
      const label = operationLabel(request);
      const levels = this.history.items().slice(0, this.history.position + 1).filter((entry) => entry.label === label).length;
      request = { ...request, level: levels };
    }
    // throws (leaving the session as it was) when the operation does not apply
    const { operation, phases } = startOperation(working, request);
    this.stepping = { label: operationLabel(request), request, total: phases, working, operation, phases: 0, phase: null, diff: null };
    return this.snapshot();
  }

  /** Runs the next phase; when the operation has no more, its result joins the history. */
  step(): Snapshot {
    this.stepOnce();
    return this.snapshot();
  }

  /**
   * Runs the remaining phases, yielding to the event loop between them so that `cancel` (or any
   * other call) is heard; reports progress after each phase.
   */
  async runToEnd(): Promise<Snapshot> {
    this.cancelRequested = false;
    while (this.stepping) {
      const label = this.stepping.label;
      this.stepOnce();
      const done = this.stepping ? this.stepping.phases / (this.stepping.total ?? this.stepping.phases + 1) : 1;
      this.progress?.({ label, fraction: Math.min(1, done) });
      await new Promise((resolve) => setTimeout(resolve, 0));
      if (this.cancelRequested) this.abandonStepping();
    }
    return this.snapshot();
  }

  /** Drops the operation being stepped (or run): back to the mesh before it. */
  cancel(): Snapshot {
    this.cancelRequested = true;
    this.abandonStepping();
    return this.snapshot();
  }

  edit(request: EditRequest): Snapshot {
    const current = this.currentMesh();
    this.abandonStepping();
    const mesh = current.clone();
    const result = applyEdit(mesh, request); // throws, leaving the session as it was
    this.history.push(result.label, mesh, {
      source: { kind: 'edit', request },
      report: null,
      file: this.history.entry()!.info.file,
      phase: null,
      diff: { changes: result.changes, total: result.changes.length },
    });
    return this.snapshot();
  }

  undo(): Snapshot {
    this.abandonStepping();
    if (this.history.position > 0) this.history.moveTo(this.history.position - 1);
    return this.snapshot();
  }

  redo(): Snapshot {
    this.abandonStepping();
    if (this.history.position + 1 < this.history.length) this.history.moveTo(this.history.position + 1);
    return this.snapshot();
  }

  jump(index: number): Snapshot {
    this.abandonStepping();
    this.history.moveTo(index);
    return this.snapshot();
  }

  exportMesh(format: string): Uint8Array {
    return writeMesh(this.stepping?.working ?? this.currentMesh(), format as WriteFormat);
  }

  /** Bytes the history keeps (see `History`): a test of its thrift. */
  historyBytes(): number {
    return this.history.bytes();
  }

  snapshot(): Snapshot {
    const entry = this.history.entry();
    const stepping = this.stepping;
    const mesh = stepping?.working ?? this.history.mesh();
    if (!mesh || !entry) throw new TopologyError('no mesh is open yet');
    const { info } = entry;
    return makeSnapshot(mesh, {
      version: ++this.version,
      report: stepping ? null : info.report,
      file: info.file,
      phase: stepping ? stepping.phase : info.phase,
      diff: stepping ? stepping.diff : info.diff,
      stepping: stepping ? { label: stepping.label, phases: stepping.phases, total: stepping.total } : null,
      history: {
        items: this.history.items().map(({ label, vertices, faces, info }) => ({ label, vertices, faces, source: info.source })),
        index: this.history.position,
      },
    });
  }

  private stepOnce(): void {
    const stepping = this.stepping;
    if (!stepping) throw new TopologyError('no operation is being stepped: start one first');
    const before = stepping.working.halfedgeSlots <= DIFF_HALFEDGE_LIMIT ? stepping.working.clone() : null;
    let next = stepping.operation.next();
    if (!next.done) {
      stepping.phases++;
      stepping.phase = next.value;
      stepping.diff = before ? diffPointers(before, stepping.working, 2000) : null;
      if (stepping.total === null || stepping.phases < stepping.total) return;
      // that was the last announced phase: let the operation finish now, so no empty step follows
      next = stepping.operation.next();
      if (!next.done) {
        // it had more to do than it announced: show that phase as well, and stop predicting
        stepping.phases++;
        stepping.phase = next.value;
        stepping.diff = null;
        stepping.total = null;
        return;
      }
    }
    // the operation is over: its result joins the history
    this.stepping = null;
    this.history.push(stepping.label, stepping.working, {
      source: { kind: 'operation', request: stepping.request },
      report: null,
      file: this.history.entry()!.info.file,
      phase: stepping.phase,
      diff: stepping.diff,
    });
  }

  private abandonStepping(): void {
    this.stepping = null;
  }

  private currentMesh(): HalfedgeMesh {
    const mesh = this.history.mesh();
    if (!mesh) throw new TopologyError('no mesh is open yet');
    return mesh;
  }
}
