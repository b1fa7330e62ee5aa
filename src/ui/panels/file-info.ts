/**
 * What the file said and what the builder had to repair. Each repair lists its incidents; an
 * incident selects the element concerned, so a student sees *where* the mesh is non-manifold.
 * All of it is file text or built from it, and goes in as text only.
 */
import type { BuildReport, RepairIncident, RepairKind } from '../../core/index.js';
import type { FileInfo } from '../../workers/protocol.js';
import { capitalized, el, replace } from '../dom.js';
import type { Selection } from '../selection.js';

/** What the File tab can do in the view: show a repair's incident, show or hide the seams. */
export interface FileInfoActions {
  showProblem: (incident: RepairIncident, kind: RepairKind, first: Selection) => void;
  toggleSeams: () => void;
  seamsShown: boolean;
  /** Opens the file again welding within a distance; null when the page does not have the file (a sample, a link). */
  reopen: ((weldTolerance: number) => void) | null;
}

export function renderFileInfo(container: HTMLElement, file: FileInfo | null, report: BuildReport | null, actions: FileInfoActions): void {
  if (!file) {
    replace(container, el('p', { class: 'note' }, 'No file yet.'));
    return;
  }
  const facts = el(
    'p',
    {},
    el('strong', {}, file.name),
    ` — ${formatName(file)}, ${file.counts.vertices} vertices and ${file.counts.faces} faces in the file`,
  );
  const seams =
    file.seams === null
      ? null
      : el(
          'p',
          { class: 'seams' },
          `${file.seams} seam edge${file.seams === 1 ? '' : 's'}: where the file split its vertices along texture coordinates or normals. Welded, each corner keeps its own values. `,
          file.seams > 0
            ? el('button', { type: 'button', 'aria-pressed': String(actions.seamsShown), onclick: actions.toggleSeams }, actions.seamsShown ? 'Hide the seams' : 'Show the seams')
            : null,
        );
  const weld = file.format === 'stl' || file.format === 'gltf' ? weldControl(file, actions.reopen) : null;
  const list = (title: string, lines: string[]) =>
    lines.length ? el('details', {}, el('summary', {}, `${title} (${lines.length})`), el('ul', {}, ...lines.map((line) => el('li', {}, line)))) : null;
  const repairs = report?.repairs.length
    ? el(
        'div',
        { class: 'repairs', 'aria-label': 'Repairs made while building' },
        el('h3', {}, 'Repairs'),
        ...report.repairs.map((repair) =>
          el(
            'details',
            { 'data-repair': repair.kind },
            el('summary', {}, repair.message),
            el(
              'ul',
              {},
              ...repair.incidents.slice(0, 200).map((incident) => {
                const target = incidentTarget(incident);
                return el(
                  'li',
                  {},
                  target
                    ? el(
                        'button',
                        { type: 'button', class: 'link', 'aria-label': `Show: ${incident.message}`, onclick: () => actions.showProblem(incident, repair.kind, target) },
                        incident.message,
                      )
                    : incident.message,
                );
              }),
              repair.count > 200 ? el('li', {}, `… ${repair.count - 200} more`) : null,
            ),
          ),
        ),
      )
    : el('p', { class: 'note' }, 'No repairs were needed: the file holds a clean, oriented, manifold mesh.');
  replace(container, facts, seams, weld, list('Notes', file.notes), list('Comments in the file', file.comments), repairs);
}

/**
 * How near the file's vertices had to be to weld, and for a file of the user's, a distance to open
 * it again with (a file written in float32, or by a sloppy exporter, has corners a hair apart).
 */
function weldControl({ notes, weldTolerance: tolerance }: FileInfo, reopen: FileInfoActions['reopen']): HTMLElement {
  // the reader's own count ("welded 177 glTF vertices into 122 (55 joined …)"), else what was joined
  const note = notes.find((line) => line.startsWith('welded '));
  const said = note
    ? `${capitalized(note)}.`
    : tolerance > 0
      ? `Vertices within ${tolerance} of each other were welded.`
      : 'Vertices at exactly equal positions were welded.';
  if (!reopen) return el('p', { class: 'note' }, said);
  const input = el('input', { type: 'number', min: 0, step: 'any', value: tolerance, 'aria-label': 'Weld distance', class: 'weld-distance' });
  const go = () => reopen(input.value.trim() === '' ? Number.NaN : Number(input.value));
  input.addEventListener('keydown', (event) => void ((event as KeyboardEvent).key === 'Enter' && go()));
  return el(
    'p',
    { class: 'weld' },
    `${said} `,
    el('label', {}, 'Weld within ', input),
    ' ',
    el('button', { type: 'button', 'aria-label': 'Open again, welding within this distance', onclick: go }, 'Reopen'),
  );
}

/** The element a repair incident is shown at: its last vertex (a copy the repair made), else face or halfedge. */
export function incidentTarget(incident: { vertices?: number[]; faces?: number[]; halfedges?: number[] }): Selection | null {
  if (incident.vertices?.length) return { kind: 'vertex', id: incident.vertices.at(-1)! };
  if (incident.faces?.length) return { kind: 'face', id: incident.faces.at(-1)! };
  if (incident.halfedges?.length) return { kind: 'halfedge', id: incident.halfedges[0] };
  return null;
}

/** `PLY binary little endian`, `OFF ascii`, `glTF binary (.glb)`. */
function formatName({ format, encoding }: { format: string; encoding: string }): string {
  if (format === 'gltf') return encoding === 'ascii' ? 'glTF (JSON)' : 'glTF binary (.glb)';
  return `${format.toUpperCase()} ${encoding.replaceAll('_', ' ')}`;
}
