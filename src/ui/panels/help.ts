/** The help overlay (`?`): every key, from the same table that handles them. */
import { el, replace } from '../dom.js';
import { keyBindings } from '../keys.js';

export function renderHelp(container: HTMLElement): void {
  const rows = keyBindings
    .filter((binding) => binding.help)
    .map(({ keys, help }) => el('tr', {}, el('th', {}, el('kbd', {}, keys.map(displayKey).join(' / '))), el('td', {}, help)));
  replace(container, el('table', { class: 'keys' }, ...rows));
}

function displayKey(key: string): string {
  return key.length === 1 ? key.toUpperCase() : key.replace(/(^|\+)(\w)/g, (_, plus: string, c: string) => plus + c.toUpperCase());
}
