/**
 * Counts and invariants, always on screen: V, E, F, χ = V − E + F, genus (per part when there are
 * several), boundary loops (the first few listed with their lengths, each with a button that frames
 * it), components, and the state of `validate()` (a check mark, or each broken invariant with a
 * button that selects the culprit).
 */
import type { MeshStats, Violation } from '../../core/index.js';
import { el, replace } from '../dom.js';
import type { Selection } from '../selection.js';

/** Problems listed on the view: more would cover the mesh they are about. */
const SHOWN_PROBLEMS = 2;
/** Boundary loops listed on the view, for the same reason. */
const SHOWN_LOOPS = 3;
/** Parts whose genera are spelled out: past this many, a row of terms would run across the view. */
const SPELLED_PARTS = 4;

/** A boundary loop: one of its halfedges, and its number of edges. */
export interface BoundaryLoop {
  halfedge: number;
  length: number;
}

export interface HudActions {
  select: (s: Selection) => void;
  frameLoop: (index: number) => void;
}

export function renderHud(container: HTMLElement, stats: MeshStats, problems: Violation[], loops: BoundaryLoop[], actions: HudActions): void {
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
    genusCell(stats, cell),
    cell('boundary loops', stats.boundaryLoops, 'closed chains of boundary halfedges (halfedges without a face)'),
    cell('parts', stats.components, 'connected components'),
  );
  const loopList =
    loops.length === 0
      ? null
      : el(
          'ul',
          { class: 'loops', 'aria-label': 'Boundary loops' },
          ...loops.slice(0, SHOWN_LOOPS).map(({ length }, i) =>
            el(
              'li',
              {},
              `loop ${i + 1}: ${length} edge${length === 1 ? '' : 's'} `,
              el('button', { type: 'button', class: 'link', 'aria-label': `Frame boundary loop ${i + 1}`, onclick: () => actions.frameLoop(i) }, 'frame'),
            ),
          ),
          loops.length > SHOWN_LOOPS ? el('li', { class: 'more' }, `and ${loops.length - SHOWN_LOOPS} more`) : null,
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
                culprit ? el('button', { type: 'button', class: 'link', onclick: () => actions.select(culprit) }, 'select the culprit') : null,
              );
            }),
            problems.length > SHOWN_PROBLEMS ? el('li', { class: 'more' }, `and ${problems.length - SHOWN_PROBLEMS} more`) : null,
          ),
        );
  replace(container, counts, loopList, invariants);
}

/**
 * The genus: with several parts, each part's (“1 + 1” for two tori, which a sum of 2 would make
 * read as a double torus), “–” for a non-orientable part; with many parts, the first few (the
 * parts cell says how many, the tooltip the sum).
 */
function genusCell(stats: MeshStats, cell: (label: string, value: string | number, title: string) => HTMLElement): HTMLElement {
  const parts = stats.genusPerPart;
  if (parts.length < 2) {
    return cell('genus', stats.genus ?? '—', stats.orientable ? 'from χ = 2 − 2g − b' : 'undefined: the surface is non-orientable');
  }
  const terms = parts.slice(0, SPELLED_PARTS).map((g) => (g === null ? '–' : String(g)));
  const value = terms.join(' + ') + (parts.length > SPELLED_PARTS ? ' + …' : '');
  const title =
    stats.genus === null
      ? 'per part, each from χ = 2 − 2g − b of that part; – for a non-orientable part, which has no genus'
      : `per part, each from χ = 2 − 2g − b of that part; ${stats.genus} in all`;
  return cell('genus', value, title);
}

function culpritOf(problem: Violation): Selection | null {
  if (problem.halfedges?.length) return { kind: 'halfedge', id: problem.halfedges[0] };
  if (problem.vertices?.length) return { kind: 'vertex', id: problem.vertices[0] };
  if (problem.faces?.length) return { kind: 'face', id: problem.faces[0] };
  return null;
}
