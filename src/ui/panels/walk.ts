/**
 * Walk buttons (each with its key, from the table of commands) and the breadcrumb of the path walked.
 */
import { type Command, commands, displayKey } from '../commands.js';
import { el, replace } from '../dom.js';
import type { Convention } from '../records.js';
import { breadcrumbText, type Move, type WalkStep } from '../selection.js';

/** The walk buttons: the walk commands; the vertex one walks to the vertex the naming names (V: origin or target). */
export function walkButtons(convention: Convention): Array<{ move: Move; key: string; label: string; title: string }> {
  return commands
    .filter((command): command is Command & { move: (c: Convention) => Move } => command.move !== undefined)
    .map((command) => {
      const move = command.move(convention);
      return { move, key: displayKey(command.keys[0]!), label: move, title: command.help(convention) };
    });
}

export function renderWalkButtons(container: HTMLElement, go: (move: Move) => void, convention: Convention): void {
  replace(
    container,
    ...walkButtons(convention).map(({ move, key, label, title }) =>
      el(
        'button',
        { type: 'button', 'data-move': move, 'aria-label': `Walk to ${label} (${key})`, 'aria-keyshortcuts': key, title: `${title} (${key})`, onclick: () => go(move) },
        el('kbd', {}, key),
        ` ${label}`,
      ),
    ),
  );
}

/** The breadcrumb; `maxSteps`: fewer in presentation mode, where its large type must fit the panel. */
export function renderBreadcrumb(container: HTMLElement, path: WalkStep[], maxSteps?: number): void {
  container.textContent = path.length ? breadcrumbText(path, maxSteps) : '—';
}
