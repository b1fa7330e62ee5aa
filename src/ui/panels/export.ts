/**
 * Export: the current mesh (PLY ascii or binary, OFF, OBJ, written in the worker), the halfedge
 * tables as JSON (every record and pointer), and a PNG of the view. Files are made in the browser
 * and handed to the user as downloads: nothing leaves the machine.
 */
import { el, replace } from '../dom.js';

export interface ExportActions {
  meshBytes(format: string): Promise<Uint8Array>;
  tablesJson(): string;
  png(): Promise<Blob>;
  /** Base of the file names (the open file's name without its extension). */
  baseName(): string;
}

const meshFormats: Array<{ format: string; label: string; extension: string }> = [
  { format: 'ply', label: 'PLY (text)', extension: 'ply' },
  { format: 'ply-binary', label: 'PLY (binary)', extension: 'ply' },
  { format: 'off', label: 'OFF', extension: 'off' },
  { format: 'obj', label: 'OBJ', extension: 'obj' },
  { format: 'glb', label: 'glTF (.glb)', extension: 'glb' },
];

export function renderExport(container: HTMLElement, actions: ExportActions): void {
  const meshButtons = meshFormats.map(({ format, label, extension }) =>
    el(
      'button',
      {
        type: 'button',
        'aria-label': `Export the mesh as ${label}`,
        onclick: async () => download(new Blob([(await actions.meshBytes(format)) as Uint8Array<ArrayBuffer>]), `${actions.baseName()}-edited.${extension}`),
      },
      label,
    ),
  );
  replace(
    container,
    el('div', { class: 'button-row' }, ...meshButtons),
    el(
      'div',
      { class: 'button-row' },
      el(
        'button',
        { type: 'button', 'aria-label': 'Export the halfedge tables as JSON', onclick: () => download(new Blob([actions.tablesJson()], { type: 'application/json' }), `${actions.baseName()}-halfedges.json`) },
        'Tables (JSON)',
      ),
      el('button', { type: 'button', 'aria-label': 'Export a PNG of the view', onclick: async () => download(await actions.png(), `${actions.baseName()}.png`) }, 'Picture (PNG)'),
    ),
  );
}

export function download(blob: Blob, name: string): void {
  const url = URL.createObjectURL(blob);
  el('a', { href: url, download: name }).click();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
