/**
 * Every key of the app in one table: what it does and the line the help overlay (`?`) shows, so
 * the two cannot drift apart. The app can be driven from the keyboard alone.
 */
import type { App } from './app.js';
import { moveKeys } from './selection.js';

interface KeyBinding {
  /** As `keyName` writes them: `n`, `backspace`, `ctrl+z`, `?`. */
  keys: string[];
  help: string;
  run: (app: App, key: string) => void;
}

const walk = (app: App, key: string) => void app.walk(moveKeys[key]!);

export const keyBindings: KeyBinding[] = [
  { keys: ['n', 'p', 't'], help: 'walk to next / prev / twin', run: walk },
  { keys: ['f', 'e'], help: 'walk to the face / edge', run: walk },
  { keys: ['v'], help: 'walk to the vertex the naming names: origin or target', run: (app) => void app.walk(app.inspection.convention) },
  { keys: ['h'], help: 'the halfedge of the selected vertex, face or edge', run: walk },
  { keys: ['r', 'l'], help: 'twin.next / prev.twin: rotate around the origin', run: walk },
  { keys: ['backspace'], help: 'back one step of the walk', run: (app) => app.back() },
  { keys: ['escape'], help: 'close this help, or clear the selection (and end a quiz question)', run: (app) => (app.helpShown ? app.toggleHelp(false) : app.select(null)) },
  { keys: ['home', 'z'], help: 'frame the mesh / the selection', run: (app, key) => (key === 'home' ? app.frameMesh() : app.frameSelection()) },
  { keys: ['o'], help: 'top view on or off', run: (app) => app.toggleTopView() },
  { keys: ['b'], help: "exploded view on or off: the parts drawn pulled apart (a cut's two sides, to see the caps)", run: (app) => void app.setExploded(!app.exploded) },
  { keys: ['i'], help: 'label every vertex and face (small meshes)', run: (app) => app.toggleIds() },
  { keys: ['k'], help: 'hide or show the legend and the counts on the view', run: (app) => app.toggleOverlays() },
  { keys: ['d'], help: 'fold or open the record tables (folded in presentation mode)', run: (app) => app.showTables(!app.tablesShown) },
  {
    keys: ['s', 'g', 'x'],
    help: 'step the operation / run it to the end / cancel it',
    run: (app, key) => void app.request(key === 's' ? 'step' : key === 'g' ? 'runToEnd' : 'cancel'),
  },
  { keys: ['shift+s'], help: 'back to the previous phase (also after the last step)', run: (app) => void app.request('stepBack') },
  { keys: ['ctrl+z', 'ctrl+y'], help: 'undo / redo (also ctrl+shift+z)', run: (app, key) => void app.request(key === 'ctrl+z' ? 'undo' : 'redo') },
  { keys: ['ctrl+shift+z'], help: '', run: (app) => void app.request('redo') },
  {
    keys: ['q'],
    help: 'a new quiz question',
    run: (app) => {
      app.showTab('quiz');
      app.quiz.ask();
    },
  },
  { keys: ['m'], help: 'presentation mode', run: (app) => app.setPresentation(app.scale === 1) },
  { keys: ['?'], help: 'this help', run: (app) => app.toggleHelp() },
];

/** `ctrl+shift+z`, `shift+s`, `n`, `?`, `backspace`: the name a binding lists a key press under. */
export function keyName(event: KeyboardEvent): string {
  const key = event.key.toLowerCase();
  // Shift names itself only with a letter: `?` is Shift+/ on most keyboards and lists as `?`
  const shift = event.shiftKey ? (event.ctrlKey || event.metaKey ? 'shift+' : /^[a-z]$/.test(key) ? 'shift+' : '') : '';
  const modifiers = event.ctrlKey || event.metaKey ? 'ctrl+' : '';
  return `${modifiers}${shift}${key}`;
}

/** Runs the binding of a key press; false when no binding has that key. */
export function handleKey(app: App, event: KeyboardEvent): boolean {
  if (event.altKey) return false;
  const name = keyName(event);
  const binding = keyBindings.find((b) => b.keys.includes(name));
  if (!binding) return false;
  binding.run(app, name);
  return true;
}
