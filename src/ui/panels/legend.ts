/**
 * The colour legend, on screen whenever the mesh is. While an operation is stepped the colours
 * mean something else, so the legend then says which phase this is, in one sentence, and what
 * the colours mean now: the phase's name would otherwise sit below the fold of the Operate tab.
 */
import { legend, phaseColors, swatchStyle } from '../colors.js';
import { el, replace } from '../dom.js';
import type { PhaseMeaning } from '../highlights.js';
import type { Convention } from '../records.js';
import type { ColourScale } from '../../workers/colour-scale.js';

/** The phase being stepped: its title ("Loop subdivision — phase 2 of 4: …"), explanation, and what its marks' colours mean. */
export interface LegendPhase {
  title: string;
  explanation: string;
  meanings: readonly PhaseMeaning[];
}

export function renderLegend(container: HTMLElement, phase: LegendPhase | null, convention: Convention): void {
  // presentation mode shows each label's first word only, to keep the legend to a line or two
  const row = (style: string, label: string, swatch = 'swatch') =>
    el(
      'div',
      { class: 'legend-row' },
      el('span', { class: swatch, style, 'aria-hidden': 'true' }),
      ...(label.includes(' ') ? [el('span', { class: 'long' }, label), el('span', { class: 'short', 'aria-hidden': 'true' }, label.split(' ')[0]!)] : [label]),
    );
  container.classList.toggle('stepping', phase !== null);
  if (phase) {
    // the explanation's first sentence: the one that says what the phase does
    const sentence = phase.explanation.split(/(?<=\.) (?=[A-Z])/)[0] ?? '';
    replace(
      container,
      el('p', { class: 'legend-phase' }, phase.title),
      sentence ? el('p', { class: 'legend-sentence' }, sentence) : '',
      ...phase.meanings.map((name) => row(`background:${phaseColors[name]}`, name)),
    );
    return;
  }
  replace(
    container,
    // the highlighted vertex is the one the naming names
    ...legend.map(({ role, label }) => row(swatchStyle(role), role === 'origin' ? `${convention} vertex` : label)),
    row('', 'boundary halfedge', 'swatch dashed'),
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
