/**
 * The stepper: Step (one phase), Run to end, Cancel; the phase's name and explanation; what it
 * created, moved and rewired (drawn in the view); and the pointer diff — each `next`, `prev`,
 * `twin`-side, `face` and `origin` field that changed, old → new.
 */
import type { PointerChange } from '../../core/index.js';
import type { PageSnapshot as Snapshot } from '../../workers/page-copy.js';
import { phaseColors } from '../colors.js';
import { el, replace } from '../dom.js';
import type { Selection } from '../selection.js';
import { setAvailability, whenAvailable } from './operations.js';

export interface StepperActions {
  step(): void;
  stepBack(): void;
  runToEnd(): void;
  cancel(): void;
  select(s: Selection): void;
}

/**
 * "Loop subdivision — phase 2 of 4: split every edge" while an operation is being stepped (or
 * "…: ready — press Step" before its first phase), "…phase 4 of 4 (done): …" while the last phase
 * of one the last Step ended stays on show; null otherwise. The stepper and the view's legend both
 * say it.
 */
export function steppingTitle(snapshot: Snapshot): string | null {
  const { phase } = snapshot;
  const stepping = snapshot.stepping ?? snapshot.ended;
  if (!stepping) return null;
  if (stepping.phases === 0) return `${stepping.label}: ready — press Step`;
  const of = stepping.total ? ` of ${stepping.total}` : '';
  return `${stepping.label} — phase ${stepping.phases}${of}${snapshot.ended ? ' (done)' : ''}: ${phase?.name ?? ''}`;
}

/**
 * Rows of the pointer diff shown (the count says how many there were): more than a lecture reads
 * in its scroll box, and few enough to lay out with the phase (300 took 33 ms of the task that
 * shows a subdivision phase).
 */
const MAX_DIFF_ROWS = 100;

export class StepperPanel {
  private readonly title = el('p', { class: 'phase-title', 'aria-live': 'polite' });
  private readonly explanation = el('p', { class: 'phase-explanation' });
  private readonly diff = el('div', { class: 'diff scroll-box' });
  private readonly stepButton: HTMLButtonElement;
  private readonly backButton: HTMLButtonElement;
  private readonly runButton: HTMLButtonElement;
  private readonly cancelButton: HTMLButtonElement;

  constructor(container: HTMLElement, private readonly actions: StepperActions) {
    this.stepButton = el('button', { type: 'button', 'aria-keyshortcuts': 'S', onclick: whenAvailable(() => actions.step()) }, 'Step');
    this.backButton = el('button', { type: 'button', 'aria-keyshortcuts': 'Shift+S', onclick: whenAvailable(() => actions.stepBack()) }, 'Previous phase');
    this.runButton = el('button', { type: 'button', 'aria-keyshortcuts': 'G', onclick: whenAvailable(() => actions.runToEnd()) }, 'Run to end');
    this.cancelButton = el('button', { type: 'button', 'aria-keyshortcuts': 'X', onclick: whenAvailable(() => actions.cancel()) }, 'Cancel operation');
    const key = (name: keyof typeof phaseColors) =>
      el('span', { class: 'legend-row' }, el('span', { class: 'swatch', style: `background:${phaseColors[name]}`, 'aria-hidden': 'true' }), name);
    replace(
      container,
      this.title,
      this.explanation,
      el('div', { class: 'button-row' }, this.stepButton, this.backButton, this.runButton, this.cancelButton),
      el('div', { class: 'phase-legend' }, key('created'), key('moved'), key('rewired')),
      this.diff,
    );
  }

  update(snapshot: Snapshot): void {
    const { stepping, ended, phase } = snapshot;
    const notRunning = ended
      ? `${ended.label} has ended: Previous phase (Shift+S) goes back into it, Undo (Ctrl+Z) takes it back`
      : stepping
        ? null
        : 'start an operation first (Operations, above)';
    setAvailability(this.stepButton, 'Step one phase (S)', notRunning);
    setAvailability(
      this.backButton,
      'Back to the previous phase (Shift+S)',
      stepping?.phases === 0 ? 'the operation is at its start: there is no phase before' : stepping || ended ? null : notRunning,
    );
    setAvailability(this.runButton, 'Run to end (G)', notRunning);
    setAvailability(this.cancelButton, 'Cancel the operation (X)', notRunning);
    if (stepping || ended) {
      this.title.textContent = steppingTitle(snapshot)!;
    } else {
      const last = snapshot.history.items[snapshot.history.index];
      this.title.textContent = phase ? `${last?.label ?? 'done'} — done (last phase: ${phase.name})` : 'No operation running.';
    }
    this.explanation.textContent = phase?.explanation ?? '';
    this.renderDiff(snapshot);
  }

  /** What a phase changed, as far as its first few pointers: what the panel keeps in sight. */
  firstChanges(): Element {
    return this.diff.querySelector(`tbody tr:nth-child(${Math.min(3, this.diff.querySelectorAll('tbody tr').length)})`) ?? this.diff;
  }

  private renderDiff(snapshot: Snapshot): void {
    const diff = snapshot.diff;
    if (!diff) {
      replace(this.diff, snapshot.phase ? el('p', { class: 'note' }, 'The pointer diff is left out on a mesh this large.') : '');
      return;
    }
    if (diff.total === 0) {
      replace(this.diff, el('p', { class: 'note' }, 'No pointer changed in this step (positions only, or nothing).'));
      return;
    }
    const rows = diff.changes.slice(0, MAX_DIFF_ROWS).map((change) => this.row(change));
    replace(
      this.diff,
      el('p', {}, `${diff.total} pointer field${diff.total === 1 ? '' : 's'} changed${diff.total > rows.length ? ` (first ${rows.length} shown)` : ''}:`),
      el('table', { class: 'diff-table' }, el('thead', {}, el('tr', {}, el('th', {}, 'element'), el('th', {}, 'field'), el('th', {}, 'old'), el('th', {}, 'new'))), el('tbody', {}, ...rows)),
    );
  }

  private row(change: PointerChange): HTMLTableRowElement {
    const owner: Selection = { kind: change.element, id: change.id };
    const valueKind = change.field === 'origin' ? 'vertex' : change.field === 'face' ? 'face' : 'halfedge';
    const link = (s: Selection, text: string) => el('button', { type: 'button', class: 'link', onclick: () => this.actions.select(s) }, text);
    const value = (id: number) => (id < 0 ? '—' : link({ kind: valueKind, id }, `${valueKind[0]}${id}`));
    return el(
      'tr',
      {},
      el('td', {}, link(owner, `${change.element[0]}${change.id}`)),
      el('td', {}, change.field),
      el('td', {}, value(change.before)),
      el('td', {}, value(change.after)),
    );
  }
}
