/**
 * De Berg-style record tables (vertices, faces, halfedges), linked both ways with the 3D view:
 * hovering a row previews the element, clicking selects it, and a selection made elsewhere
 * scrolls its row into view. Only the rows on screen exist in the page (virtual scrolling), so a
 * 100k-face mesh scrolls as smoothly as a cube. Deleted slots (an operation leaves them until the
 * mesh is compacted) are not rows: the tables list the mesh as it is. Each table exports as CSV.
 */
import { type ChangeRecord, type HalfedgeMesh, isLive, type ListedKind, LiveIds, slotCount } from '../../core/index.js';
import { el, replace } from '../dom.js';
import { download } from './export.js';
import { type Convention, round } from '../records.js';
import { type ElementKind, elementName, type Selection } from '../selection.js';

const ROW_HEIGHT = 28;
const OVERSCAN = 8;

interface TableSpec {
  kind: ListedKind;
  title: string;
  /** CSS grid columns. */
  widths: string;
  columns: (convention: Convention) => string[];
  /** Cells of row `id`: strings, or element names that become links. */
  row: (mesh: HalfedgeMesh, id: number, convention: Convention) => Array<string | Selection>;
}

const v = (id: number): Selection | string => (id < 0 ? '—' : { kind: 'vertex', id });
const h = (id: number): Selection | string => (id < 0 ? '—' : { kind: 'halfedge', id });
const f = (id: number): Selection | string => (id < 0 ? '—' : { kind: 'face', id });

export const tableSpecs: TableSpec[] = [
  {
    kind: 'vertex',
    title: 'Vertices',
    widths: 'minmax(0, 1fr) minmax(0, 3fr) minmax(0, 1.2fr)',
    columns: () => ['vertex', 'coordinates', 'incident halfedge'],
    row: (mesh, id) => [elementName({ kind: 'vertex', id }), `(${mesh.position(id).map(round).join(', ')})`, h(mesh.vertexHalfedge(id))] as Array<string | Selection>,
  },
  {
    kind: 'face',
    title: 'Faces',
    widths: 'repeat(3, minmax(0, 1fr))',
    columns: () => ['face', 'halfedge', 'sides'],
    row: (mesh, id) => [elementName({ kind: 'face', id }), h(mesh.faceHalfedge(id)), String(mesh.faceDegree(id))] as Array<string | Selection>,
  },
  {
    kind: 'halfedge',
    title: 'Halfedges',
    widths: 'repeat(7, minmax(0, 1fr))',
    columns: (convention) => ['halfedge', convention, 'twin', 'face', 'next', 'prev', 'edge'],
    row: (mesh, id, convention) =>
      [
        elementName({ kind: 'halfedge', id }),
        v(convention === 'origin' ? mesh.origin(id) : mesh.target(id)),
        h(mesh.twin(id)),
        f(mesh.face(id)),
        h(mesh.next(id)),
        h(mesh.prev(id)),
        `e${id >> 1}`,
      ] as Array<string | Selection>,
  },
];

export class RecordTables {
  private spec = tableSpecs[2];
  private mesh: HalfedgeMesh | null = null;
  private convention: Convention = 'origin';
  private selected: Selection | null = null;
  /** The mesh's `idsVersion` (see `PageSnapshot`): the same number on the same mesh, the same live ids. */
  private idsVersion = -1;
  /** The current table's rows: its kind's live ids (null before a mesh). */
  private ids: LiveIds | null = null;
  /** What `ids` lists: the live ids of this kind, in this mesh, at this `idsVersion`. */
  private listed: { mesh: HalfedgeMesh; idsVersion: number; kind: ElementKind } | null = null;
  private readonly tabs: HTMLButtonElement[];
  private readonly header = el('div', { class: 'table-row table-head', role: 'row' });
  private readonly table = el('div', { class: 'table', role: 'table' });
  private readonly body = el('div', { class: 'table-body', role: 'rowgroup', tabindex: '0', 'aria-label': 'Records' });
  private readonly spacer = el('div', { class: 'table-spacer' });
  private readonly rows = el('div', { class: 'table-rows' });
  private pending = false;

  constructor(
    container: HTMLElement,
    private readonly select: (s: Selection) => void,
    private readonly hover: (s: Selection | null) => void,
  ) {
    this.tabs = tableSpecs.map((spec) =>
      el('button', { type: 'button', role: 'tab', 'data-table': spec.kind, 'aria-label': `${spec.title} table`, onclick: () => this.show(spec.kind) }, spec.title),
    );
    const csv = el('button', { type: 'button', 'aria-label': 'Export this table as CSV', onclick: () => download(new Blob([this.csv()], { type: 'text/csv' }), `${this.spec.kind}-records.csv`) }, 'CSV');
    this.body.append(this.spacer);
    this.spacer.append(this.rows);
    this.body.addEventListener('scroll', () => this.schedule());
    this.body.addEventListener('mouseleave', () => this.hover(null));
    this.table.append(this.header, this.body);
    replace(container, el('div', { class: 'table-tabs', role: 'tablist' }, ...this.tabs, csv), this.table);
  }

  /**
   * Shows `mesh` (of a snapshot whose `idsVersion` is given) in the naming `convention`;
   * `change`: the record that led to it from the snapshot before, if it came as a patch.
   */
  setMesh(mesh: HalfedgeMesh, convention: Convention, idsVersion: number, change: ChangeRecord | null = null): void {
    this.mesh = mesh;
    this.convention = convention;
    this.idsVersion = idsVersion;
    this.listIds(change);
    this.render();
  }

