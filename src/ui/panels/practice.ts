/**
 * The Practice tab: the student picks an exercise, writes the function in the editor, and runs it
 * in the sandbox on every fixture. The panel lists each check, the first invariant the code broke
 * (with its write and line), and every write it made, each of which can be shown in the view.
 * Code and progress are kept in the browser per exercise; "Export" saves all solutions as one file.
 */
import { type HalfedgeMesh, type PointerDiff, type SerializedMesh, serializeMesh } from '../../core/index.js';
// module by module: the index would bring the solution parser, which only the sandbox needs
import { describeInput, type Exercise, type ExerciseInput, fixtureMesh } from '../../core/practice/exercise.js';
import { exercises } from '../../core/practice/exercises.js';
import { type CheckStatus, type FirstBroken, PARTIAL_CREDIT } from '../../core/practice/grade.js';
import { type GradeReport, gradeOnMesh, gradeSolution } from '../../core/practice/grade-solution.js';
import { whyNotDrawable } from '../../core/practice/drawable.js';
import { MAX_VISITS, PRACTICE_API_NAMES } from '../../core/practice/mesh-api.js';
import { SolutionError } from '../../core/practice/solution-error.js';
import { applyWrite, describeWrite, pointerChangeOf, type PracticeWrite, replayWriter, replayWrites } from '../../core/practice/writes.js';
import { el, replace, replaceKeepingFocus } from '../dom.js';
import { fixtureFiles } from '../practice-link.js';
import { readMarks, writeMarks } from '../practice-marks.js';
import { browserRunner } from '../practice-sandbox.js';
import type { PracticeEditor } from '../practice-editor.js';
import type { HighlightSpec } from '../scene/highlight.js';

export interface PracticeActions {
  /**
   * Shows a state of a run in the view, with the write that led to it as the pointer diff and
   * `marks` drawn on it; `frame` points the camera at it.
   */
  showState(mesh: SerializedMesh, label: string, diff: PointerDiff | null, frame: boolean, marks: HighlightSpec | null): Promise<void>;
  /** Changes the marks on the state shown; false when the view has moved on to another mesh. */
  mark(marks: HighlightSpec | null): boolean;
  /** Points the camera at an element and the faces around it, from their front. */
  frame(selection: { kind: 'vertex'; id: number }): void;
  /** Selects an element in the view (a culprit of the first broken invariant), or nothing. */
  select(selection: { kind: 'halfedge' | 'vertex' | 'face'; id: number } | null): void;
  say(message: string, role?: 'status' | 'alert'): void;
}

/** What `run()` reports, as `window.halfedgeLab.practice.run()` gives it. */
export interface PracticeRunResult {
  passed: boolean;
  /** The points earned (a partial check earns part of its point) and the points there are. */
  score: number;
  maxScore: number;
  checks: { name: string; passed: boolean; status: CheckStatus; score: number; message: string; hidden: boolean }[];
  /** The writes on the fixture shown (the first shown fixture that failed, else the first shown). */
  writes: PracticeWrite[];
  firstBroken: FirstBroken | null;
  /** Every fixture; a hidden one with no writes and no first broken write (they are not shown). */
  fixtures: { name: string; hidden: boolean; writes: PracticeWrite[]; firstBroken: FirstBroken | null }[];
  /** Why the code could not run at all (a syntax error, no default export), with its line. */
  error: { message: string; line: number | null } | null;
}

/**
 * What the student's code did to the mesh in the view ("Use my code"): `mesh` is what it left when
 * that is a valid mesh the app takes as the new current one, null when nothing is to change (it
 * could not run, broke an invariant, or refused); `message` says which, for the status line.
 */
export interface SolutionOnView {
  mesh: HalfedgeMesh | null;
  writes: PracticeWrite[];
  message: string;
}

