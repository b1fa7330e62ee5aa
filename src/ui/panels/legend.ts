/** The colour legend, on screen whenever the mesh is. */
import { colors, legend } from '../colors.js';
import { el, replace } from '../dom.js';
import type { ColourScale } from '../scene/colour-map.js';

export function renderLegend(container: HTMLElement): void {
  replace(
    container,
    ...legend.map(({ role, label }) =>
      el('div', { class: 'legend-row' }, el('span', { class: 'swatch', style: `background:${colors[role]}`, 'aria-hidden': 'true' }), label),
    ),
    el('div', { class: 'legend-row' }, el('span', { class: 'swatch dashed', 'aria-hidden': 'true' }), 'boundary halfedge'),
  );
}

/** The colour scale of the values a phase reports (hidden when the surface is plain). */
export function renderValuesLegend(container: HTMLElement, scale: ColourScale | null, title: string): void {
  container.hidden = scale === null;
  if (!scale) return;
  const gradient = scale.diverging ? '#0072B2, #ffffff, #D55E00' : '#F0E442, #009E73, #0072B2';
  const number = (x: number) => (Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4 ? +x.toPrecision(3) : x.toExponential(2));
  replace(
    container,
    el('div', {}, title),
    el('div', { class: 'values-bar', style: `background: linear-gradient(to right, ${gradient})` }),
    el('div', { class: 'values-ends' }, el('span', {}, String(number(scale.low))), el('span', {}, `${number(scale.high)}+`)),
  );
}
