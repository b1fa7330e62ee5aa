/**
 * How the page reaches the app: its buttons and menus, files picked or dropped, clicks and hovers
 * on the canvas, and the keys. Only wiring: a key or a toolbar button runs a command of the table
 * in commands.ts (which the automation runs too); a menu or a file calls the app, through
 * `ControlsTarget`, the part of it the controls use (the app imports this file, not the other way).
 */
import { type Command, commands, type CommandTarget, commandTooltip, displayKey, handleKey, runCommand } from './commands.js';
import { byId } from './dom.js';
import type { DragAdjust } from './drag-adjust.js';
import type { Opening } from './opening.js';
import type { Convention } from './records.js';
import type { PickFilter } from './scene/picking.js';
import type { Selection } from './selection.js';

/** The tabs of the side bar, each a button `tab-…` over a pane `pane-…`. */
export const tabs = ['inspect', 'operate', 'quiz', 'practice', 'file'] as const;
export type Tab = (typeof tabs)[number];

/** Where a key press is typing, not a command. */
const FIELDS = 'input, select, textarea, [contenteditable]';

export interface ControlsHost {
  /** Holds the markup of layout.html. */
  root: Document | ShadowRoot;
  /** Hears the keys and the dropped files: the window for the page, the element for an embed. */
  input: Window | HTMLElement;
  canvas: HTMLCanvasElement;
  /** Whether a pick answers at once (not while a large mesh's hierarchy is still being built). */
  quickToPick: () => boolean;
}

/** What the controls ask of the app. */
export interface ControlsTarget {
  readonly opening: Pick<Opening, 'openFiles' | 'openSample'>;
  filter: PickFilter;
  readonly inspection: { readonly convention: Convention };
  readonly commandTarget: CommandTarget;
  readonly adjust: Pick<DragAdjust, 'down' | 'move' | 'up' | 'end'>;
  readonly viewer: { readonly controls: { enabled: boolean } };
  setConvention(convention: Convention): void;
  toggleHelp(show?: boolean): void;
  showTab(tab: Tab): void;
  click(x: number, y: number): Promise<void>;
  pickAt(x: number, y: number): Promise<Selection | null>;
  hover(selection: Selection | null): void;
}

export function wireControls(app: ControlsTarget, { root, input, canvas, quickToPick }: ControlsHost): void {
  const find = <T extends HTMLElement = HTMLElement>(id: string) => byId<T>(root, id);
  const onClick = (id: string, run: () => void) => find(id).addEventListener('click', run);
  const onChange = (id: string, run: (value: string) => void) =>
    find<HTMLSelectElement>(id).addEventListener('change', (event) => run((event.target as HTMLSelectElement).value));

  // a field that has the focus takes the keys as typing (see the keydown listener below); once a
  // file or a sample is chosen, they are the view's again at once: the picker and the menu keep
  // the focus, and a lecturer who opens a file then presses M expects presentation mode (the menu
  // would take M as the first letter of a sample, and open that one)
  const keysToView = () => {
    const focused = root.activeElement;
    if (!(focused instanceof HTMLElement) || !focused.closest(FIELDS)) return;
    focused.blur();
    if (input instanceof HTMLElement) input.focus(); // an embed hears the keys only while focused
  };
  const fileInput = find<HTMLInputElement>('file-input');
  fileInput.addEventListener('change', async () => {
    keysToView();
    await app.opening.openFiles([...(fileInput.files ?? [])]);
    fileInput.value = '';
  });
  onChange('sample-select', (file) => {
    keysToView();
    void app.opening.openSample(file);
  });
  onChange('pick-filter', (filter) => (app.filter = filter as PickFilter));
  onChange('convention', (convention) => app.setConvention(convention as Convention));
  // each command's button: named, with its key in its tooltip, running the command
  for (const command of commands) {
    if (command.button) wireButton(find<HTMLButtonElement>(command.button.id), command, app);
  }
  onClick('help-close', () => app.toggleHelp(false));
  onClick('error-dismiss', () => (find('error-panel').hidden = true));
  for (const tab of tabs) onClick(`tab-${tab}`, () => app.showTab(tab));

  // drop a file anywhere on the page (anywhere on an embed)
  const hint = find('drop-hint');
  const target = input as HTMLElement; // the window hears the same events, of the same types
  target.addEventListener('dragover', (event) => {
    event.preventDefault();
    hint.hidden = false;
  });
  target.addEventListener('dragleave', (event) => {
    const to = event.relatedTarget;
    if (to === null || (target instanceof Node && !target.contains(to as Node))) hint.hidden = true;
  });
  target.addEventListener('drop', async (event) => {
    event.preventDefault();
    hint.hidden = true;
    keysToView();
    await app.opening.openFiles([...(event.dataTransfer?.files ?? [])]);
  });

  // a click picks; a drag orbits, or, just after an extrusion or a bevel, sets how far it goes
  // (heard first, in the capture phase, so that the camera's own controls do not start turning)
  let down: { x: number; y: number } | null = null;
  canvas.addEventListener(
    'pointerdown',
    (event) => {
      down = { x: event.offsetX, y: event.offsetY };
      if (app.adjust.down(event.offsetY)) app.viewer.controls.enabled = false;
    },
    { capture: true },
  );
  canvas.addEventListener('pointerup', (event) => {
    app.adjust.up();
    app.viewer.controls.enabled = true;
    if (down && Math.hypot(event.offsetX - down.x, event.offsetY - down.y) < 5) void app.click(event.offsetX, event.offsetY);
    down = null;
  });
  let hoverPending = false;
  canvas.addEventListener('pointermove', (event) => {
    // a few pixels' wobble is still a click, which keeps the edit as it is
    if (down && event.buttons !== 0 && Math.abs(event.offsetY - down.y) >= 5) app.adjust.move(event.offsetY);
    // no hover preview until picking is quick (a big mesh's hierarchy is still being built)
    if (hoverPending || event.buttons !== 0 || !quickToPick()) return;
    hoverPending = true;
    requestAnimationFrame(async () => {
      app.hover(await app.pickAt(event.offsetX, event.offsetY));
      hoverPending = false;
    });
  });
  canvas.addEventListener('pointerleave', () => app.hover(null));

  target.addEventListener('keydown', (event) => {
    // the element pressed on, inside an embed's shadow root too (where event.target is the embed)
    const origin = event.composedPath()[0];
    if (origin instanceof Element && origin.closest(FIELDS)) return;
    app.adjust.end();
    if (!handleKey(app.commandTarget, event)) return;
    event.preventDefault();
    // a key this view used is not also the slide deck's around it (N is "next slide" in reveal.js)
    event.stopPropagation();
  });
}

/** A command's button: its name and tooltip from the table; a click runs the command (or says why it does not apply). */
function wireButton(button: HTMLButtonElement, command: Command, app: ControlsTarget): void {
  button.setAttribute('aria-label', command.button!.label);
  if (command.keys.length) button.setAttribute('aria-keyshortcuts', command.keys.map(displayKey).join(' '));
  button.title = commandTooltip(command, app.inspection.convention);
  button.addEventListener('click', () => runCommand(app.commandTarget, command));
}