/** Writes listed in the panel (all of them can still be stepped through with the buttons). */
const WRITES_LISTED = 400;
/** How fast Play walks a query's reads: a face loop of six halfedges plays in about two seconds. */
const READS_PER_SECOND = 4;
/** What a hard case refused cleanly earns, said in the summary. */
const PARTIAL_TEXT = `${PARTIAL_CREDIT * 100} % of its points`;

const storageKey = (id: string) => `halfedge-lab.practice.${id}`;

interface Saved {
  code: string;
  passed: boolean;
}

export class PracticePanel {
  readonly exercises: Exercise[] = [...exercises];
  exercise: Exercise = exercises[0];
  code = '';
  /** The run under way, which a second request joins. */
  private current: Promise<PracticeRunResult> | null = null;
  report: GradeReport | null = null;
  /**
   * The fixture and the number of its writes asked to be shown, and the number really shown:
   * fewer when the state asked for cannot be drawn (a pointer half-way rewired: `why`).
   */
  shown: { fixture: number; write: number; drawn: number; why: string | null } | null = null;
  /** For a query: the fixture whose reads are shown, and the read the view is at (an index into its visits). */
  read: { fixture: number; step: number } | null = null;
  private readTimer: ReturnType<typeof setInterval> | null = null;
  private hintsShown = 0;
  /** The fixture run the camera was last pointed at. */
  private framed: unknown = null;
  private editor: PracticeEditor | null = null;
  private editorLoading: Promise<void> | null = null;
  private readonly select = el('select', { 'aria-label': 'Exercise', onchange: () => this.load(this.select.value) });
  private readonly task = el('div', { class: 'practice-task' });
  private readonly hints = el('ol', { class: 'practice-hints' });
  private readonly hintButton = el('button', { type: 'button', onclick: () => this.showHint() }, 'Hint');
  private readonly editorHost = el('div', { class: 'practice-editor' });
  private readonly runButton = el('button', { type: 'button', class: 'primary', 'aria-label': 'Run the solution', 'aria-keyshortcuts': 'Control+Enter', title: 'Run on every fixture (Ctrl+Enter)', onclick: () => void this.run() }, 'Run');
  /**
   * "Use my code": while on, the app's own button for this exercise's operation (and `edit()` or
   * `start()` of it) runs this code on the mesh in the view instead of the library's function.
   */
  useMine = false;
  private readonly useMineButton = el('button', { type: 'button', 'aria-pressed': 'false', onclick: () => this.setUseMine(!this.useMine) }, 'Use my code');
  private readonly summary = el('p', { class: 'practice-summary', role: 'status', 'aria-live': 'polite' });
  private readonly checks = el('ul', { class: 'practice-checks' });
  private readonly broken = el('div', { class: 'practice-broken' });
  private readonly writes = el('div', { class: 'practice-writes' });
  private readonly reads = el('div', { class: 'practice-writes' });