  /** Shows another table, at the selected element's row when it is one of that table's, else at the top. */
  show(kind: ElementKind): void {
    this.switchTo(kind);
    this.scrollToRow(this.selected?.kind === kind ? this.ids?.rowOf(this.selected.id) ?? -1 : 0, 'top');
  }

  /** Marks the selected element's row and scrolls it into view (switching tables if needed). */
  reveal(selection: Selection | null): void {
    this.selected = selection;
    if (selection && selection.kind !== 'edge') {
      if (selection.kind !== this.spec.kind) this.switchTo(selection.kind);
      this.scrollToRow(this.ids?.rowOf(selection.id) ?? -1, 'into view');
    }
    this.render();
  }

  /**
   * Switches tables and sizes the scroll area to the new one before anything scrolls: a scroll
   * position set first would be cut to the old table's length, and show the wrong row.
   */
  private switchTo(kind: ElementKind): void {
    this.spec = tableSpecs.find((s) => s.kind === kind) ?? this.spec;
    this.listIds();
    this.render();
  }

  /**
   * Lists the current table's live ids, unless the list already holds them: listing them takes a
   * pass over the slots (tens of milliseconds on a large mesh with deleted ones), and after a flip,
   * say, they are as they were. After a change that created or deleted some (`change`, which
   * led from the ids listed to these), only the ids it touched are looked at again.
   */
  private listIds(change: ChangeRecord | null = null): void {
    const { mesh, idsVersion, listed } = this;
    const kind = this.spec.kind;
    if (!mesh) return;
    const same = listed?.mesh === mesh && listed.kind === kind;
    if (same && listed.idsVersion === idsVersion) return;
    this.ids = same && change && this.ids && listed.idsVersion === idsVersion - 1 ? this.ids.after(mesh, kind, change) : LiveIds.of(mesh, kind);
    this.listed = { mesh, idsVersion, kind };
  }

  /** Scrolls row `row` to the top, or into view (to the middle, only when it is out of sight). */
  private scrollToRow(row: number, where: 'top' | 'into view'): void {
    if (row < 0) return;
    const top = row * ROW_HEIGHT;
    if (where === 'top') this.body.scrollTop = top;
    else if (top < this.body.scrollTop || top + ROW_HEIGHT > this.body.scrollTop + this.body.clientHeight) {
      this.body.scrollTop = Math.max(0, top - this.body.clientHeight / 2);
    }
    this.render();
  }

  /** CSV of the current table (every row, deleted ones left out). */
  csv(): string {
    const mesh = this.mesh;
    if (!mesh) return '';
    const lines = [this.spec.columns(this.convention).join(',')];
    for (let id = 0, slots = slotCount(mesh, this.spec.kind); id < slots; id++) {
      if (!isLive(mesh, this.spec.kind, id)) continue;
      lines.push(this.spec.row(mesh, id, this.convention).map((cell) => (typeof cell === 'string' ? `"${cell}"` : elementName(cell))).join(','));
    }
    return lines.join('\n') + '\n';
  }

  /** Element names of the rows in the page now (for tests of the virtual scrolling). */
  renderedRows(): string[] {
    return [...this.rows.children].map((row) => (row as HTMLElement).dataset.element ?? '');
  }

  private schedule(): void {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.render();
    });
  }

  private render(): void {
    for (const tab of this.tabs) tab.setAttribute('aria-selected', String(tab.dataset.table === this.spec.kind));
    this.table.style.setProperty('--columns', this.spec.widths);
    replace(this.header, ...this.spec.columns(this.convention).map((c) => el('span', { role: 'columnheader' }, c)));
    const mesh = this.mesh;
    if (!mesh) return;
    const ids = this.ids;
    const count = ids?.count ?? 0;
    this.spacer.style.height = `${count * ROW_HEIGHT}px`;
    const first = Math.max(0, Math.floor(this.body.scrollTop / ROW_HEIGHT) - OVERSCAN);
    const last = Math.min(count, Math.ceil((this.body.scrollTop + (this.body.clientHeight || 400)) / ROW_HEIGHT) + OVERSCAN);
    this.rows.style.transform = `translateY(${first * ROW_HEIGHT}px)`;
    const rows: HTMLElement[] = [];
    for (let row = first; row < last; row++) {
      const id = ids!.idAt(row);
      const self: Selection = { kind: this.spec.kind, id };
      const isSelected = this.selected?.kind === self.kind && this.selected.id === id;
      const cells = this.spec.row(mesh, id, this.convention).map((cell) =>
            el(
              'span',
              { role: 'cell' },
              typeof cell === 'string'
                ? cell
                : el('button', { type: 'button', class: 'link', tabindex: '-1', onclick: (event: Event) => (event.stopPropagation(), this.select(cell)) }, elementName(cell)),
            ),
          );
      rows.push(
        el(
          'div',
          {
            class: `table-row${isSelected ? ' selected' : ''}`,
            role: 'row',
            'data-element': elementName(self),
            'aria-selected': String(isSelected),
            onclick: () => this.select(self),
            onmouseenter: () => this.hover(self),
          },
          ...cells,
        ),
      );
    }
    replace(this.rows, ...rows);
  }
}
