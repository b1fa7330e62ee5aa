/** The help overlay (`?`): every key, from the table of commands that handles them. */
import { commands, displayKey } from '../commands.js';
import { el, replace } from '../dom.js';
import type { Convention } from '../records.js';

/** Drawn again when the naming changes: the V key's line says which vertex it walks to. */
export function renderHelp(container: HTMLElement, convention: Convention): void {
  // a list of key and meaning pairs, which the style sets in two columns where the card is wide
  const rows = commands
    .filter((command) => command.keys.length > 0)
    .map((command) => el('div', { class: 'key-row' }, el('dt', {}, ...keyCaps(command.keys)), el('dd', {}, command.help(convention))));
  replace(container, el('dl', { class: 'keys' }, ...rows));
}

/** A key cap each, `Ctrl+Y` / `Ctrl+Shift+Z`: a narrow column wraps between them, never inside one. */
function keyCaps(keys: string[]): (HTMLElement | string)[] {
  return keys.flatMap((key, i) => [...(i > 0 ? [' / '] : []), el('kbd', {}, displayKey(key))]);
}
