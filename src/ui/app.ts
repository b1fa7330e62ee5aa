/**
 * The teaching app: it shows the snapshots the session worker sends and keeps only view state
 * (camera, selection, the path walked, which table is open). Every change to the mesh is asked of
 * the worker; every pointer question is answered here, from the snapshot's arrays.
 */
import { type Box3, type Object3D, Vector3 } from 'three';
import { type HalfedgeMesh, type PointerDiff, type SerializedMesh, meshToHalfedgeJSON, type Repair, type RepairIncident, type RepairKind } from '../core/index.js';
import { colors } from './colors.js';
import { SessionClient } from '../workers/client.js';
import type { PageSnapshot as Snapshot } from '../workers/page-copy.js';
import { type EditRequest, type SolutionCall, solutionCall } from '../workers/operations.js';
import { PICK_IN_WORKER_ABOVE, type RenderPatch, type StudentVerb, type VerbArguments } from '../workers/protocol.js';
import { recordWrites } from '../core/practice/writes.js';
import { byId, capitalized, el } from './dom.js';
import { hoverHighlight, idLabels, phaseHighlight, phaseMeanings, quizHighlight } from './highlights.js';
import { boundaryLoopList, incidentBounds, loopBounds, neighbourhoodPoints, selectionBounds, selectionFacing } from './framing.js';
import { renderExport } from './panels/export.js';
import { incidentTarget, renderFileInfo } from './panels/file-info.js';
import { renderHelp } from './panels/help.js';
import { HistoryPanel } from './panels/history.js';
import { type BoundaryLoop, renderHud } from './panels/hud.js';
import { renderInspector } from './panels/inspector.js';
import { renderLegend, renderValuesLegend } from './panels/legend.js';
import { OperationsPanel, setAvailability } from './panels/operations.js';
import type { PracticePanel } from './panels/practice.js';
import { QuizPanel } from './panels/quiz.js';
import { StepperPanel, steppingTitle } from './panels/stepper.js';
import { RecordTables } from './panels/tables.js';
import { TraversalPanel } from './panels/traversal.js';
import { renderBreadcrumb, renderWalkButtons } from './panels/walk.js';
import type { Convention } from './records.js';
import { ArrowLayer } from './scene/arrows.js';
import { emptyHighlight, HighlightLayer, type HighlightSpec } from './scene/highlight.js';
import { pick, type PickFilter } from './scene/picking.js';
import { PlaneGizmo } from './scene/plane-gizmo.js';
import { SurfaceLayer } from './scene/surface.js';
import { Viewer } from './scene/viewer.js';
import { Opening } from './opening.js';
import { type Tab, tabs, wireControls } from './controls.js';
import { Inspection } from './inspection.js';
import { repairStory } from './repair-story.js';
import { ViewDetail } from './view-detail.js';
import { cutPlaneOnShow, explodedMesh, explodedRender, explodeOffsets } from './explode.js';
import { adjustable, DragAdjust } from './drag-adjust.js';
import { type CommandTarget, commands, commandTooltip } from './commands.js';
import { elementName, exists, isMove, type Move, type Selection } from './selection.js';
import { isRight } from './quiz.js';
import { encodeViewState, openedEntry, type ReplayStep, replayable, type ViewState } from './share.js';
import type { PanelName } from './embed.js';

/** Label every vertex and face when the mesh has at most this many of them. */
const MAX_ID_LABELS = 400;

/** Why a mesh of one part has no exploded view. */
const ONE_PART = 'the mesh is one connected part: there is nothing to pull apart';

/** How long the changes must pause before the full counts and checks are asked for. */
const DETAILS_AFTER_MS = 400;

/** Walk steps the breadcrumb shows in presentation mode: its large type keeps them on a few lines of the panel. */
const PRESENTATION_BREADCRUMB_STEPS = 3;

/** Where an app lives: the whole page, or the shadow root of a `<halfedge-view>` element. */
export interface AppHost {
  /** Holds the markup of layout.html, in which ids are looked up. */
  root: Document | ShadowRoot;
  /** Carries the state classes (presentation, stepping…) and goes full screen in presentation mode. */
  frame: HTMLElement;
  /** Hears the keys and the dropped files: the window for the page, the element for an embed. */
  input: Window | HTMLElement;
  /** The panels an embed shows, without the toolbar or the tabs (see embed.ts); null for the whole app. */
  panels: readonly PanelName[] | null;
}

/** The whole page as the app's host. */
export function pageHost(panels: readonly PanelName[] | null = null): AppHost {
  return { root: document, frame: document.documentElement, input: window, panels };
}

export class App {
  readonly client: SessionClient;
  readonly viewer: Viewer;
  snapshot: Snapshot | null = null;
  /** The page's copy of the session's mesh: what the records, tables and exports read. */
  mesh: HalfedgeMesh | null = null;
  /**
   * The mesh as the view draws it: `mesh` itself, or in the exploded view the same mesh with its
   * parts pulled apart (see explode.ts). Everything drawn over the mesh, picked or framed reads it.
   */
  drawn: HalfedgeMesh | null = null;
  /** Whether the exploded view is on: the parts of the mesh drawn pulled apart. */
  exploded = false;
  /** The selection, the walk, the hover, the naming and the marks: what the student is looking at. */
  readonly inspection = new Inspection();
  filter: PickFilter = 'auto';
  /** Larger arrows, dots and type in presentation mode. */
  scale = 1;
  showIds = false;
  /** The last message shown to the student (an error, a walk that led nowhere…). */
  message = '';
  /** The last edit (or operation the student's code did): its kind, whose code made it, and how many pointer writes. */
  lastEdit: { kind: string; by: 'solution' | 'library'; writes: number } | null = null;
  /** What the commands (keys, toolbar buttons, `command(name)`) reach of the app: see commands.ts. */
  readonly commandTarget: CommandTarget = commandTargetOf(this);
  /** After an extrusion or a bevel, a drag on the view sets its offset or amount (see drag-adjust.ts). */
  readonly adjust = new DragAdjust(
    (request) => this.editAgain(request),
    (message) => this.say(message),
  );
  /** Files, samples and opening them again. */
  readonly opening: Opening;
  /** Resolves when the first mesh is on screen. */
  readonly ready: Promise<void>;
  /** The snapshot version last shown, and when it arrived (performance.now()). */
  shown = { version: 0, at: 0 };

