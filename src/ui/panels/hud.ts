/**
 * Counts and invariants, always on screen: V, E, F, χ = V − E + F, genus, boundary loops,
 * components, and the state of `validate()` (a check mark, or each broken invariant with a button
 * that selects the culprit).
 */
import type { MeshStats, Violation } from '../../core/index.js';
import { el, replace } from '../dom.js';
import type { Selection } from '../selection.js';

/** Problems listed on the view: more would cover the mesh they are about. */
const SHOWN_PROBLEMS = 2;

export function renderHud(container: HTMLElement, stats: MeshStats, problems: Violation[], select: (s: Selection) => void): void {
  const { vertices: V, edges: E, faces: F } = stats;
  // `short`: what presentation mode shows instead, on its one compact line
  const cell = (label: string, value: string | number, title: string, short?: string) =>
    el(
      'div',
      { class: 'count', title },
      el('span', { class: 'count-label' }, label),
      el('span', { class: `count-value${short ? ' long' : ''}`, 'data-count': label }, String(value)),
      short ? el('span', { class: 'count-value short', 'aria-hidden': 'true' }, short) : '',
    );
  const counts = el(
    'div',
    { class: 'counts' },
    cell('V', V, 'vertices'),
    cell('E', E, 'edges'),
    cell('F', F, 'faces'),
    cell('χ', `${V} − ${E} + ${F} = ${stats.eulerCharacteristic}`, 'Euler characteristic', String(stats.eulerCharacteristic)),
    cell('genus', stats.genus ?? '—', stats.orientable ? 'from χ = 2 − 2g − b, summed over components' : 'undefined: the surface is non-orientable'),
    cell('holes', stats.boundaryLoops, 'boundary loops'),
    cell('parts', stats.components, 'connected components'),
  );
  const invariants =
    problems.length === 0
      ? el('p', { class: 'valid', 'data-valid': 'true' }, el('span', { class: 'long' }, '✓ every halfedge invariant holds'), el('span', { class: 'short', 'aria-hidden': 'true' }, '✓ valid'))
      : el(
          'div',
          { class: 'invalid', 'data-valid': 'false' },
          el('p', {}, `✗ ${problems.length} broken invariant${problems.length === 1 ? '' : 's'}`),
          el(
            'ul',
            {},
            ...problems.slice(0, SHOWN_PROBLEMS).map((problem) => {
              const culprit = culpritOf(problem);
              return el(
                'li',
                {},
                `${problem.invariant}: ${problem.message} `,
                culprit ? el('button', { type: 'button', class: 'link', onclick: () => select(culprit) }, 'select the culprit') : null,
              );
            }),
            problems.length > SHOWN_PROBLEMS ? el('li', { class: 'more' }, `and ${problems.length - SHOWN_PROBLEMS} more`) : null,
          ),
        );
  replace(container, counts, invariants);
}

function culpritOf(problem: Violation): Selection | null {
  if (problem.halfedges?.length) return { kind: 'halfedge', id: problem.halfedges[0] };
  if (problem.vertices?.length) return { kind: 'vertex', id: problem.vertices[0] };
  if (problem.faces?.length) return { kind: 'face', id: problem.faces[0] };
  return null;
}
