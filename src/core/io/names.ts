/**
 * Names from a file, in notes and messages. A file chooses its names freely: a header may declare
 * a hundred thousand properties, or one name a megabyte long. A note stays a sentence a student
 * reads: each name is cut short, and a list shows its first few items, then how many more there are.
 *
 * @example
 *   someOf(['a', 'b', 'c', 'd', 'e', 'f', 'g'].map(quoted)); // "'a', 'b', 'c', 'd', 'e' and 2 more"
 */

/** Characters of a name shown before it is cut. */
const NAME_CHARS = 40;

/** Items of a list shown before "and N more". */
const ITEMS_SHOWN = 5;

/** The name in quotes, cut to its first 40 characters. */
export function quoted(name: string): string {
  return name.length > NAME_CHARS ? `'${name.slice(0, NAME_CHARS)}…'` : `'${name}'`;
}

/** The first `shown` items joined by commas, then "and N more" for the rest. */
export function someOf(items: readonly string[], shown = ITEMS_SHOWN): string {
  if (items.length <= shown) return items.join(', ');
  return `${items.slice(0, shown).join(', ')} and ${items.length - shown} more`;
}