  private readonly surface = new SurfaceLayer();
  private readonly arrows = new ArrowLayer();
  private readonly selectionLayer = new HighlightLayer();
  private readonly hoverLayer = new HighlightLayer(0.55, 1.3);
  private readonly idLayer = new HighlightLayer();
  private readonly phaseLayer = new HighlightLayer(0.85, 1.3, 9);
  private readonly tables: RecordTables;
  private readonly traversal: TraversalPanel;
  private readonly operations: OperationsPanel;
  private readonly stepper: StepperPanel;
  private readonly history: HistoryPanel;
  /** Says, beside the glTF export, what it makes of the mesh's polygons. */
  private readonly exportNote: (faceDegrees: Record<number, number>) => void;
  readonly quiz: QuizPanel;
  /** The Practice tab, loaded with its editor and grader when first asked for (see `practice()`). */
  private practicePanel: Promise<PracticePanel> | null = null;
  /** The Practice panel once loaded: "Use my code" is read from it as a request comes. */
  private practiceLoaded: PracticePanel | null = null;
  /** Whether the camera was last framed on the whole mesh (not on a selection): see `show`. */
  private framedWhole = false;
  /** Frames again what was framed last, the same way (presentation mode changes the view's size). */
  private frameAgain: () => void = () => this.frameMesh();
  /** The phase marks last worked out, and the snapshot they are of (see `phaseMarks`). */
  private marked: { snapshot: Snapshot; marks: HighlightSpec } | null = null;
  /** What the phase layer draws, or is about to (see `drawPhaseMarks`). */
  private phaseMarksDrawn: { marks: HighlightSpec | null; mesh: HalfedgeMesh; scale: number } | null = null;
  /** The boundary loops last listed, and the snapshot they are of (see `boundaryLoops`). */
  private loops: { snapshot: Snapshot; loops: BoundaryLoop[] } | null = null;
  private readonly gizmo: PlaneGizmo;
  private readonly detail: ViewDetail;
  private markReady!: () => void;
  private readonly root: Document | ShadowRoot;
  private readonly frame: HTMLElement;
  private readonly input: Window | HTMLElement;
  /** The panels shown, in embed mode; null for the whole app, with its toolbar and tabs. */
  readonly panels: readonly PanelName[] | null;