  constructor(
    container: HTMLElement,
    private readonly actions: PracticeActions,
  ) {
    // three parts, stacked in a narrow column and side by side in a wide one (see the style):
    // the task, the code, and what a run found
    replace(
      container,
      el('div', { class: 'practice-brief' }, el('label', { class: 'practice-pick' }, 'Exercise ', this.select), this.task, el('div', { class: 'practice-hint-row' }, this.hintButton, ' ', this.useMineButton), this.hints),
      el(
        'div',
        { class: 'practice-code' },
        this.editorHost,
        el(
          'div',
          { class: 'practice-buttons' },
          this.runButton,
          el('button', { type: 'button', 'aria-label': 'Start again from the starter code', onclick: () => this.setCode(this.exercise.starter) }, 'Starter code'),
          el('button', { type: 'button', 'aria-label': 'Export all solutions as one file', onclick: () => this.exportSolutions() }, 'Export'),
        ),
      ),
      el('div', { class: 'practice-results' }, this.summary, this.checks, this.broken, this.writes, this.reads),
    );
    this.editorHost.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
        event.preventDefault();
        void this.run();
      }
    });
    this.load(this.exercise.id);
  }

  /** Adds an exercise (an instructor's, from a URL) and opens it. */
  add(exercise: Exercise): void {
    const at = this.exercises.findIndex((e) => e.id === exercise.id);
    if (at >= 0) this.exercises[at] = exercise;
    else this.exercises.push(exercise);
    this.load(exercise.id);
  }

  load(id: string): void {
    const exercise = this.exercises.find((e) => e.id === id) ?? this.exercises.find((e) => e.aliases?.includes(id));
    if (!exercise) throw new Error(`there is no exercise '${id}' (there are ${this.exercises.map((e) => e.id).join(', ')})`);
    this.exercise = exercise;
    id = exercise.id;
    this.report = null;
    this.shown = null;
    this.stopReads();
    this.read = null;
    this.hintsShown = 0;
    this.code = savedFor(exercise)?.code ?? exercise.starter;
    this.editor?.setText(this.code);
    this.drawUseMine();
    this.drawList();
    if (this.editor) void this.showFirstFixture();
    replace(this.task, el('h3', {}, exercise.title), ...exercise.task.map((p) => el('p', {}, p)));
    replace(this.hints);
    this.drawHintButton();
    this.summary.textContent = '';
    replace(this.checks);
    replace(this.broken);
    replace(this.writes);
    replace(this.reads);
  }

  /** Turns "Use my code" on or off (an exercise that only answers questions has no operation to take over). */
  setUseMine(on: boolean): void {
    this.useMine = on && this.exercise.kind === 'edit';
    this.drawUseMine();
    if (on && !this.useMine) this.actions.say(`${this.exercise.title} changes nothing in the view: only an edit's code can do the app's operation.`, 'alert');
    else this.actions.say(this.useMine ? `Your ${this.exercise.title.toLowerCase()} code now does the app's own ${this.exercise.title.toLowerCase()}, on the mesh in the view.` : "The app's own operations are back.");
  }

  private drawUseMine(): void {
    if (this.exercise.kind !== 'edit') this.useMine = false;
    this.useMineButton.setAttribute('aria-pressed', String(this.useMine));
    this.useMineButton.disabled = this.exercise.kind !== 'edit';
    this.useMineButton.title =
      this.exercise.kind === 'edit'
        ? `While pressed, Operate's ${this.exercise.title.toLowerCase()} runs your code on the mesh in the view; a result that breaks the mesh is not kept`
        : 'A query changes nothing: only an edit exercise can do the app\'s operation';
  }

  /**
   * Runs the code on the mesh in the view with `input` (what the app's own edit would use), and
   * shows the run as a fixture's: its checks (a valid mesh; the same as the library's), the first
   * broken write, the writes. The mesh is not changed: what the code left is returned, for the
   * app to make current when it is valid (it need not be the library's: the student's code rules).
   */
  async runOnView(mesh: HalfedgeMesh, input: ExerciseInput | undefined, label: string): Promise<SolutionOnView> {
    this.stopReads();
    this.summary.textContent = `Running your code: ${label}…`;
    let report: GradeReport;
    try {
      report = await gradeOnMesh(this.exercise, this.code, browserRunner, mesh, input, 'the mesh in the view');
    } catch (error) {
      if (!(error instanceof SolutionError)) throw error;
      this.summary.textContent = `The code cannot run: ${error.message}`;
      replace(this.broken, lineButton(error.line, (line) => this.goToLine(line)));
      return { mesh: null, writes: [], message: `Your code cannot run: ${error.message}. The mesh stays as it was.` };
    }
    this.report = report;
    this.shown = null;
    const [valid, outcome] = report.checks;
    const result = report.fixtures[0];
    this.summary.textContent = `Your code on the mesh in the view (${label}): ${valid.passed ? 'a valid mesh' : 'the mesh is broken'}${outcome.passed ? ", the library's result" : ''}.`;
    this.drawChecks(report);
    this.drawBroken(result.firstBroken, 0);
    this.drawWrites(0);
    const refusal = this.exercise.refusal;
    if (!valid.passed) return { mesh: null, writes: result.writes, message: `Your code broke the mesh, so it stays as it was: ${valid.message.replace(/^the mesh it leaves breaks an invariant: /, '')}.` };
    if (result.writes.length === 0) {
      const refused = refusal !== undefined ? ` (it returned ${String(refusal)})` : '';
      return { mesh: null, writes: [], message: `Your code changed nothing${refused}: ${label} stays undone.` };
    }
    return { mesh: result.after, writes: result.writes, message: outcome.passed ? '' : `It differs from the library's: ${outcome.message}.` };
  }

  /** Loads the editor (once) and shows the exercise's first fixture, when the tab is opened. */
  open(): Promise<void> {
    this.editorLoading ??= import('../practice-editor.js').then(({ createEditor }) => {
      this.editor = createEditor(this.editorHost, this.code, (text) => this.remember(text), PRACTICE_API_NAMES);
    });
    if (!this.report && this.framed !== this.exercise) void this.showFirstFixture();
    return this.editorLoading;
  }

  /** The mesh the exercise is about, before the student's code has run (its first fixture that is not hidden). */
  private async showFirstFixture(): Promise<void> {
    const fixture = this.exercise.fixtures.find((f) => !f.hidden) ?? this.exercise.fixtures[0];
    if (fixture.hidden) return;
    this.framed = this.exercise;
    await this.actions.showState(serializeMesh(fixtureMesh(fixture, fixtureFiles)), this.fixtureLabel(fixture.name, fixture.input), null, true, null);
  }

  /** `practice: Flip an edge, an edge inside a disk, input 10`: the history entry and the status line. */
  private fixtureLabel(name: string, input: ExerciseInput | undefined): string {
    return `practice: ${this.exercise.title}, ${name}${input === undefined ? '' : `, input ${describeInput(input)}`}`;
  }

  setCode(text: string): void {
    this.remember(text);
    this.editor?.setText(text);
  }

  /**
   * Runs the code on every fixture. Asked again while a run is under way (Ctrl+Enter pressed twice),
   * it starts no second run: it answers with the one under way.
   */
  run(): Promise<PracticeRunResult> {
    this.current ??= this.runOnce().finally(() => (this.current = null));
    return this.current;
  }

  get running(): boolean {
    return this.current !== null;
  }

  private async runOnce(): Promise<PracticeRunResult> {
    this.runButton.disabled = true;
    this.stopReads();
    this.summary.textContent = `Running on ${this.exercise.fixtures.length} fixtures…`;
    try {
      const report = await gradeSolution(this.exercise, this.code, browserRunner, fixtureFiles);
      this.report = report;
      const passedCount = report.checks.filter((c) => c.passed).length;
      const partial = report.checks.some((c) => c.status === 'partial') ? ` (${report.score} of ${report.maxScore} points: a hard case refused earns ${PARTIAL_TEXT})` : '';
      this.summary.textContent = report.passed ? `All ${report.checks.length} checks pass.` : `${passedCount} of ${report.checks.length} checks pass${partial}.`;
      store(this.exercise.id, { code: this.code, passed: report.passed || (saved(this.exercise.id)?.passed ?? false) });
      this.drawList();
      this.drawChecks(report);
      // the fixture shown: the first that failed, else the first, of those that are not hidden
      const visible = report.fixtures.map((f, i) => i).filter((i) => !report.fixtures[i].hidden);
      const shown = visible.find((i) => report.fixtures[i].checks.some((c) => !c.passed)) ?? visible[0] ?? 0;
      const fixture = report.fixtures[shown];
      this.drawBroken(fixture.firstBroken, shown);
      this.drawWrites(shown);
      if (this.exercise.kind === 'edit') {
        // the result, with a culprit of the first broken invariant selected
        await this.show(shown, fixture.writes.length);
        const culprit = fixture.firstBroken ? firstCulprit(fixture.firstBroken) : null;
        if (culprit && this.shown?.drawn === fixture.writes.length) this.actions.select(culprit);
      } else {
        // every halfedge the query read; Play walks through them in order
        this.read = null;
        await this.showRead(shown, fixture.visits.length - 1);
      }
      return resultOf(report, shown);
    } catch (error) {
      if (!(error instanceof SolutionError)) throw error;
      this.summary.textContent = `The code cannot run: ${error.message}`;
      replace(this.checks);
      replace(this.broken, lineButton(error.line, (line) => this.goToLine(line)));
      replace(this.writes);
      replace(this.reads);
      return { passed: false, score: 0, maxScore: 0, checks: [], writes: [], firstBroken: null, fixtures: [], error: { message: error.message, line: error.line } };
    } finally {
      this.runButton.disabled = false;
    }
  }

  /** Shows fixture `fixture` after its first `count` writes in the view. */
  async show(fixture: number, count: number): Promise<void> {
    const result = this.report?.fixtures[fixture];
    if (!result || result.hidden) return;
    const write = Math.max(0, Math.min(count, result.writes.length));
    // replay up to the state asked for, remembering the last one that can be drawn
    const mesh = result.before.clone();
    let why = whyNotDrawable(mesh);
    let drawn = why ? -1 : 0;
    const writer = replayWriter(mesh);
    for (let i = 0; i < write; i++) {
      applyWrite(writer, result.writes[i]);
      why = whyNotDrawable(mesh);
      if (!why) drawn = i + 1;
    }
    const frame = this.shown?.fixture !== fixture || this.framed !== result;
    this.framed = result;
    // the marks say what this state is about; a selection made on another state would crowd them
    this.actions.select(null);
    this.shown = { fixture, write, drawn: Math.max(0, drawn), why };
    const state = drawn === write ? mesh : replayWrites(result.before.clone(), result.writes, Math.max(0, drawn));
    // the write that led here, or every write since the last state that can be drawn, marked on it
    const marked = result.writes.slice(drawn === write ? Math.max(0, write - 1) : Math.max(0, drawn), write);
    const from = Math.max(0, drawn) + 1;
    const pending = drawn === write ? '' : from === write ? `, write ${write} marked` : `, writes ${from}–${write} marked`;
    const label = `practice: ${this.exercise.title}, ${result.fixture}${drawn <= 0 ? '' : `, after write ${drawn}`}${pending}`;
    const change = drawn > 0 ? pointerChangeOf(result.writes[drawn - 1]) : null;
    await this.actions.showState(serializeMesh(state), label, change ? { changes: [change], total: 1 } : null, frame, writeMarks(state, marked));
    this.drawWrites(fixture);
  }

  /** For a query: shows fixture `fixture` with the halfedges its run read up to read `step` (zero-based) marked. */
  async showRead(fixture: number, step: number): Promise<void> {
    const result = this.report?.fixtures[fixture];
    if (!result || result.hidden) return;
    const at = Math.max(0, Math.min(step, result.visits.length - 1));
    const marks = result.visits.length === 0 ? null : readMarks(result.before, result.visits, at);
    const sameFixture = this.read?.fixture === fixture;
    this.read = { fixture, step: at };
    // a step on the fixture in the view only changes the marks; another fixture is shown first
    if (!sameFixture || !this.actions.mark(marks)) {
      const frame = this.framed !== result;
      await this.actions.showState(serializeMesh(result.before), this.fixtureLabel(result.fixture, result.input), null, frame, marks);
      // where the code read: on a closed mesh the whole view may show the other side
      if (frame && result.visits.length > 0) this.actions.frame({ kind: 'vertex', id: result.before.origin(result.visits[0]) });
      this.framed = result;
    }
    this.drawReads(fixture);
  }

  /** Plays the reads of the fixture shown, a few a second, from the start when at the end. */
  async playReads(): Promise<void> {
    const read = this.read;
    const result = read ? this.report?.fixtures[read.fixture] : undefined;
    if (!read || !result || result.visits.length === 0) return;
    this.stopReads();
    const last = result.visits.length - 1;
    await this.showRead(read.fixture, read.step >= last ? 0 : read.step);
    this.readTimer = setInterval(() => {
      const now = this.read;
      if (!now || now.step >= last) return this.stopReads();
      now.step++;
      // the view has moved on (another mesh opened, an undo): the reads stop rather than bring the fixture back
      if (!this.actions.mark(readMarks(result.before, result.visits, now.step))) return this.stopReads();
      this.drawReads(now.fixture);
    }, 1000 / READS_PER_SECOND);
    this.drawReads(read.fixture);
  }

  stopReads(): void {
    if (this.readTimer === null) return;
    clearInterval(this.readTimer);
    this.readTimer = null;
    if (this.read) this.drawReads(this.read.fixture);
  }

  state() {
    return {
      exercise: this.exercise.id,
      code: this.code,
      running: this.running,
      passed: this.report?.passed ?? null,
      shown: this.shown,
      read: this.read && { ...this.read, total: this.report?.fixtures[this.read.fixture].visits.length ?? 0, playing: this.readTimer !== null },
      progress: Object.fromEntries(this.exercises.map((e) => [e.id, saved(e.id)?.passed ?? false])),
      useMine: this.useMine,
    };
  }

  goToLine(line: number): void {
    void this.open().then(() => {
      this.editor?.goToLine(line);
      this.editor?.focus();
    });
  }

  private remember(text: string): void {
    this.code = text;
    store(this.exercise.id, { code: text, passed: saved(this.exercise.id)?.passed ?? false });
  }

  private showHint(): void {
    const hint = this.exercise.hints[this.hintsShown];
    if (hint === undefined) return;
    this.hints.append(el('li', {}, hint));
    this.hintsShown++;
    this.drawHintButton();
  }

  private drawHintButton(): void {
    const left = this.exercise.hints.length - this.hintsShown;
    this.hintButton.textContent = left > 0 ? `Show a hint (${left} left)` : 'No more hints';
    this.hintButton.disabled = left === 0;
  }

  private drawList(): void {
    replace(
      this.select,
      ...this.exercises.map((e, i) => el('option', { value: e.id, selected: e.id === this.exercise.id }, `${i + 1}. ${e.title}${savedFor(e)?.passed ? ' ✓' : ''}`)),
    );
    this.select.value = this.exercise.id;
  }

  /**
   * The failed checks, each with its reason, then those earning part of their point; the passed
   * ones folded under one line. A hidden fixture's check says so; its reason gives its rule only.
   */
  private drawChecks(report: GradeReport): void {
    const marks: Record<CheckStatus, string> = { passed: '✓', partial: '◐', failed: '✗' };
    const classes: Record<CheckStatus, string> = { passed: 'pass', partial: 'partial', failed: 'fail' };
    const item = (check: GradeReport['checks'][number]) =>
      el(
        'li',
        { class: classes[check.status] },
        el('span', { class: 'mark', 'aria-hidden': 'true' }, marks[check.status]),
        ' ',
        el('strong', {}, check.name),
        check.hidden ? el('span', { class: 'note' }, ' (hidden: its mesh is not shown)') : '',
        check.status === 'partial' ? el('span', { class: 'note' }, ` ${check.score} of a point`) : '',
        check.passed ? '' : el('span', { class: 'why' }, check.message),
      );
    const passed = report.checks.filter((c) => c.passed);
    replace(
      this.checks,
      ...report.checks.filter((c) => c.status === 'failed').map(item),
      ...report.checks.filter((c) => c.status === 'partial').map(item),
      passed.length === 0 ? null : el('li', {}, el('details', { open: passed.length === report.checks.length }, el('summary', {}, `${passed.length} passed`), el('ul', { class: 'practice-checks' }, ...passed.map(item)))),
    );
  }

  private drawBroken(first: FirstBroken | null, fixture: number): void {
    if (!first) return replace(this.broken);
    const result = this.report!.fixtures[fixture];
    replace(
      this.broken,
      el('p', {}, `First broken: ${first.invariant}. It broke at write ${first.write + 1}, ${describeWrite(result.writes[first.write])}`, first.line === null ? '.' : ', ', lineButton(first.line, (line) => this.goToLine(line))),
    );
  }

  private drawWrites(fixture: number): void {
    const result = this.report?.fixtures[fixture];
    if (!result || result.hidden || this.exercise.kind === 'query') return replace(this.writes);
    const shown = this.shown?.fixture === fixture ? this.shown : null;
    const at = shown ? shown.write : -1;
    const step = (delta: number) => void this.show(fixture, (at < 0 ? 0 : at) + delta);
    replaceKeepingFocus(
      this.writes,
      el('h3', {}, `Writes (${result.writes.length})`),
      this.fixturePicker('writes', fixture, (i) => void this.show(i, this.report!.fixtures[i].writes.length)),
      el(
        'div',
        { class: 'practice-buttons' },
        el('button', { type: 'button', 'aria-label': 'Show the fixture before any write', onclick: () => void this.show(fixture, 0) }, 'Before'),
        el('button', { type: 'button', 'aria-label': 'Show the previous write', disabled: at <= 0, onclick: () => step(-1) }, 'Previous write'),
        el('button', { type: 'button', 'aria-label': 'Show the next write', disabled: at >= result.writes.length, onclick: () => step(1) }, 'Next write'),
        el('button', { type: 'button', 'aria-label': 'Show the result after every write', onclick: () => void this.show(fixture, result.writes.length) }, 'After'),
      ),
      el('p', { class: 'note', role: 'status' }, shownText(shown, result.writes.length)),
      el(
        'ol',
        { class: 'practice-write-list' },
        ...result.writes.slice(0, WRITES_LISTED).map((write, i) =>
          el(
            'li',
            { class: [i + 1 === at ? 'current' : '', result.firstBroken?.write === i ? 'culprit' : ''].join(' ').trim() || undefined },
            el('button', { type: 'button', 'aria-label': `Show the mesh after write ${i + 1}, ${describeWrite(write)}`, onclick: () => void this.show(fixture, i + 1) }, describeWrite(write)),
            write.line === null ? '' : el('span', { class: 'line' }, ` line ${write.line}`),
          ),
        ),
      ),
      result.writes.length > WRITES_LISTED ? el('p', { class: 'note' }, `The first ${WRITES_LISTED} are listed; step with the buttons to see the rest.`) : null,
    );
    this.writes.querySelector('li.current')?.scrollIntoView({ block: 'nearest' });
  }

  /** A query's reads on one fixture: play them, or step, in the view. */
  private drawReads(fixture: number): void {
    const result = this.report?.fixtures[fixture];
    if (!result || result.hidden || this.exercise.kind !== 'query') return replace(this.reads);
    const total = result.visits.length;
    const at = this.read?.fixture === fixture ? this.read.step : 0;
    const playing = this.readTimer !== null;
    const kept = total === MAX_VISITS ? ` (the first ${total.toLocaleString('en')} of ${result.reads.toLocaleString('en')} reads are kept)` : '';
    replaceKeepingFocus(
      this.reads,
      el('h3', {}, `Reads (${total})`),
      this.fixturePicker('reads', fixture, (i) => void this.showRead(i, this.report!.fixtures[i].visits.length - 1)),
      total === 0
        ? el('p', { class: 'note' }, 'The code read no halfedge pointer on this fixture.')
        : el(
            'div',
            { class: 'practice-buttons' },
            el('button', { type: 'button', 'aria-label': 'Play the reads', 'aria-pressed': String(playing), onclick: () => (playing ? this.stopReads() : void this.playReads()) }, playing ? 'Pause' : 'Play'),
            el('button', { type: 'button', 'aria-label': 'Show the previous read', disabled: at <= 0, onclick: () => void this.showRead(fixture, at - 1) }, 'Previous read'),
            el('button', { type: 'button', 'aria-label': 'Show the next read', disabled: at >= total - 1, onclick: () => void this.showRead(fixture, at + 1) }, 'Next read'),
          ),
      total === 0 ? null : el('p', { class: 'note', role: 'status' }, `Read ${at + 1} of ${total}: h${result.visits[at]} (orange); the halfedges read before it are blue${kept}.`),
    );
  }

  /** Which fixture's writes or reads are listed (a hidden one is not offered). */
  private fixturePicker(what: 'writes' | 'reads', fixture: number, pick: (fixture: number) => void): HTMLElement {
    const select = el('select', { 'aria-label': `Fixture whose ${what} are shown`, onchange: () => pick(Number(select.value)) },
      ...this.report!.fixtures.map((f, i) => (f.hidden ? null : el('option', { value: i, selected: i === fixture }, f.fixture))));
    return el('label', {}, 'On ', select);
  }

  private exportSolutions(): void {
    const solutions = Object.fromEntries(this.exercises.map((e) => [e.id, saved(e.id)?.code ?? null]).filter(([, code]) => code !== null));
    const blob = new Blob([JSON.stringify({ format: 'halfedge-lab practice solutions', solutions }, null, 2)], { type: 'application/json' });
    const link = el('a', { href: URL.createObjectURL(blob), download: 'halfedge-lab-solutions.json' });
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
    this.actions.say(`Exported ${Object.keys(solutions).length} solutions.`);
  }
}

