/**
 * Export: the current mesh (PLY ascii or binary, OFF, OBJ, glTF, written in the worker), the
 * halfedge tables as JSON (every record and pointer), and a PNG of the view. Files are made in the
 * browser and handed to the user as downloads: nothing leaves the machine. Every format but glTF
 * keeps the faces as they are; glTF holds only triangles, which the panel says before saving.
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

/**
 * Draws the panel; the function it returns takes the mesh's face degrees (`MeshStats.faceDegrees`)
 * and says what a glTF export would make of its polygons.
 */
export function renderExport(container: HTMLElement, actions: ExportActions): (faceDegrees: Record<number, number>) => void {
  const gltfNote = el('p', { id: 'gltf-note', class: 'note' });
  const meshButtons = meshFormats.map(({ format, label, extension }) =>
    el(
      'button',
      {
        type: 'button',
        'aria-label': `Export the mesh as ${label}`,
        'aria-describedby': format === 'glb' ? 'gltf-note' : undefined,
        onclick: async () => download(new Blob([(await actions.meshBytes(format)) as Uint8Array<ArrayBuffer>]), `${actions.baseName()}-edited.${extension}`),
      },
      label,
    ),
  );
  replace(
    container,
    el('div', { class: 'button-row' }, ...meshButtons),
    gltfNote,
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
  return (faceDegrees) => {
    const sentence = gltfTriangulation(faceDegrees);
    gltfNote.textContent = sentence ?? '';
    gltfNote.hidden = sentence === null;
  };
}

/**
 * What a glTF export does to the faces that are not triangles (each of n sides becomes n − 2
 * triangles), e.g. "the 128 quads become 256 triangles"; null when every face is a triangle.
 */
export function gltfTriangulation(faceDegrees: Record<number, number>): string | null {
  let polygons = 0;
  let triangles = 0;
  let quadsOnly = true;
  for (const [degree, count] of Object.entries(faceDegrees)) {
    const sides = Number(degree);
    if (sides <= 3 || count === 0) continue;
    polygons += count;
    triangles += count * (sides - 2);
    quadsOnly &&= sides === 4;
  }
  if (polygons === 0) return null;
  const faces = polygons === 1 ? `the ${quadsOnly ? 'quad' : 'polygon'} becomes` : `the ${polygons} ${quadsOnly ? 'quads' : 'polygons'} become`;
  return `glTF holds only triangles: ${faces} ${triangles} triangles. The other formats keep the faces as they are.`;
}

export function download(blob: Blob, name: string): void {
  const url = URL.createObjectURL(blob);
  el('a', { href: url, download: name }).click();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
