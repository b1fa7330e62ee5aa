/**
 * Every command of the app in one table: its name, its keys, its button (where it has one), what
 * it does in words, when it does not apply (and the sentence why), and what it runs. The keys,
 * the toolbar and walk buttons, the `?` help and `window.halfedgeLab.command(name)` are all made
 * from it, so none of them can drift from another.
 *
 * A command reaches the app through `CommandTarget`, the part of it that commands use: the table
 * knows nothing else of the app (and the app imports the table, not the other way round).
 */
import { capitalized } from './dom.js';
import type { Convention } from './records.js';
import type { Move } from './selection.js';
import type { StudentVerb } from '../workers/protocol.js';

/** What the commands ask of the app. */
export interface CommandTarget {
  readonly convention: Convention;
  readonly exploded: boolean;
  readonly helpShown: boolean;
  readonly tablesShown: boolean;
  readonly presenting: boolean;
  walk(move: Move): void;
  back(): void;
  select(selection: null): void;
  frameMesh(): void;
  frameSelection(): void;
  toggleTopView(): void;
  /** Null when the exploded view can be shown, else why not (one part). */
  explodeUnavailable(): string | null;
  setExploded(on: boolean): unknown;
  toggleIds(): void;
  toggleOverlays(): void;
  showTables(show: boolean): void;
  toggleHelp(show?: boolean): void;
  setPresentation(on: boolean): void;
  shareLink(): unknown;
  request(verb: Extract<StudentVerb, 'step' | 'stepBack' | 'runToEnd' | 'cancel' | 'undo' | 'redo'>): unknown;
  askQuiz(): void;
  /** Says why a command does not apply. */
  say(message: string): void;
}

export interface Command {
  /** Its name: `window.halfedgeLab.command(name)` runs it. */
  name: string;
  /** The keys that run it, as `keyName` writes them (`n`, `shift+s`, `ctrl+z`, `?`). */
  keys: string[];
  /** What it does, in words: the help's line and the tooltip of its button. */
  help(convention: Convention): string;
  /** Its button in the layout (`id`), and the button's name for a screen reader. */
  button?: { id: string; label: string };
  /** A walk: the pointer it follows (the walk buttons are made from these). */
  move?: (convention: Convention) => Move;
  /** Null when it applies now, else the sentence why not. */
  unavailable?(target: CommandTarget): string | null;
  run(target: CommandTarget): void;
}

/** A command's button's tooltip: what it does, and its keys. */
export function commandTooltip(command: Command, convention: Convention): string {
  const keys = command.keys.map(displayKey).join(', ');
  return `${capitalized(command.help(convention))}${keys ? ` (${keys})` : ''}`;
}

const walk = (key: string, move: Move, help: string): Command => ({ name: `walk-${move}`, keys: [key], help: () => help, move: () => move, run: (t) => t.walk(move) });