  constructor(host: AppHost = pageHost()) {
    ({ root: this.root, frame: this.frame, input: this.input, panels: this.panels } = host);
    this.ready = new Promise((resolve) => (this.markReady = resolve));
    this.client = new SessionClient({
      createSessionWorker: () => new Worker(new URL('../workers/session.worker.ts', import.meta.url), { type: 'module' }),
      createLoaderWorker: () => new Worker(new URL('./loader.worker.ts', import.meta.url), { type: 'module' }),
    });
    this.client.onProgress = ({ label, fraction }) => this.showProgress(label, fraction);
    this.client.onRestart = (message, snapshot) => {
      this.say(message, 'alert');
      if (snapshot) this.show(snapshot, false);
    };

    this.opening = new Opening(this.byId('sample-select'), {
      open: (bytes, name, sample, options) => this.client.open(bytes, name, sample, options),
      opened: (snapshot, name) => {
        this.show(snapshot, true);
        const repairs = snapshot.report?.repairs ?? [];
        if (repairs.length > 0) this.announceRepairs(name, repairs);
        else this.say(`Opened ${name}.`);
      },
      say: (message, role) => this.say(message, role),
      showError: (title, message) => this.showError(title, message),
      hideProgress: () => this.hideProgress(),
    });
    this.viewer = new Viewer(this.byId('viewport'));
    this.viewer.add(this.surface.group, this.arrows.group, this.phaseLayer.group, this.selectionLayer.group, this.hoverLayer.group, this.idLayer.group);
    // shaders, once the first mesh is drawn, in the time the student takes to look at it
    void this.ready.then(() => {
      const precompile = (object: Object3D) => this.viewer.precompile(object);
      return Promise.all([this.surface.prepareColours(this.viewer), ...[this.phaseLayer, this.selectionLayer, this.hoverLayer].map((layer) => layer.prepare(this.mesh!, precompile))]);
    });
    this.gizmo = new PlaneGizmo(this.viewer, (plane) => this.operations.setPlane(plane));
    this.viewer.add(this.gizmo.group);
    this.detail = new ViewDetail(
      this.viewer,
      this.surface,
      this.arrows,
      this.byId('arrow-note'),
      () => ({ mesh: this.drawn, stats: this.snapshot?.stats ?? null, inspection: this.inspection, scale: this.scale }),
      () => this.frameAgainIfCovered(),
    );
    this.viewer.controls.addEventListener('end', () => this.detail.refreshIfPartial());
    this.viewer.beforeDraw = () => this.detail.fit();
    // the surface's arrays a slice per frame; the view draws once they and the phase's marks are all there
    this.viewer.beforeFrame = () => this.surface.uploadSlice(this.viewer.renderer) || this.phaseLayer.laying;
    // labels and framed meshes keep off the overlays on the view
    this.viewer.overlays = () =>
      ['legend', 'hud', 'status', 'values-legend', 'arrow-note'].flatMap((id) => {
        const overlay = this.byId(id);
        const rect = overlay.getBoundingClientRect();
        // an overlay an embed hides by its style has no size, and covers nothing
        return overlay.hidden || !overlay.textContent || rect.width === 0 || rect.height === 0 ? [] : [rect];
      });
    this.tables = new RecordTables(this.byId('tables'), (s) => this.selectInSight(s), (s) => this.hover(s));
    this.traversal = new TraversalPanel(
      this.byId('traversal'),
      () => ({ mesh: this.mesh, selection: this.inspection.selection, convention: this.inspection.convention }),
      (spec) => {
        this.inspection.marks.traversal = spec;
        this.drawSelection();
      },
    );
    this.operations = new OperationsPanel(this.byId('operations'), {
      start: (request) => void this.request('start', request),
      edit: (request) => void this.request('edit', request),
      say: (message) => this.say(message),
      showPlane: (plane) => this.showPlane(plane),
      setPlaneMode: (mode) => this.gizmo.setMode(mode),
    });
    this.stepper = new StepperPanel(this.byId('stepper'), {
      step: () => void this.request('step'),
      stepBack: () => void this.request('stepBack'),
      runToEnd: () => void this.request('runToEnd'),
      cancel: () => void this.request('cancel'),
      select: (s) => this.select(s),
    });
    this.history = new HistoryPanel(this.byId('history'), { undo: () => void this.request('undo'), redo: () => void this.request('redo'), jump: (i) => void this.request('jump', i) });
    this.exportNote = renderExport(this.byId('export'), {
      meshBytes: (format) => this.client.exportMesh(format),
      tablesJson: () => (this.mesh ? JSON.stringify(meshToHalfedgeJSON(this.mesh)) : '{}'),
      png: () => new Promise((resolve, reject) => this.viewer.renderer.domElement.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('no picture'))), 'image/png')),
      baseName: () => (this.snapshot?.file?.name ?? 'mesh').replace(/\.[^.]*$/, ''),
    });
    this.quiz = new QuizPanel(this.byId('quiz'), {
      mesh: () => this.mesh,
      convention: () => this.inspection.convention,
      showPath: (question, picked) => {
        this.inspection.marks.quiz = question ? quizHighlight(question.path, picked, picked !== null && isRight(question, picked)) : null;
        this.drawSelection();
      },
    });
    this.drawLegend();
    renderHelp(this.byId('help-keys'), this.inspection.convention);
    renderWalkButtons(this.byId('walk-buttons'), (move) => this.walk(move), this.inspection.convention);
    wireControls(this, { root: this.root, input: this.input, canvas: this.viewer.renderer.domElement, quickToPick: () => this.surface.quickToPick });
    if (this.panels) this.embed(this.panels);
    this.drawPanels();
  }

  /** Stops the workers and the drawing, for an embed taken out of its page. */
  dispose(): void {
    this.client.dispose();
    this.surface.dispose();
    this.viewer.dispose();
  }

  private byId<T extends HTMLElement = HTMLElement>(id: string): T {
    return byId<T>(this.root, id);
  }

  /**
   * Shows only the view and the chosen panels, the side ones stacked in the order named: no toolbar,
   * no tabs (every pane open, its other panels hidden).
   */
  private embed(panels: readonly PanelName[]): void {
    const sections = [...this.root.querySelectorAll<HTMLElement>('[data-panel]')];
    for (const section of sections) {
      const at = panels.indexOf(section.dataset.panel as PanelName);
      section.hidden = at < 0;
      section.style.order = String(at);
    }
    for (const tab of tabs) this.byId(`pane-${tab}`).hidden = false;
    this.frame.classList.add('embed');
    this.frame.classList.toggle('embed-side', sections.some((section) => !section.hidden && section.dataset.panel !== 'tables'));
    for (const part of ['tables', 'legend', 'hud'] as const) this.frame.classList.toggle(`embed-${part}`, panels.includes(part));
    // no tab opens it here
    if (panels.includes('practice')) void this.practice().then((panel) => panel.open());
  }

  /** The Practice tab's panel, its code loaded on first use: the page's first load does without it. */
  practice(): Promise<PracticePanel> {
    const actions = {
      showState: async (mesh: SerializedMesh, label: string, diff: PointerDiff | null, frame: boolean, marks: HighlightSpec | null) => {
        try {
          this.show(await this.client.practice(mesh, label, diff), frame);
          this.inspection.marks.practice = marks;
          this.drawSelection();
          this.say(`${capitalized(label)}.`);
        } catch (error) {
          this.say((error as Error).message, 'alert');
        }
      },
      select: (selection: Selection | null) => this.select(selection),
      frame: (selection: Selection) => this.frameAround(selection),
      mark: (marks: HighlightSpec | null) => {
        // only on the state the panel showed: after an undo or an opened file the ids mean other elements
        const history = this.snapshot?.history;
        if (history?.items[history.index]?.source.kind !== 'practice') return false;
        this.inspection.marks.practice = marks;
        this.drawSelection();
        return true;
      },
      say: (message: string, role?: 'status' | 'alert') => this.say(message, role),
    };
    this.practicePanel ??= import('./panels/practice.js').then(({ PracticePanel }) => (this.practiceLoaded = new PracticePanel(this.byId('practice'), actions)));
    return this.practicePanel;
  }

  // -----------------------------------------------------------------------------------------------
  // Asking the session for changes

  async run(action: () => Promise<Snapshot | null>): Promise<Snapshot | null> {
    try {
      const snapshot = await action();
      if (snapshot) this.show(snapshot, false);
      return snapshot;
    } catch (error) {
      this.say((error as Error).message, 'alert');
      return null;
    } finally {
      this.hideProgress();
    }
  }

  /**
   * Asks the session for one of the student's verbs (the table in protocol.ts) and shows the
   * answer; after undo, redo or a jump, says where in the history the view now is.
   */
  request<V extends StudentVerb>(verb: V, ...args: VerbArguments<V>): Promise<Snapshot | null> {
    this.adjust.end();
    if (verb === 'edit') return this.editOrDrag(args[0] as EditRequest);
    const mine = this.solutionCallFor(verb, args[0]);
    if (mine) return this.solutionEdit(mine.panel, mine.call, mine.kind);
    const ask = () => (this.client[verb] as (...args: unknown[]) => Promise<Snapshot | null>)(...args);
    if (verb === 'undo' || verb === 'redo' || verb === 'jump') return this.moveInHistory(ask);
    return this.run(ask);
  }

  /** An edit (the library's, or the student's with "Use my code"); after an extrusion or a bevel, a drag on the view sets how far it goes. */
  private async editOrDrag(request: EditRequest): Promise<Snapshot | null> {
    const used = this.numbersOf(request);
    const snapshot = await this.editOnce(request);
    const target = snapshot ? adjustable(request, used) : null;
    if (target) {
      this.adjust.offer(target);
      this.say(`${this.message.replace(/ Ctrl\+Z undoes it\.$/, '')} Drag up or down in the view to set its ${target.field}; Ctrl+Z undoes it.`);
    }
    return snapshot;
  }

  private editOnce(request: EditRequest): Promise<Snapshot | null> {
    const mine = this.solutionCallFor('edit', request);
    return mine ? this.solutionEdit(mine.panel, mine.call, mine.kind) : this.edit(() => this.client.edit(request), request.kind);
  }

  /** The numbers an edit is made with, its defaults written out (a bevel's amount, an extrusion's offset); null for none or a kind there is none of. */
  private numbersOf(request: EditRequest): { readonly [name: string]: number } | null {
    try {
      const input = this.mesh && solutionCall(this.mesh, { verb: 'edit', request })?.input;
      return input && typeof input === 'object' && !Array.isArray(input) ? (input as { readonly [name: string]: number }) : null;
    } catch {
      return null;
    }
  }

  /** A drag's step: the last edit taken back and made again with `request`; when that does not apply, the edit before is put back. */
  private async editAgain(request: EditRequest): Promise<boolean> {
    await this.run(() => this.client.undo());
    if (await this.editOnce(request)) return true;
    const why = this.message;
    await this.run(() => this.client.redo());
    this.say(why, 'alert');
    return false;
  }

  /** An edit, saying what it did and how many pointers it wrote (else the status line would still say how the file opened). */
  private async edit(action: () => Promise<Snapshot | null>, kind: string): Promise<Snapshot | null> {
    const snapshot = await this.run(action);
    if (snapshot) {
      const { label } = snapshot.history.items[snapshot.history.index]!;
      const total = snapshot.diff?.total;
      const written = total === undefined ? '' : `: ${total} pointer${total === 1 ? '' : 's'} changed`;
      this.lastEdit = { kind, by: 'library', writes: total ?? 0 };
      this.say(`${capitalized(label)}${written}. Ctrl+Z undoes it.`);
    }
    return snapshot;
  }

  /**
   * With "Use my code" on in Practice, the exercise's solution for an edit or operation that is
   * the loaded exercise's (see `solutionCall`); null otherwise, and for a request no exercise sets.
   */
  private solutionCallFor(verb: StudentVerb, request: unknown): { panel: PracticePanel; call: SolutionCall; kind: string } | null {
    const panel = this.practiceLoaded;
    if (!panel?.useMine || !this.mesh || (verb !== 'edit' && verb !== 'start')) return null;
    let call: SolutionCall | null;
    try {
      call = solutionCall(this.mesh, { verb, request } as Parameters<typeof solutionCall>[1]);
    } catch {
      return null; // an edit there is none of: the session refuses it by name
    }
    return call?.exercise === panel.exercise.id ? { panel, call, kind: (request as { kind: string }).kind } : null;
  }

  /**
   * Runs the student's solution on the mesh in the view, in the sandbox, instead of the library's
   * edit; a valid result becomes the current mesh (an entry undo takes back), a broken one is not
   * kept and the Practice panel shows where it broke, as for a fixture.
   */
  private async solutionEdit(panel: PracticePanel, call: SolutionCall, kind: string): Promise<Snapshot | null> {
    const mesh = this.mesh!;
    const run = await panel.runOnView(mesh, call.input, call.label);
    this.lastEdit = { kind, by: 'solution', writes: run.writes.length };
    if (!run.mesh) {
      this.say(run.message, 'alert');
      return null;
    }
    // the writes as a record on a copy of the mesh in view, sent as the library's edits are
    const record = recordWrites(mesh.clone(), run.writes);
    const label = `${call.label} (your code)`;
    const snapshot = await this.run(() => this.client.solution(record, label, call.exercise));
    if (snapshot) this.say(`${capitalized(label)}: ${run.writes.length} write${run.writes.length === 1 ? '' : 's'}. ${run.message ? `${run.message} ` : ''}Ctrl+Z undoes it.`);
    return snapshot;
  }

  /** Undo, redo or a jump, saying where in the history (and which model) the view now is. */
  private async moveInHistory(action: () => Promise<Snapshot | null>): Promise<Snapshot | null> {
    const snapshot = await this.run(action);
    const open = snapshot && openedEntry(snapshot);
    if (snapshot && open) {
      const here = snapshot.history.items[snapshot.history.index]!;
      this.say(here.source.kind === 'open' ? `Back to ${open.name} as opened.` : `Back to “${here.label}” on ${open.name}.`);
    }
    return snapshot;
  }

  /**
   * Replays the steps of a link on the model just opened, each operation run to its end; stops at
   * the first that does not apply, saying which. Returns whether every step ran.
   */
  async replay(steps: ReplayStep[]): Promise<boolean> {
    for (const [i, step] of steps.entries()) {
      const done =
        step.kind === 'edit'
          ? await this.request('edit', step.request)
          : (await this.request('start', step.request)) && (await this.request('runToEnd'));
      if (!done) {
        this.say(`This link's step ${i + 1} of ${steps.length} could not be replayed: ${this.message}`, 'alert');
        return false;
      }
    }
    return true;
  }

  // -----------------------------------------------------------------------------------------------
  // Showing a snapshot

  /** Draws a snapshot; `frame` points the camera at it (a newly opened mesh). */
  show(snapshot: Snapshot, frame: boolean): void {
    this.shown = { version: snapshot.version, at: performance.now() };
    const before = this.snapshot;
    this.snapshot = snapshot;
    this.opening.shown(snapshot);
    const mesh = (this.mesh = snapshot.mesh);
    // a new model opens as its file has it
    if (frame) this.exploded = false;
    this.drawMesh(snapshot.renderPatch);
    // while stepping, a phase may colour the vertices by a value it computed
    renderValuesLegend(this.byId('values-legend'), this.surface.setVertexColours(snapshot.colours), `${snapshot.phase?.name ?? ''}: colour by value`);
    this.inspection.meshChanged(mesh, frame);
    if (frame) {
      this.traversal.stop();
      const planar = snapshot.render.planeNormal !== null;
      this.viewer.setMode(planar ? 'top' : 'perspective');
      this.byId('top-view').setAttribute('aria-pressed', String(planar));
    }
    this.tables.setMesh(mesh, this.inspection.convention, snapshot.idsVersion, snapshot.change);
    this.stepper.update(snapshot);
    if (snapshot.stepping || snapshot.ended) revealInPanel(this.stepper.firstChanges());
    // while stepping, the Operate tab puts the stepper's buttons first
    this.frame.classList.toggle('stepping', snapshot.stepping !== null || snapshot.ended !== null);
    this.drawLegend();
    // an operation that ended (run through or cancelled), or another mesh opened, takes the plane
    // away: its square tints the view, and its preview shows where it crossed the mesh before
    if ((before?.stepping && !snapshot.stepping) || frame) this.operations.hidePlane();
    const stepping = steppingTitle(snapshot);
    if (stepping) this.say(`${stepping}.`);
    else if (before?.stepping && !frame) {
      // the status line said a phase: say how the operation ended, run through or cancelled
      const grew = snapshot.history.index !== before.history.index || snapshot.history.items.length !== before.history.items.length;
      this.say(grew ? `${before.stepping.label}: done.` : `${before.stepping.label}: cancelled; the mesh is as it was.`);
    }
    if (before?.stepping && !snapshot.stepping) this.offerExplodedView(before);
    this.history.update(snapshot);
    // a question on a changed mesh is asked again (its ids may be gone); a new model, or an
    // answered question's path on a changed mesh, leaves the view
    if (this.quiz.active && !frame) this.quiz.ask();
    else if (this.inspection.marks.quiz) this.quiz.end();
    this.drawSelection();
    this.drawPanels();
    // framed last: the overlays it keeps the mesh clear of now show this mesh's counts
    if (frame) this.frameMesh();
    else this.frameAgainIfCovered();
    // the arrows for the view as framed (too small to draw there, none are placed); a patch leaves
    // the view where it was: they grow from the same face, without asking the picking worker
    void this.detail.refresh(snapshot.renderPatch !== null);
    this.markReady();
    if (snapshot.pending) void this.completeDetails(snapshot);
  }

  /**
   * After a patched snapshot: the full counts and checks, asked for once the changes pause (the
   * pass over a large mesh takes the worker a while, and an edit asked for meanwhile would wait
   * for it), and shown if the snapshot is still current.
   */
  private async completeDetails(snapshot: Snapshot): Promise<void> {
    await new Promise((resolve) => setTimeout(resolve, DETAILS_AFTER_MS));
    if (this.snapshot !== snapshot) return;
    const details = await this.client.details().catch(() => null);
    if (!details || this.snapshot !== snapshot || details.version !== snapshot.version) return;
    Object.assign(snapshot, { stats: details.stats, problems: details.problems, unavailable: details.unavailable, pending: false });
    this.drawPanels();
  }

  /**
   * Draws the surface of the snapshot on show, and sets the mesh the other layers draw: the page's
   * own, or in the exploded view one with its parts pulled apart, worked out again for every
   * snapshot (an edit may join parts, or move them). The exploded view goes off where it no longer
   * applies: on a mesh of one part, or one the picking worker holds.
   */
  private drawMesh(patch: RenderPatch | null): void {
    const { mesh, render, history } = this.snapshot!;
    const explosion = this.exploded && !render.picking ? explodeOffsets(mesh, cutPlaneOnShow(history)) : null;
    this.exploded = explosion !== null;
    this.drawn = explosion ? explodedMesh(mesh, explosion) : mesh;
    // the moved positions are a copy, uploaded whole; the page's own were patched in place
    this.surface.update(explosion ? explodedRender(render, explosion, this.drawn) : render, explosion ? null : patch);
    this.byId('explode').setAttribute('aria-pressed', String(this.exploded));
  }

  /** A command's button that may not apply: marked so, its tooltip saying why (see commands.ts). */
  private drawCommandButtons(): void {
    for (const command of commands) {
      if (!command.button || !command.unavailable) continue;
      const tip = commandTooltip(command, this.inspection.convention);
      setAvailability(this.byId<HTMLButtonElement>(command.button.id), command.button.label, command.unavailable(this.commandTarget), tip);
    }
  }

  /** Why the exploded view does not apply to the mesh on show (its button's tooltip), or null when it does. */
  explodeUnavailable(): string | null {
    const snapshot = this.snapshot;
    if (!snapshot) return 'no mesh is open';
    const { render, stats, pending } = snapshot;
    // a mesh this large is picked in a worker, from a hierarchy of its triangles where they are
    if (render.picking) return `it is for meshes of up to ${PICK_IN_WORKER_ABOVE.toLocaleString('en')} triangles, and this one has ${render.counts.triangles.toLocaleString('en')}`;
    // pending counts have not counted the parts since the last change: turning the view on counts them
    if (!pending && stats.components < 2) return stats.components === 0 ? 'the mesh has no edges, so no parts to pull apart' : ONE_PART;
    return null;
  }

  /**
   * Turns the exploded view on or off (saying why not, when it does not apply), and frames the
   * whole mesh again, as it grows or shrinks. Returns whether it is on.
   */
  setExploded(on: boolean): boolean {
    if (!this.snapshot || on === this.exploded) return this.exploded;
    const why = on ? this.explodeUnavailable() : null;
    if (why === null) {
      this.exploded = on;
      this.drawMesh(null);
    }
    if (on && !this.exploded) {
      this.say(`No exploded view: ${why ?? ONE_PART}.`);
      return false;
    }
    // said first: framing keeps the mesh clear of the status line as it will read
    this.say(on ? 'Exploded view: the parts are drawn pulled apart; the mesh itself has not moved. B puts them back.' : 'The parts are drawn where they are again.');
    this.hover(this.inspection.hovered);
    this.drawSelection();
    this.drawPanels();
    this.frameMesh();
    void this.detail.refresh();
    return this.exploded;
  }

  /**
   * The end of a cut that kept both sides leaves its two sides touching, caps face to face: the
   * status line says how to pull them apart. The view does not do it by itself: a student who
   * sees the halves jump apart would take it that the cut moved them.
   */
  private offerExplodedView(before: Snapshot): void {
    const snapshot = this.snapshot!;
    const plane = cutPlaneOnShow(snapshot.history);
    const ended = snapshot.history.index !== before.history.index;
    if (!ended || !plane || this.exploded || snapshot.render.picking || !explodeOffsets(snapshot.mesh, plane)) return;
    this.say(`${this.message} Its two sides touch: press B to see them pulled apart (only the view moves).`, 'status', { label: 'Explode parts', run: () => this.setExploded(true) });
  }

  /**
   * A view the app framed and nobody has moved since is framed again when an overlay has come
   * over the mesh (a phase card while stepping, the note that the arrows are too small to draw);
   * one the user placed, or a selection framed, stays.
   */
  private frameAgainIfCovered(): void {
    if (this.framedWhole && this.viewer.overlaysCoverFramed()) this.frameMesh();
  }

  frameMesh(): void {
    if (!this.drawn) return;
    const { box, radius } = this.surface.bounds;
    this.viewer.frame(box, this.viewNormal(), radius);
    this.framedWhole = true;
    this.frameAgain = () => this.frameMesh();
  }

  /**
   * Brings the selection and its neighbourhood (the faces around it) to fill most of the view,
   * seen from the side its faces face.
   */
  frameSelection(): void {
    if (this.inspection.selection) this.frameAround(this.inspection.selection);
  }

  /** Brings an element and the faces around it to fill most of the view, seen from their front. */
  private frameAround(s: Selection): void {
    const mesh = this.drawn;
    if (!mesh || !exists(mesh, s)) return;
    const { box, radius } = selectionBounds(mesh, s, this.inspection.convention);
    // close up, an element facing away would be seen from inside the surface: look at its front
    const facing = selectionFacing(mesh, s);
    const direction = this.viewer.camera.position.clone().sub(this.viewer.controls.target);
    this.framePart(box, radius, facing && facing.dot(direction) < 0 ? facing : undefined);
  }

  /** Frames a part of the mesh (a selection, a boundary loop, a repair), and remembers how. */
  private framePart(box: Box3, radius: number, from?: Vector3): void {
    this.viewer.frame(box, this.viewNormal(), radius, from);
    this.framedWhole = false;
    this.frameAgain = () => this.framePart(box, radius, from);
  }

  /**
   * The boundary loops of the mesh on screen (one halfedge and the number of edges of each),
   * listed once per snapshot: the counts are drawn again at every selection.
   */
  boundaryLoops(): BoundaryLoop[] {
    const snapshot = this.snapshot;
    if (!snapshot) return [];
    // a closed mesh (the boundary-edge count is exact even before a patch's full pass) has none:
    // no pass over every halfedge on the page's thread after each edit of a large closed mesh
    if (this.loops?.snapshot !== snapshot) this.loops = { snapshot, loops: snapshot.stats.boundaryEdges === 0 ? [] : boundaryLoopList(snapshot.mesh) };
    return this.loops.loops;
  }

  /**
   * Selects boundary loop `index`'s halfedge (a walk along next goes round it) and frames the
   * whole loop, seen along its axis. Returns false when there is no such loop.
   */
  frameBoundaryLoop(index: number): boolean {
    const loop = this.boundaryLoops()[index];
    if (!this.drawn || !loop) return false;
    this.select({ kind: 'halfedge', id: loop.halfedge });
    // said first: framing keeps the loop clear of the status line as it will read
    this.say(`Boundary loop ${index + 1}: ${loop.length} edge${loop.length === 1 ? '' : 's'}, from h${loop.halfedge}; walk next to go round it.`);
    const { box, radius, facing } = loopBounds(this.drawn, loop.halfedge);
    this.framePart(box, radius, facing ?? undefined);
    return true;
  }

  /** The direction the top view looks along: the plane of a 2D mesh, else z. */
  private viewNormal(): Vector3 {
    const normal = this.snapshot?.render.planeNormal;
    return normal ? new Vector3(...normal) : new Vector3(0, 0, 1);
  }

  toggleTopView(): void {
    const top = this.viewer.mode !== 'top';
    this.viewer.setMode(top ? 'top' : 'perspective');
    this.byId('top-view').setAttribute('aria-pressed', String(top));
    this.frameMesh();
  }

  /** Lecture-hall mode: large type, thick arrows, high contrast, full screen. */
  setPresentation(on: boolean): void {
    this.scale = on ? 1.8 : 1;
    this.frame.classList.toggle('presentation', on);
    this.byId('presentation').setAttribute('aria-pressed', String(on));
    this.surface.setEmphasis(this.scale);
    // the room looks at the view: the record tables fold to their title (D opens them)
    this.showTables(!on);
    void this.detail.refresh();
    this.drawSelection();
    this.drawPanels();
    // the view changed size with the layout: fit what was framed to it once the layout has settled
    requestAnimationFrame(() => requestAnimationFrame(() => this.frameAgain()));
    // full screen needs a user gesture and may be refused (a test browser, an iframe): fine either way
    if (on && !document.fullscreenElement) this.frame.requestFullscreen?.().catch(() => {});
    if (!on && document.fullscreenElement) document.exitFullscreen().catch(() => {});
  }

  /** Whether the cutting plane gizmo is on the view. */
  get planeShown(): boolean {
    return this.gizmo.shown;
  }

  /** Shows or hides the cutting plane gizmo at `plane`. */
  showPlane(plane: [number, number, number, number] | null): void {
    // on the mesh where it is, not as drawn: the plane says where the cut will go
    if (plane && this.mesh) this.gizmo.show(this.mesh, plane);
    else this.gizmo.hide();
  }

  /**
   * Model, steps, selection and camera, for a link that restores them: the sample the mesh on
   * screen came from and every operation and edit since, or no model when the mesh came from a
   * file of the user's (or was put back after a restart), which no link can carry.
   */
  viewState(): ViewState {
    const camera = this.viewer.camera;
    const { model, steps } = this.snapshot ? replayable(this.snapshot) : { model: null, steps: [] };
    // the breadcrumb: where it starts, and the pointers followed from there to the selection
    const [start, ...walked] = this.inspection.path;
    return {
      model,
      steps,
      selection: start?.to ?? this.inspection.selection,
      walk: walked.flatMap((step) => (step.move ? [step.move] : [])),
      naming: this.inspection.convention,
      camera: { position: camera.position.toArray(), target: this.viewer.controls.target.toArray(), zoom: camera.zoom, shift: this.viewer.targetShift },
      mode: this.viewer.mode,
      exploded: this.exploded,
    };
  }

  /** Puts back a selection and camera from a link (after its model is open). */
  applyViewState(state: ViewState): void {
    if (state.naming) this.setConvention(state.naming);
    if (state.mode) {
      this.viewer.setMode(state.mode);
      this.byId('top-view').setAttribute('aria-pressed', String(state.mode === 'top'));
      this.frameMesh();
    }
    // before the camera: turning it on frames the parts pulled apart
    if (state.exploded) this.setExploded(true);
    if (state.camera) this.viewer.setCamera(state.camera.position, state.camera.target, state.camera.zoom, state.camera.shift);
    if (state.selection && this.mesh) {
      if (!exists(this.mesh, state.selection)) {
        this.say(`This link selects ${elementName(state.selection)}, which ${this.snapshot?.file?.name ?? 'this mesh'} does not have.`, 'alert');
        return;
      }
      this.select(state.selection);
      // the walk stops where a pointer leads nowhere (the walk's own message says why)
      for (const move of state.walk) if (!this.walk(move)) break;
    }
  }

  shareLink(): string {
    const state = this.viewState();
    const url = `${location.origin}${location.pathname}?${encodeViewState(state)}`;
    void navigator.clipboard?.writeText(url).catch(() => {});
    const replays = state.steps.length ? ` It opens ${state.model} and replays ${state.steps.length} step${state.steps.length > 1 ? 's' : ''}.` : '';
    this.say(
      state.model
        ? `Link copied: ${url}${replays}`
        : `Link copied, without the model: the mesh on screen comes from a file you opened yourself, which never leaves this browser, so a link can only name a sample model. ${url}`,
    );
    return url;
  }

  showError(title: string, message: string): void {
    this.byId('error-title').textContent = title;
    this.byId('error-message').textContent = message;
    this.byId('error-panel').hidden = false;
  }

  showTab(name: Tab): void {
    if (name !== 'quiz' && this.inspection.marks.quiz) this.quiz.end();
    // the editor is loaded when the tab is first opened
    if (name === 'practice') void this.practice().then((panel) => panel.open());
    if (this.panels) return; // an embed shows its panels side by side, without tabs
    for (const tab of tabs) {
      this.byId(`tab-${tab}`).setAttribute('aria-selected', String(tab === name));
      this.byId(`pane-${tab}`).hidden = tab !== name;
    }
    // Practice widens the side column, for the code beside the task and what a run wrote: the
    // view narrows, and what was framed is framed again once the layout has settled
    const practising = name === 'practice';
    if (this.frame.classList.contains('practising') === practising) return;
    this.frame.classList.toggle('practising', practising);
    requestAnimationFrame(() => requestAnimationFrame(() => this.frameAgain()));
  }

  // -----------------------------------------------------------------------------------------------
  // Selecting and walking

  /** Selects an element; a new selection starts a new walk. */
  select(selection: Selection | null): void {
    const refused = this.inspection.select(this.mesh, selection);
    if (refused) {
      this.say(refused, 'alert');
      return;
    }
    // a selection (or Esc) ends the quiz's drawing, which would otherwise hide the selection's
    if (this.inspection.marks.quiz) this.quiz.end();
    this.afterSelect();
  }

  /**
   * A file that had to be repaired says so as it opens, in the status line, with the way to the
   * list; and its first culprit is told over the view and framed (see `showProblem`), so it is not missed.
   */
  private announceRepairs(name: string, repairs: Repair[]): void {
    for (const repair of repairs) {
      const incident = repair.incidents.find((i) => incidentTarget(i) !== null);
      if (!incident) continue;
      this.showProblem(incident, repair.kind, incidentTarget(incident)!);
      break;
    }
    const more = repairs.length > 1 ? ` (and ${repairs.length - 1} more kind${repairs.length > 2 ? 's' : ''} of repair)` : '';
    this.say(`Opened ${name}, repaired: ${repairs[0].message}${more}.`, 'status', { label: 'Show the repairs', run: () => this.showRepairs() });
  }

  /** The File tab, with the list of repairs open. */
  showRepairs(): void {
    this.showTab('file');
    const first = this.root.querySelector<HTMLDetailsElement>('#file-info details[data-repair]');
    if (first) {
      first.open = true;
      first.querySelector('summary')?.focus();
    }
  }

  /**
   * Selects an element chosen away from the view (a row of the tables), and frames it when it is
   * out of sight: off screen, behind the camera, or seen edge-on or from behind.
   */
  selectInSight(selection: Selection): void {
    this.select(selection);
    if (this.drawn && !this.inSight(this.drawn, selection)) this.frameSelection();
  }

  private inSight(mesh: HalfedgeMesh, s: Selection): boolean {
    const points = neighbourhoodPoints(mesh, s);
    if (s.kind === 'vertex') points.push(new Vector3(...mesh.position(s.id)));
    if (points.length === 0) return true;
    const centre = points.reduce((sum, p) => sum.add(p), new Vector3()).divideScalar(points.length);
    const { x, y, visible } = this.viewer.project(centre);
    const { width, height } = this.viewer.size();
    const onScreen = visible && x >= 0 && y >= 0 && x <= width && y <= height;
    const facing = selectionFacing(mesh, s);
    const toCamera = this.viewer.camera.position.clone().sub(centre).normalize();
    // a face seen at less than about 17° from edge-on, or from behind, is not seen
    return onScreen && (!facing || facing.dot(toCamera) > 0.3);
  }

  /**
   * Selects the first element of a repair, tells the repair over the view (see repair-story.ts)
   * and frames all of its elements, seen from where none is edge-on.
   */
  showProblem(incident: RepairIncident, kind: RepairKind, first: Selection): void {
    const mesh = this.drawn;
    if (!mesh) return;
    this.select(first);
    this.inspection.marks.problem = repairStory(mesh, incident, kind);
    this.say(incident.message);
    this.drawSelection();
    const { box, radius, facing } = incidentBounds(mesh, incident, kind, this.viewer.camera.position.clone().sub(this.viewer.controls.target));
    this.framePart(box, radius, facing ?? undefined);
  }

  get seamsShown(): boolean {
    return this.inspection.marks.seams !== null;
  }

  /**
   * Marks the seams of the mesh on screen (the edges where the file had split its vertices), or
   * clears them. Asked of the session each time: an edit renumbers edges.
   */
  async toggleSeams(show = !this.seamsShown): Promise<number> {
    if (!show || !this.mesh) {
      this.inspection.marks.seams = null;
      this.drawSelection();
      this.drawPanels();
      return 0;
    }
    const version = this.shown.version;
    const edges = await this.client.seams();
    if (this.shown.version !== version) return 0; // the mesh changed meanwhile: those ids are not its edges
    this.inspection.marks.seams = { ...emptyHighlight(), edges: [...edges].map((id) => ({ id, color: colors.seam })) };
    this.say(`${edges.length} seam edge${edges.length === 1 ? '' : 's'} marked: where the file split its vertices, each corner keeping its own texture coordinate and normal.`);
    this.drawSelection();
    this.drawPanels();
    return edges.length;
  }

  /** Follows a pointer from the selection, extending the breadcrumb. */
  walk(move: Move): boolean {
    if (!this.inspection.selection) {
      this.say('Select an element first: click an arrow, a vertex or a face.');
      return false;
    }
    const nowhere = this.inspection.walk(this.mesh, move);
    const message = this.byId('walk-message');
    message.textContent = nowhere ?? '';
    if (nowhere) {
      // said on the view as well, where a room looking at the mesh reads it
      this.say(nowhere);
      revealInPanel(message);
      return false;
    }
    if (this.inspection.marks.quiz) this.quiz.end();
    this.afterSelect();
    return true;
  }

  back(): void {
    if (this.inspection.back()) this.afterSelect();
  }

  hover(selection: Selection | null): void {
    const hovered = this.inspection.hover(this.mesh, selection);
    if (this.drawn && hovered) this.hoverLayer.show(this.drawn, hoverHighlight(hovered), this.scale);
    else this.hoverLayer.clear();
    this.viewer.requestRender();
  }

  setConvention(convention: Convention): void {
    this.inspection.convention = convention;
    this.byId<HTMLSelectElement>('convention').value = convention;
    // everything that names the vertex of a halfedge speaks the naming chosen
    this.drawLegend();
    renderWalkButtons(this.byId('walk-buttons'), (move) => this.walk(move), convention);
    renderHelp(this.byId('help-keys'), convention);
    if (this.quiz.active) this.quiz.ask();
    if (this.snapshot) this.tables.setMesh(this.snapshot.mesh, convention, this.snapshot.idsVersion);
    this.drawSelection();
    this.drawPanels();
  }

  /** A click on the canvas: answers the quiz when it is waiting, selects otherwise. */
  async click(x: number, y: number): Promise<void> {
    this.adjust.end();
    const question = this.quiz.active ? this.quiz.question : null;
    const picked = await this.pickAt(x, y, question ? question.answer.kind : this.filter);
    if (question) {
      if (picked) this.quiz.answer(picked);
    } else this.select(picked);
  }

  /** The element under a point of the canvas (CSS pixels), with the current filter. */
  async pickAt(x: number, y: number, filter: PickFilter = this.filter): Promise<Selection | null> {
    if (!this.drawn) return null;
    return pick({ viewer: this.viewer, surface: this.surface, mesh: this.drawn, shown: this.arrows.shown, scale: this.scale }, x, y, filter);
  }

  /** Shows a sentence in the status line (`alert` for errors: read out at once), with a button for what follows from it. */
  say(message: string, role: 'status' | 'alert' = 'status', action?: { label: string; run: () => void }): void {
    this.message = message;
    const status = this.byId('status');
    status.setAttribute('role', role);
    status.classList.toggle('error', role === 'alert');
    status.textContent = message;
    if (action) status.append(' ', el('button', { type: 'button', class: 'link status-action', onclick: action.run }, action.label));
    // a refusal (three lines of presentation type) may reach over the mesh the app framed; other
    // lines stay where they are (a copied link would otherwise move the view it describes)
    if (role === 'alert') this.frameAgainIfCovered();
  }

  // -----------------------------------------------------------------------------------------------

  private afterSelect(): void {
    this.detail.refreshIfPartial();
    this.drawSelection();
    this.drawPanels();
    this.tables.reveal(this.inspection.selection);
    revealInPanel(this.byId('breadcrumb'));
  }

  /** The legend: while stepping, the phase and what its colours mean; else the pointers' colours. */
  private drawLegend(): void {
    const stepping = this.snapshot ? steppingTitle(this.snapshot) : null;
    const marks = this.phaseMarks();
    // only the colours the view shows: a smoothing step marks nothing, its colours are the distances
    const phase = stepping ? { title: stepping, explanation: this.snapshot?.phase?.explanation ?? '', meanings: marks ? phaseMeanings(marks) : [] } : null;
    renderLegend(this.byId('legend'), phase, this.inspection.convention);
  }

  /** The marks of the phase being stepped, worked out once per snapshot: the legend and the view both need them. */
  private phaseMarks(): HighlightSpec | null {
    const snapshot = this.snapshot;
    if (!(snapshot?.stepping || snapshot?.ended) || !snapshot.phase) return null;
    if (this.marked?.snapshot !== snapshot) this.marked = { snapshot, marks: phaseHighlight(snapshot.mesh, snapshot.phase) };
    return this.marked.marks;
  }

  /**
   * The marks of the phase on show, drawn again only when they, the mesh drawn or the scale
   * change. A phase marks thousands of elements: they are laid out in tasks of their own after
   * the one that shows the snapshot (each then well within the 100 ms a page may keep its input
   * waiting), and the view draws the snapshot once they are all there (`HighlightLayer.laying`).
   */
  private drawPhaseMarks(mesh: HalfedgeMesh): void {
    const marks = this.phaseMarks();
    const drawing = { marks, mesh, scale: this.scale };
    const last = this.phaseMarksDrawn;
    if (last && last.marks === marks && last.mesh === mesh && last.scale === this.scale) return;
    this.phaseMarksDrawn = drawing;
    if (marks) void this.phaseLayer.showInTasks(mesh, marks, this.scale).then((done) => done && this.viewer.requestRender());
    else this.phaseLayer.clear();
  }

  private drawSelection(): void {
    const mesh = this.drawn;
    if (!mesh) return;
    this.selectionLayer.show(mesh, this.inspection.highlight(mesh), this.scale);
    this.drawPhaseMarks(mesh);
    this.idLayer.clear();
    if (this.showIds && mesh.nVertices + mesh.nFaces <= MAX_ID_LABELS) this.idLayer.show(mesh, idLabels(mesh), this.scale);
    this.viewer.requestRender();
  }

  private drawPanels(): void {
    const snapshot = this.snapshot;
    // a pointer in the record is a step of the walk (Back returns); anything else starts a new one
    const follow = (field: string, s: Selection) => void (isMove(field) ? this.walk(field) : this.select(s));
    renderInspector(this.byId('record'), this.byId('convention-note'), this.mesh, this.inspection.selection, this.inspection.convention, follow);
    renderBreadcrumb(this.byId('breadcrumb'), this.inspection.path, this.scale > 1 ? PRESENTATION_BREADCRUMB_STEPS : undefined);
    if (this.mesh && snapshot) this.operations.update(this.mesh, this.inspection.selection, snapshot.unavailable);
    this.drawCommandButtons();
    if (snapshot) {
      renderHud(this.byId('hud'), snapshot.stats, snapshot.problems, this.boundaryLoops(), {
        select: (s) => this.select(s),
        frameLoop: (i) => this.frameBoundaryLoop(i),
      });
      this.exportNote(snapshot.stats.faceDegrees);
      renderFileInfo(this.byId('file-info'), snapshot.file, snapshot.report, {
        showProblem: (incident, kind, first) => this.showProblem(incident, kind, first),
        toggleSeams: () => void this.toggleSeams(),
        reopen: this.opening.reopenable(snapshot.file?.name ?? null) ? (tolerance: number) => void this.opening.reopen(tolerance, snapshot.file?.name ?? null) : null,
        seamsShown: this.seamsShown,
      });
    }
  }

  private showProgress(label: string, fraction: number): void {
    this.byId('progress').hidden = false;
    this.byId('progress-label').textContent = label;
    this.byId<HTMLProgressElement>('progress-bar').value = fraction;
  }

  private hideProgress(): void {
    this.byId('progress').hidden = true;
  }

  get helpShown(): boolean {
    return !this.byId('help-overlay').hidden;
  }

  toggleHelp(show = !this.helpShown): void {
    this.byId('help-overlay').hidden = !show;
    if (show) this.byId('help-close').focus();
  }

  /**
   * Hides the overlays on the view (legend and counts) or shows them again: for a demo where the
   * mesh alone should fill the screen. The status line stays: it says what just happened.
   */
  toggleOverlays(): void {
    const hidden = this.frame.classList.toggle('overlays-hidden');
    this.say(hidden ? 'Legend and counts hidden: press K to show them.' : 'Legend and counts shown.');
    this.viewer.requestRender();
  }

  /** Shows the record tables, or folds them to their title so the view gets their height. */
  showTables(show: boolean): void {
    this.frame.classList.toggle('tables-folded', !show);
    this.byId('tables-fold').setAttribute('aria-expanded', String(show));
    if (show) this.tables.reveal(this.inspection.selection);
  }

  get tablesShown(): boolean {
    return !this.frame.classList.contains('tables-folded');
  }

  toggleIds(): void {
    this.showIds = !this.showIds;
    this.byId('show-ids').setAttribute('aria-pressed', String(this.showIds));
    if (this.showIds && this.mesh && this.mesh.nVertices + this.mesh.nFaces > MAX_ID_LABELS) {
      this.say(`Ids are labelled on meshes of up to ${MAX_ID_LABELS} vertices and faces; use the tables for this one.`);
    }
    this.drawSelection();
  }
}

