/**
 * One editing session: the current mesh, its history, and the operation being stepped. Pure logic
 * with no worker API in sight, so it is tested directly; `session.worker.ts` exposes it to the page.
 *
 * Local edits change the current mesh in place and keep their change record as the history entry
 * (undo and redo apply it backwards or forwards); operations that change everything (subdivision,
 * the cut, decimation) work on a copy, which joins the history whole; smoothing, which only moves
 * vertices, works in place and is undone by putting the positions back.
 *
 * What the page holds: every snapshot has a version, and when the page holds the mesh just before
 * a change that has a record, the next snapshot carries the record and the render writes instead
 * of the whole mesh (`MeshPatch`), so an edit, or a stepped phase, costs what it changes.
 */
import {
  type BuildReport,
  applyChange,
  type ChangeRecord,
  deserializeMesh,
  type HalfedgeMesh,
  invertChange,
  meshFingerprint,
  type Operation,
  type Phase,
  noChange,
  onlyChangesValues,
  phaseElements,
  pointerDiffOf,
  type PointerDiff,
  positionsChange,
  seamEdges,
  type SerializedMesh,
  serializeMesh,
  TopologyError,
} from '../core/index.js';
import { type WriteFormat, writeMeshAsync } from '../core/io/index.js';
import { type ColourScale, colourScale } from './colour-scale.js';
import { applyEdit, type EditRequest, operationLabel, type OperationRequest, startOperation } from './operations.js';
import { EDIT_ROOM, History } from './history.js';
import { type FileInfo, type HistorySource, type LoadedFile, PHASE_MARKS, type ProgressListener, type ShownPhase, type Snapshot, type SnapshotDetails, type SnapshotVerbs, type SteppingState } from './protocol.js';
import { RenderLayout } from './render.js';
import { fullDetails, movedDetails, patchedDetails } from './snapshot.js';

/** What the session remembers with each mesh of the history, to show it again. */
interface EntryInfo {
  source: HistorySource;
  report: BuildReport | null;
  file: FileInfo | null;
  phase: ShownPhase | null;
  diff: PointerDiff | null;
}

interface Stepping {
  label: string;
  /** The request as run (a subdivision with its level), which the history keeps for links. */
  request: OperationRequest;
  /** Phases the operation announced, when it knows. */
  total: number | null;
  /** The mesh being changed, phase by phase: a copy, or the current mesh itself (`startPositions` set). */
  working: HalfedgeMesh;
  /** For an operation that only moves vertices, run in place: the positions to put back on cancel. */
  startPositions: Float64Array<ArrayBuffer> | null;
  operation: Operation;
  phases: number;
  /** The last phase run (null before the first), its record the page's patch. */
  phase: Phase | null;
  /** How the last phase is shown (its marks and pointer diff), worked out when first sent: a run to the end shows only its last. */
  shown: { phase: ShownPhase; diff: PointerDiff } | null;
}

/** Pointer changes a phase's diff lists (all are counted). */
const DIFF_LIMIT = 1000;

