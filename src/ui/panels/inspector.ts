/**
 * The record panel: the selected element printed like a debugger would,
 * `h17 { next: h18, prev: h19, twin: h16, origin: v4, face: f5, edge: e8 }`, each value a link
 * (a button) that follows that pointer as a step of the walk (so Back returns), coloured as in
 * the legend.
 */
import type { HalfedgeMesh } from '../../core/index.js';
import { type PointerRole, swatchStyle } from '../colors.js';
import { el, replace } from '../dom.js';
import { type Convention, conventionNote, recordOf } from '../records.js';
import { elementName, type Selection } from '../selection.js';

const roleOfField: Record<string, PointerRole> = { next: 'next', prev: 'prev', twin: 'twin', face: 'face', origin: 'origin', target: 'origin' };

export function renderInspector(
  record: HTMLElement,
  note: HTMLElement,
  mesh: HalfedgeMesh | null,
  selection: Selection | null,
  convention: Convention,
  follow: (field: string, s: Selection) => void,
): void {
  note.textContent = conventionNote[convention];
  if (!mesh || !selection) {
    replace(record, 'Click a halfedge arrow, a vertex or a face (or use the tables).');
    return;
  }
  const lines: Array<Node | string> = [`${elementName(selection)} {\n`];
  for (const { field, value } of recordOf(mesh, selection, convention)) {
    const role = roleOfField[field];
    const swatch = role ? el('span', { class: 'swatch', style: swatchStyle(role), 'aria-hidden': 'true' }) : '';
    const shown =
      'element' in value
        ? el(
            'button',
            {
              type: 'button',
              class: 'link',
              'data-element': elementName(value.element),
              'aria-label': `${field || 'also'}: select ${elementName(value.element)}`,
              onclick: () => follow(field, value.element),
            },
            elementName(value.element),
          )
        : value.text;
    lines.push('  ', swatch, field ? `${field}: ` : '  ', shown, ',\n');
  }
  lines.push('}');
  replace(record, ...lines);
}