function firstCulprit({ elements }: FirstBroken): { kind: 'halfedge' | 'vertex' | 'face'; id: number } | null {
  if (elements.vertices.length) return { kind: 'vertex', id: elements.vertices[0] };
  if (elements.halfedges.length) return { kind: 'halfedge', id: elements.halfedges[0] };
  if (elements.faces.length) return { kind: 'face', id: elements.faces[0] };
  return null;
}

function shownText(shown: PracticePanel['shown'], total: number): string {
  if (!shown) return '';
  const after = (n: number) => (n === 0 ? 'the fixture before any write' : `the mesh after write ${n} of ${total}`);
  if (shown.drawn === shown.write) return `The view shows ${after(shown.write)}.`;
  return `After write ${shown.write} the pointers are half-way rewired (${shown.why}), which cannot be drawn: the view shows ${after(shown.drawn)}, the last state that can, with the writes since marked on it.`;
}

function resultOf(report: GradeReport, shown: number): PracticeRunResult {
  const fixture = report.fixtures[shown];
  return {
    passed: report.passed,
    score: report.score,
    maxScore: report.maxScore,
    checks: report.checks.map(({ name, passed, status, score, message, hidden }) => ({ name, passed, status, score, message, hidden: hidden === true })),
    writes: fixture.writes,
    firstBroken: fixture.firstBroken,
    fixtures: report.fixtures.map((f) => ({ name: f.fixture, hidden: f.hidden, writes: f.writes, firstBroken: f.firstBroken })),
    error: null,
  };
}

function lineButton(line: number | null, go: (line: number) => void): HTMLElement | string {
  return line === null ? '' : el('button', { type: 'button', class: 'link', 'aria-label': `Go to line ${line} in the editor`, onclick: () => go(line) }, `line ${line}`);
}

/** What is kept for an exercise, or for one of its older ids (a `poke-face` solution for `inset-vertex`). */
function savedFor(exercise: Exercise): Saved | null {
  for (const id of [exercise.id, ...(exercise.aliases ?? [])]) {
    const value = saved(id);
    if (value) return value;
  }
  return null;
}

function saved(id: string): Saved | null {
  try {
    const text = localStorage.getItem(storageKey(id));
    const value = text ? (JSON.parse(text) as Saved) : null;
    return value && typeof value.code === 'string' ? value : null;
  } catch {
    return null;
  }
}

function store(id: string, value: Saved): void {
  try {
    localStorage.setItem(storageKey(id), JSON.stringify(value));
  } catch {
    // storage full or refused (a private window): the code stays in the editor
  }
}