export const commands: readonly Command[] = [
  walk('n', 'next', 'next: the following halfedge around the same face'),
  walk('p', 'prev', 'prev: the previous halfedge around the same face'),
  walk('t', 'twin', 'twin: the opposite halfedge of the same edge'),
  walk('f', 'face', 'face: the face on the left'),
  {
    name: 'walk-vertex',
    keys: ['v'],
    help: (c) => `${c}: ${c === 'origin' ? 'the vertex the halfedge starts from' : 'the vertex the halfedge points to'}`,
    move: (c) => c,
    run: (t) => t.walk(t.convention),
  },
  walk('e', 'edge', 'edge: the edge this halfedge is half of'),
  walk('h', 'halfedge', 'halfedge: the halfedge a vertex, face or edge points to'),
  // around the vertex the halfedge starts from, whatever the naming (twin.next leaves it again)
  walk('r', 'twin.next', 'twin.next: rotate clockwise around the vertex the halfedge starts from'),
  walk('l', 'prev.twin', 'prev.twin: rotate counter-clockwise around the vertex the halfedge starts from'),
  { name: 'walk-back', keys: ['backspace'], help: () => 'back one step of the walk', button: { id: 'walk-back', label: 'Back one step' }, run: (t) => t.back() },
  {
    name: 'escape',
    keys: ['escape'],
    help: () => 'close this help, or clear the selection (and end a quiz question)',
    run: (t) => (t.helpShown ? t.toggleHelp(false) : t.select(null)),
  },
  { name: 'frame-mesh', keys: ['home'], help: () => 'frame the mesh', button: { id: 'frame-mesh', label: 'Frame the mesh' }, run: (t) => t.frameMesh() },
  { name: 'frame-selection', keys: ['z'], help: () => 'frame the selection', button: { id: 'frame-selection', label: 'Frame the selection' }, run: (t) => t.frameSelection() },
  { name: 'top-view', keys: ['o'], help: () => 'orthographic top view on or off (for planar meshes)', button: { id: 'top-view', label: 'Top view' }, run: (t) => t.toggleTopView() },
  {
    name: 'explode',
    keys: ['b'],
    help: () => "exploded view on or off: the parts drawn pulled apart (a cut's two sides, to see the caps)",
    button: { id: 'explode', label: 'Explode parts' },
    // turning it off always applies
    unavailable: (t) => (t.exploded ? null : t.explodeUnavailable()),
    run: (t) => void t.setExploded(!t.exploded),
  },
  { name: 'show-ids', keys: ['i'], help: () => 'label every vertex and face (small meshes)', button: { id: 'show-ids', label: 'Show all ids' }, run: (t) => t.toggleIds() },
  { name: 'overlays', keys: ['k'], help: () => 'hide or show the legend and the counts on the view', run: (t) => t.toggleOverlays() },
  {
    name: 'tables',
    keys: ['d'],
    help: () => 'fold or open the record tables (folded in presentation mode)',
    button: { id: 'tables-fold', label: 'Records' },
    run: (t) => t.showTables(!t.tablesShown),
  },
  { name: 'step', keys: ['s'], help: () => 'step the operation: its next phase', run: (t) => void t.request('step') },
  { name: 'step-back', keys: ['shift+s'], help: () => 'back to the previous phase (also after the last step)', run: (t) => void t.request('stepBack') },
  { name: 'run-to-end', keys: ['g'], help: () => 'run the operation to its end', run: (t) => void t.request('runToEnd') },
  { name: 'cancel', keys: ['x'], help: () => 'cancel the operation', button: { id: 'cancel', label: 'Cancel' }, run: (t) => void t.request('cancel') },
  { name: 'undo', keys: ['ctrl+z'], help: () => 'undo', run: (t) => void t.request('undo') },
  { name: 'redo', keys: ['ctrl+y', 'ctrl+shift+z'], help: () => 'redo', run: (t) => void t.request('redo') },
  { name: 'quiz', keys: ['q'], help: () => 'a new quiz question', run: (t) => t.askQuiz() },
  { name: 'presentation', keys: ['m'], help: () => 'presentation mode: large type and arrows, full screen', button: { id: 'presentation', label: 'Presentation mode' }, run: (t) => t.setPresentation(!t.presenting) },
  { name: 'share', keys: [], help: () => 'copy a link that opens this model, selection and view', button: { id: 'share', label: 'Copy a link to this view' }, run: (t) => void t.shareLink() },
  { name: 'help', keys: ['?'], help: () => 'this help', button: { id: 'help', label: 'Keyboard help' }, run: (t) => t.toggleHelp() },
];

/** The command of this name. */
export function commandNamed(name: string): Command | undefined {
  return commands.find((command) => command.name === name);
}

/** `ctrl+shift+z`, `shift+s`, `n`, `?`, `backspace`: the name a command lists a key press under. */
export function keyName(event: KeyboardEvent): string {
  const key = event.key.toLowerCase();
  // Shift names itself only with a letter: `?` is Shift+/ on most keyboards and lists as `?`
  const shift = event.shiftKey ? (event.ctrlKey || event.metaKey ? 'shift+' : /^[a-z]$/.test(key) ? 'shift+' : '') : '';
  const modifiers = event.ctrlKey || event.metaKey ? 'ctrl+' : '';
  return `${modifiers}${shift}${key}`;
}

/** `N`, `Shift+S`, `Ctrl+Z`, `Home`: a key as a key cap shows it. */
export function displayKey(key: string): string {
  return key.length === 1 ? key.toUpperCase() : key.replace(/(^|\+)(\w)/g, (_, plus: string, c: string) => plus + c.toUpperCase());
}

/**
 * Runs `command` unless it does not apply now; returns null when it ran, else why it did not.
 * A key and a button run commands through here, and so does the automation.
 */
export function runCommand(target: CommandTarget, command: Command): string | null {
  const why = command.unavailable?.(target) ?? null;
  if (why === null) command.run(target);
  else target.say(`${command.button?.label ?? command.name} is not available: ${why}.`);
  return why;
}

/** Runs the command of a key press; false when no command has that key. */
export function handleKey(target: CommandTarget, event: KeyboardEvent): boolean {
  if (event.altKey) return false;
  const name = keyName(event);
  const command = commands.find((c) => c.keys.includes(name));
  if (!command) return false;
  runCommand(target, command);
  return true;
}