/**
 * Scrolls the side panel just enough for `element` to be in sight below its sticky tabs (the page
 * and the view stay where they are, as `scrollIntoView` would not leave them); nothing when the
 * element is not shown (another tab is open).
 */
function revealInPanel(element: Element): void {
  const side = element.closest<HTMLElement>('.side');
  if (!side || element.getClientRects().length === 0) return;
  const box = element.getBoundingClientRect();
  const panel = side.getBoundingClientRect();
  const top = panel.top + (side.querySelector('.side-tabs')?.getBoundingClientRect().height ?? 0);
  if (box.bottom > panel.bottom) side.scrollTop += Math.min(box.bottom - panel.bottom, box.top - top);
  else if (box.top < top) side.scrollTop -= top - box.top;
}

/** The app as the commands see it. */
function commandTargetOf(app: App): CommandTarget {
  return {
    get convention() {
      return app.inspection.convention;
    },
    get exploded() {
      return app.exploded;
    },
    get helpShown() {
      return app.helpShown;
    },
    get tablesShown() {
      return app.tablesShown;
    },
    get presenting() {
      return app.scale > 1;
    },
    walk: (move) => void app.walk(move),
    back: () => app.back(),
    select: () => app.select(null),
    frameMesh: () => app.frameMesh(),
    frameSelection: () => app.frameSelection(),
    toggleTopView: () => app.toggleTopView(),
    explodeUnavailable: () => app.explodeUnavailable(),
    setExploded: (on) => app.setExploded(on),
    toggleIds: () => app.toggleIds(),
    toggleOverlays: () => app.toggleOverlays(),
    showTables: (show) => app.showTables(show),
    toggleHelp: (show) => app.toggleHelp(show),
    setPresentation: (on) => app.setPresentation(on),
    shareLink: () => app.shareLink(),
    request: (verb) => app.request(verb),
    askQuiz: () => {
      app.showTab('quiz');
      app.quiz.ask();
    },
    say: (message) => app.say(message, 'alert'),
  };
}
