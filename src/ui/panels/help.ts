/** The help overlay (`?`): every key, from the same table that handles them. */
import { el, replace } from '../dom.js';
import { keyBindings } from '../keys.js';

export function renderHelp(container: HTMLElement): void {
  // a list of key and meaning pairs, which the style sets in two columns where the card is wide
  const rows = keyBindings
    .filter((binding) => binding.help)
    .map(({ keys, help }) => el('div', { class: 'key-row' }, el('dt', {}, ...keyCaps(keys)), el('dd', {}, help)));
  replace(container, el('dl', { class: 'keys' }, ...rows));
}

/** A key cap each, `N` / `P` / `T`: a narrow column wraps between them, never inside one. */
function keyCaps(keys: string[]): (HTMLElement | string)[] {
  return keys.flatMap((key, i) => [...(i > 0 ? [' / '] : []), el('kbd', {}, displayKey(key))]);
}

function displayKey(key: string): string {
  return key.length === 1 ? key.toUpperCase() : key.replace(/(^|\+)(\w)/g, (_, plus: string, c: string) => plus + c.toUpperCase());
}
