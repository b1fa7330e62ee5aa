/** The help overlay (`?`): every key, so the app can be driven from the keyboard alone. */
import { el, replace } from '../dom.js';

export const keyHelp: Array<[string, string]> = [
  ['N / P / T', 'walk to next / prev / twin'],
  ['F / V / E', 'walk to the face / origin vertex / edge'],
  ['H', 'the halfedge of the selected vertex, face or edge'],
  ['R / L', 'twin.next / prev.twin: rotate around the origin'],
  ['Backspace', 'back one step of the walk'],
  ['Esc', 'clear the selection (or close this help)'],
  ['Home / Z', 'frame the mesh / the selection'],
  ['O', 'top view on or off'],
  ['I', 'label every vertex and face (small meshes)'],
  ['S / G / X', 'step the operation / run it to the end / cancel it'],
  ['Ctrl+Z / Ctrl+Y', 'undo / redo'],
  ['Q', 'a new quiz question'],
  ['M', 'presentation mode'],
  ['?', 'this help'],
];

export function renderHelp(container: HTMLElement): void {
  replace(container, el('table', { class: 'keys' }, ...keyHelp.map(([keys, what]) => el('tr', {}, el('th', {}, el('kbd', {}, keys)), el('td', {}, what)))));
}