export class EditingSession implements SnapshotVerbs<Snapshot | Promise<Snapshot>> {
  private readonly history = new History<EntryInfo>();
  private stepping: Stepping | null = null;
  /**
   * The operation the last `step` finished: its last phase stays on show (card, colours, diff) and
   * can be stepped back into, until the mesh changes again.
   */
  private ended: Stepping | null = null;
  private cancelRequested = false;
  private version = 0;
  /** Counts every change of the mesh on screen; a patch applies to the state it was made from. */
  private state = 0;
  /** The version and state of the last snapshot sent: what the page holds. */
  private sent: { version: number; state: number } | null = null;
  private readonly layout = new RenderLayout();
  /** The counts and checks of the last snapshot sent: a full pass, or patched (see `patchedDetails`). */
  private lastDetails: SnapshotDetails | null = null;
  /**
   * Whether the connectivity is still that of the last full pass (only vertices moved since, as
   * smoothing does): `details()` then measures the surface again and keeps the rest.
   */
  private connectivityChecked = false;
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
    this.history.pushMesh(`open ${loaded.file.name}`, mesh, { source, report: loaded.report, file: loaded.file, phase: null, diff: null });
    this.state++;
    return this.send(null, -1);
  }

  restore(serialized: SerializedMesh, label: string): Snapshot {
    this.abandonStepping();
    this.history.pushMesh(label, deserializeMesh(serialized), { source: { kind: 'restore' }, report: null, file: null, phase: null, diff: null });
    this.state++;
    return this.send(null, -1);
  }

  /**
   * Shows a state of a practice run: a fixture after some of a solution's writes, which may break
   * invariants (the snapshot's problems say which). One history entry holds it, replaced by the
   * next state shown, so stepping through a run does not bury the meshes before it.
   */
  practice(serialized: SerializedMesh, label: string, diff: PointerDiff | null): Snapshot {
    this.abandonStepping();
    if (this.history.entry()?.info.source.kind === 'practice' && this.history.position > 0) this.history.moveTo(this.history.position - 1);
    this.history.pushMesh(label, deserializeMesh(serialized), { source: { kind: 'practice' }, report: null, file: null, phase: null, diff });
    this.state++;
    return this.send(null, -1);
  }

  /**
   * Applies what a student's solution wrote on the current mesh ("Use my code"), as the record
   * the page made of its writes on its copy of this mesh: an edit like the library's, which undo
   * takes back and the page gets as a patch. The page has checked the result is valid.
   * @throws TopologyError when the record does not start from the current mesh.
   */
  solution(change: ChangeRecord, label: string, exercise: string): Snapshot {
    return this.applyRecord(change, label, { kind: 'solution', exercise });
  }

  /** Starts stepping an operation (on a copy, or in place when it only moves vertices); nothing changes until `step`. */
  start(request: OperationRequest): Snapshot {
    const current = this.currentMesh();
    const from = this.state;
    const undone = this.abandonStepping();
    if (request.kind === 'subdivide' && request.level === undefined) {
      // how many levels of this scheme led to the current mesh (√3 alternates its boundary rule)
      const label = operationLabel(request);
      const levels = this.history.items().slice(0, this.history.position + 1).filter((entry) => entry.label === label).length;
      request = { ...request, level: levels };
    }
    const { working } = this.begin(request); // throws (leaving the session as it was) when the operation does not apply
    // a subdivision compacts its copy first: the page then needs the renumbered mesh whole
    if (working.vertexSlots !== current.vertexSlots || working.edgeSlots !== current.edgeSlots || working.faceSlots !== current.faceSlots) return this.send(null, -1);
    // else nothing has changed yet (the copy equals the mesh the page holds): an empty patch, not the whole mesh
    return this.send(undone ?? noChange(current), from);
  }

  /** Runs the next phase; when the operation has no more, its result joins the history. */
  step(): Snapshot {
    const from = this.state;
    const stepping = this.stepping;
    const change = this.stepOnce();
    if (!this.stepping) this.ended = stepping;
    return this.send(change, from);
  }

  /**
   * Goes back one phase, as far as the operation's start; after the last `step`, back into the
   * operation (whose result stays in the history, for redo). The page gets the whole mesh: the
   * operation runs again from its start to the phase before (an operation on a copy of the mesh
   * cannot simply undo its last record, as the copy compacted the mesh first).
   */
  stepBack(): Snapshot {
    const stepping = this.stepping ?? this.ended;
    if (!stepping) throw new TopologyError('no operation is being stepped: there is no phase to go back to');
    if (stepping.phases === 0) throw new TopologyError(`${stepping.label} is at its start: there is no phase before it`);
    if (this.stepping) this.abandonStepping();
    else {
      this.ended = null;
      this.history.moveTo(this.history.position - 1);
    }
    this.state++;
    const again = this.begin(stepping.request);
    const target = stepping.phases - 1;
    for (let i = 1; i <= target; i++) {
      if (!this.advance(again)) throw new TopologyError(`${stepping.label} ended after ${i - 1} phases when run again`);
    }
    if (again.total !== null && again.phases >= again.total) again.total = null;
    return this.send(null, -1);
  }

  /**
   * Runs the remaining phases, yielding to the event loop between them so that `cancel` (or any
   * other call) is heard; reports progress after each phase.
   */
  async runToEnd(): Promise<Snapshot> {
    this.cancelRequested = false;
    const from = this.state;
    const mesh = this.stepping?.startPositions ? this.stepping.working : null;
    const positions = mesh ? positionsOf(mesh) : null;
    while (this.stepping) {
      const label = this.stepping.label;
      this.stepOnce();
      const done = this.stepping ? this.stepping.phases / (this.stepping.total ?? this.stepping.phases + 1) : 1;
      this.progress?.({ label, fraction: Math.min(1, done) });
      await new Promise((resolve) => setTimeout(resolve, 0));
      if (this.cancelRequested) this.abandonStepping();
    }
    return this.send(mesh && positions ? positionsChange(mesh, positions) : null, from);
  }

  /** Drops the operation being stepped (or run): back to the mesh before it. */
  cancel(): Snapshot {
    this.cancelRequested = true;
    const from = this.state;
    return this.send(this.abandonStepping(), from);
  }

  /** Applies a local edit to the current mesh; its change record becomes the history entry. */
  edit(request: EditRequest): Snapshot {
    const from = this.state;
    const undone = this.abandonStepping();
    const result = applyEdit(this.currentMesh(), request); // throws, leaving the session as it was
    return this.recorded(result.record!, result.label, { kind: 'edit', request }, from, undone);
  }

  /** Applies a change written elsewhere (a solution's, on the page) to the current mesh, as an edit. */
  private applyRecord(change: ChangeRecord, label: string, source: HistorySource): Snapshot {
    const from = this.state;
    const undone = this.abandonStepping();
    const mesh = this.currentMesh();
    const { before } = change;
    const state = mesh.slotState;
    if (Object.keys(before).some((key) => before[key as keyof typeof before] !== state[key as keyof typeof state])) {
      throw new TopologyError(`${label} was made on another mesh than the current one (its slots differ): nothing was changed`);
    }
    applyChange(mesh, change, 'forward');
    return this.recorded(change, label, source, from, undone);
  }

  /** Makes the change just made to the current mesh a history entry, and sends it. */
  private recorded(record: ChangeRecord, label: string, source: HistorySource, from: number, undone: ChangeRecord | null): Snapshot {
    this.history.pushChange(label, record, {
      source,
      report: null,
      file: this.history.entry()!.info.file,
      phase: null,
      diff: pointerDiffOf(record, DIFF_LIMIT),
    });
    this.state++;
    // the page may hold the operation that was just dropped: then it needs the whole mesh
    return this.send(undone ? null : record, undone ? -1 : from, true);
  }

  undo(): Snapshot {
    return this.jump(Math.max(0, this.history.position - 1));
  }

  redo(): Snapshot {
    return this.jump(Math.min(this.history.length - 1, this.history.position + 1));
  }

  /** Makes history entry `index` current; one step over a change record is sent as that record. */
  jump(index: number): Snapshot {
    const from = this.state;
    const undone = this.abandonStepping();
    const position = this.history.position;
    this.history.moveTo(index);
    if (index === position && !undone) return this.send(null, -1);
    this.state++;
    const change = undone
      ? null
      : index === position + 1
        ? this.history.changeAt(index)
        : index === position - 1 && this.history.changeAt(position)
          ? invertChange(this.history.changeAt(position)!)
          : null;
    return this.send(change, from, true);
  }

  /** The mesh as a file: `ply`, `ply-binary`, `off`, `obj` or `glb`. */
  exportMesh(format: string): Promise<Uint8Array> {
    return writeMeshAsync(this.stepping?.working ?? this.currentMesh(), format as WriteFormat | 'glb');
  }

  /** The fingerprint of the mesh of the last snapshot: a test that the page's copy equals it. */
  fingerprint(): string {
    return meshFingerprint(this.shownMesh());
  }

  /** The seam edges of the mesh of the last snapshot (see `seamEdges`). */
  seams(): Int32Array {
    return seamEdges(this.shownMesh());
  }

  /** Bytes the history keeps (see `History`): a test of its thrift. */
  historyBytes(): number {
    return this.history.bytes();
  }

  /** The current snapshot, with the whole mesh. */
  snapshot(): Snapshot {
    return this.send(null, -1);
  }

  /** The full counts and checks of the mesh of the last snapshot sent. */
  details(): SnapshotDetails {
    const entry = this.history.entry();
    const report = this.stepping ? null : (entry?.info.report ?? null);
    this.lastDetails =
      this.lastDetails && this.connectivityChecked ? movedDetails(this.shownMesh(), this.lastDetails, this.version) : fullDetails(this.shownMesh(), report, this.version);
    this.connectivityChecked = true;
    return this.lastDetails;
  }

  /**
   * The next snapshot: a patch when `change` leads from the state the page holds (`from`) to the
   * current one and the render buffers have room for it, else the whole mesh. `kept`: the history
   * holds `change` (an edit, an undo), so the page gets a copy to own.
   */
  private send(change: ChangeRecord | null, from: number, kept = false): Snapshot {
    const entry = this.history.entry();
    const stepping = this.stepping;
    const mesh = this.shownMesh();
    const { info } = entry!;
    const version = ++this.version;
    const canPatch = change !== null && this.sent?.state === from && this.lastDetails !== null;
    const render = canPatch ? this.layout.patch(mesh, change) : null;
    // the patch's record is transferred to the page: one the history keeps goes as a copy
    const patch = render && this.sent ? { from: this.sent.version, change: kept ? structuredClone(change!) : change!, render } : null;
    this.sent = { version, state: this.state };
    const report = stepping ? null : info.report;
    // a change too large to patch (a subdivision phase) still has its record: the mesh goes whole,
    // its counts read off the record at once, the full pass after (on request, as after a patch)
    const counted = canPatch ? change : null;
    this.lastDetails = counted ? patchedDetails(mesh, counted, this.lastDetails!, version) : fullDetails(mesh, report, version);
    this.connectivityChecked = counted ? this.connectivityChecked && onlyChangesValues(counted) : true;
    return {
      version,
      mesh: patch ? null : serializeMesh(mesh, EDIT_ROOM),
      render: patch ? null : this.layout.full(mesh),
      patch,
      details: { ...this.lastDetails, pending: counted !== null },
      report,
      file: info.file,
      ...(stepping ? shownPhase(stepping) : { phase: info.phase, diff: info.diff }),
      colours: vertexColours(mesh, (stepping ?? this.ended)?.phase ?? null),
      stepping: steppingState(stepping),
      ended: steppingState(this.ended),
      history: {
        items: this.history.items().map(({ label, vertices, faces, info }) => ({ label, vertices, faces, source: info.source })),
        index: this.history.position,
      },
    };
  }

  /**
   * Starts stepping `request` on the current mesh (on a copy, or in place when it only moves
   * vertices). @throws when the operation does not apply, leaving the session as it was.
   */
  private begin(request: OperationRequest): Stepping {
    const current = this.currentMesh();
    const inPlace = request.kind === 'smooth';
    const working = inPlace ? current : current.clone();
    const { operation, phases } = startOperation(working, request);
    const startPositions = inPlace ? positionsOf(current) : null;
    this.stepping = { label: operationLabel(request), request, total: phases, working, startPositions, operation, phases: 0, phase: null, shown: null };
    return this.stepping;
  }

  /** Runs the operation's next phase, if it has one (false when it has finished instead). */
  private advance(stepping: Stepping): boolean {
    const next = stepping.operation.next();
    if (next.done) return false;
    stepping.phases++;
    stepping.phase = { ...next.value, change: next.value.change ?? noChange(stepping.working) };
    stepping.shown = null;
    return true;
  }

  /** Runs one phase; returns its change record (null when two phases ran, and the page needs the whole mesh). */
  private stepOnce(): ChangeRecord | null {
    const stepping = this.stepping;
    if (!stepping) throw new TopologyError('no operation is being stepped: start one first');
    const { working } = stepping;
    this.state++;
    // an operation that ends without another phase (decimation finds nothing more) changed nothing
    let change: ChangeRecord | null = noChange(working);
    if (this.advance(stepping)) {
      change = stepping.phase!.change!;
      if (stepping.total === null || stepping.phases < stepping.total) return change;
      // that was the last announced phase: let the operation finish now, so no empty step follows;
      // one that had more to do than it announced shows that phase as well, and stops predicting
      if (this.advance(stepping)) {
        stepping.total = null;
        return null;
      }
    }
    // the operation is over: its result joins the history
    this.stepping = null;
    const info: EntryInfo = {
      source: { kind: 'operation', request: stepping.request },
      report: null,
      file: this.history.entry()!.info.file,
      ...shownPhase(stepping),
    };
    if (stepping.startPositions) this.history.pushChange(stepping.label, positionsChange(working, stepping.startPositions), info);
    else this.history.pushMesh(stepping.label, working, info);
    return change;
  }

  /**
   * Drops the operation being stepped, if any. One run in place puts the positions back: the
   * change that makes (for the page), else null.
   */
  private abandonStepping(): ChangeRecord | null {
    this.ended = null;
    const stepping = this.stepping;
    if (!stepping) return null;
    this.stepping = null;
    this.state++;
    if (!stepping.startPositions) return null;
    const { working } = stepping;
    const moved = positionsOf(working);
    working.positions.set(stepping.startPositions);
    return positionsChange(working, moved);
  }

  private shownMesh(): HalfedgeMesh {
    return this.stepping?.working ?? this.currentMesh();
  }

  private currentMesh(): HalfedgeMesh {
    const mesh = this.history.mesh();
    if (!mesh) throw new TopologyError('no mesh is open yet');
    return mesh;
  }
}

/** The last phase as the page shows it: what it marks and its pointer diff, read off its record once. */
function shownPhase(stepping: Stepping): { phase: ShownPhase | null; diff: PointerDiff | null } {
  const { phase } = stepping;
  if (!phase) return { phase: null, diff: null };
  const { change, ...rest } = phase;
  stepping.shown ??= { phase: { ...rest, ...phaseElements(change!, PHASE_MARKS) }, diff: pointerDiffOf(change!, DIFF_LIMIT) };
  return stepping.shown;
}

function steppingState(stepping: Stepping | null): SteppingState | null {
  return stepping ? { label: stepping.label, phases: stepping.phases, total: stepping.total } : null;
}

/** The colours of a phase's per-vertex values (one per vertex slot), if it reports them. */
function vertexColours(mesh: HalfedgeMesh, phase: Phase | null): ColourScale | null {
  const values = phase?.values?.vertices;
  return values && values.length === mesh.vertexSlots ? colourScale(values) : null;
}

/** A copy of the positions of a mesh's vertex slots (to put back, or to record a move from). */
function positionsOf(mesh: HalfedgeMesh): Float64Array<ArrayBuffer> {
  return mesh.positions.slice(0, 3 * mesh.vertexSlots);
}
