/** The history timeline: every mesh so far, the current one marked; click one to go back to it. */
import type { PageSnapshot as Snapshot } from '../../workers/page-copy.js';
import { el, replace } from '../dom.js';
import { setAvailability, whenAvailable } from './operations.js';

export interface HistoryActions {
  undo(): void;
  redo(): void;
  jump(index: number): void;
}

export class HistoryPanel {
  private readonly undoButton: HTMLButtonElement;
  private readonly redoButton: HTMLButtonElement;
  private readonly list = el('ol', { class: 'history', 'aria-label': 'History of the mesh' });

  constructor(container: HTMLElement, private readonly actions: HistoryActions) {
    this.undoButton = el('button', { type: 'button', 'aria-keyshortcuts': 'Control+Z', onclick: whenAvailable(() => actions.undo()) }, 'Undo');
    this.redoButton = el('button', { type: 'button', 'aria-keyshortcuts': 'Control+Y', onclick: whenAvailable(() => actions.redo()) }, 'Redo');
    replace(container, el('div', { class: 'button-row' }, this.undoButton, this.redoButton), this.list);
  }

  update(snapshot: Snapshot): void {
    const { items, index } = snapshot.history;
    setAvailability(this.undoButton, 'Undo (Ctrl+Z)', index > 0 ? null : 'nothing to undo');
    setAvailability(this.redoButton, 'Redo (Ctrl+Y)', index + 1 < items.length ? null : 'nothing to redo');
    replace(
      this.list,
      ...items.map((item, i) =>
        el(
          'li',
          { 'aria-current': i === index ? 'step' : undefined, class: i > index ? 'undone' : undefined },
          el(
            'button',
            { type: 'button', class: 'link', 'aria-label': `Go back to: ${item.label}`, onclick: () => this.actions.jump(i) },
            item.label,
          ),
          ` — ${item.vertices} V, ${item.faces} F`,
        ),
      ),
    );
  }
}
