/**
 * Walk buttons (each with its key) and the breadcrumb of the path walked.
 */
import { el, replace } from '../dom.js';
import type { Convention } from '../records.js';
import { breadcrumbText, type Move, type WalkStep } from '../selection.js';

/** The walk buttons; the vertex one walks to the vertex the naming names (V: origin or target). */
export function walkButtons(convention: Convention): Array<{ move: Move; key: string; label: string; title: string }> {
  const vertex = convention === 'origin' ? 'the vertex the halfedge starts from' : 'the vertex the halfedge points to';
  return [
    { move: 'next', key: 'N', label: 'next', title: 'next: the following halfedge around the same face' },
    { move: 'prev', key: 'P', label: 'prev', title: 'prev: the previous halfedge around the same face' },
    { move: 'twin', key: 'T', label: 'twin', title: 'twin: the opposite halfedge of the same edge' },
    { move: 'face', key: 'F', label: 'face', title: 'face: the face on the left' },
    { move: convention, key: 'V', label: convention, title: `${convention}: ${vertex}` },
    { move: 'edge', key: 'E', label: 'edge', title: 'edge: the edge this halfedge is half of' },
    { move: 'halfedge', key: 'H', label: 'halfedge', title: 'halfedge: the halfedge a vertex, face or edge points to' },
    { move: 'twin.next', key: 'R', label: 'twin.next', title: 'twin.next: rotate clockwise around the vertex the halfedge starts from' },
    { move: 'prev.twin', key: 'L', label: 'prev.twin', title: 'prev.twin: rotate counter-clockwise around the vertex the halfedge starts from' },
  ];
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
