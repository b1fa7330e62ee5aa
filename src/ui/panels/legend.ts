/** The colour legend, on screen whenever the mesh is. */
import { colors, legend } from '../colors.js';
import { el, replace } from '../dom.js';

export function renderLegend(container: HTMLElement): void {
  replace(
    container,
    ...legend.map(({ role, label }) =>
      el('div', { class: 'legend-row' }, el('span', { class: 'swatch', style: `background:${colors[role]}`, 'aria-hidden': 'true' }), label),
    ),
    el('div', { class: 'legend-row' }, el('span', { class: 'swatch dashed', 'aria-hidden': 'true' }), 'boundary halfedge'),
  );
}
