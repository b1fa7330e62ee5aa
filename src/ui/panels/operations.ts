/**
 * The operations a student can run: subdivision schemes, the plane cut, smoothing, decimation,
 * remeshing, and the local edits on the selection. Each button is disabled, with the reason as
 * its tooltip, when it does not apply (Loop on a quad mesh; a flip on a boundary edge). The reasons come from the core's own
 * predicates, asked here on the page's copy of the mesh.
 */
import type { HalfedgeMesh, SubdivisionScheme } from '../../core/index.js';
import type { CheckedOperation } from '../../workers/protocol.js';
import { cannotEdit, cannotStart, editButtons, type EditRequest, type OperationRequest } from '../../workers/operations.js';
import { el, replace } from '../dom.js';
import type { Selection } from '../selection.js';

export interface OperationActions {
  start(request: OperationRequest): void;
  edit(request: EditRequest): void;
  /** Says a sentence in the status line (what a two-step edit waits for). */
  say(message: string): void;
  /** Shows or hides the plane gizmo; called with the plane typed in the form. */
  showPlane(plane: [number, number, number, number] | null): void;
  /** Whether dragging the gizmo moves or turns the plane. */
  setPlaneMode(mode: 'translate' | 'rotate'): void;
}

const schemes: Array<{ scheme: SubdivisionScheme; label: string }> = [
  { scheme: 'loop', label: 'Loop' },
  { scheme: 'catmull-clark', label: 'Catmull-Clark' },
  { scheme: 'butterfly', label: 'Butterfly' },
  { scheme: 'sqrt3', label: '√3' },
  { scheme: 'linear', label: 'Linear' },
];


/** The vertex a selection names (a vertex, or the origin of a halfedge), or -1. */
function selectedVertex(mesh: HalfedgeMesh, s: Selection | null): number {
  return s?.kind === 'vertex' ? s.id : s?.kind === 'halfedge' ? mesh.origin(s.id) : -1;
}

/** The edge a selection names (an edge, or a halfedge's edge), or -1. */
function selectedEdge(s: Selection | null): number {
  return s?.kind === 'edge' ? s.id : s?.kind === 'halfedge' ? s.id >> 1 : -1;
}

/** A weld's first edge, as a request whose second edge is still to come; or why this edge cannot be one. */
function weldStart(mesh: HalfedgeMesh, edge: number): EditRequest | string {
  if (edge >= mesh.edgeSlots || mesh.eDeleted[edge]) return `e${edge} is not an edge of this mesh`;
  const onBoundary = mesh.heFace[2 * edge] === -1 || mesh.heFace[2 * edge + 1] === -1;
  return onBoundary ? { kind: 'weld-edges', edges: [edge, -1] } : `e${edge} is not on the boundary: a weld joins two boundary edges`;
}

/** The face a selection names (a face, or a halfedge's face), or -1. */
function selectedFace(mesh: HalfedgeMesh, s: Selection | null): number {
  return s?.kind === 'face' ? s.id : s?.kind === 'halfedge' ? mesh.face(s.id) : -1;
}

export class OperationsPanel {
  private readonly schemeButtons: HTMLButtonElement[];
  private readonly editButtons: HTMLButtonElement[];
  private readonly plane = [0, 1, 0, 0].map((value, i) =>
    el('input', { type: 'number', step: 'any', value: String(value), 'aria-label': `Plane coefficient ${'abcd'[i]}`, class: 'plane-input' }),
  );
  private readonly keep = el(
    'select',
    { 'aria-label': 'Which side to keep' },
    el('option', { value: 'both' }, 'keep both'),
    el('option', { value: 'above' }, 'keep above'),
    el('option', { value: 'below' }, 'keep below'),
  );
  private readonly cap = el('input', { type: 'checkbox', checked: true, 'aria-label': 'Cap the cut' });
  private readonly gizmoButton: HTMLButtonElement;
  private readonly rotateButton: HTMLButtonElement;
  private readonly cutButton: HTMLButtonElement;
  private readonly smoothMethod = el(
    'select',
    { 'aria-label': 'Smoothing method' },
    el('option', { value: 'taubin' }, 'Taubin λ|μ'),
    el('option', { value: 'laplacian' }, 'Laplacian (uniform)'),
    el('option', { value: 'cotan' }, 'Laplacian (cotangent)'),
  );
  private readonly iterations = el('input', { type: 'number', min: '1', step: '1', value: '10', 'aria-label': 'Smoothing iterations', class: 'small-input' });
  private readonly lambda = el('input', { type: 'number', step: 'any', value: '0.5', 'aria-label': 'Shrink step λ', class: 'small-input' });
  private readonly mu = el('input', { type: 'number', step: 'any', value: '-0.53', 'aria-label': 'Inflate step μ', class: 'small-input' });
  private readonly boundary = el(
    'select',
    { 'aria-label': 'Boundary vertices' },
    el('option', { value: 'fixed' }, 'boundary fixed'),
    el('option', { value: 'smooth' }, 'boundary smoothed'),
  );
  private readonly smoothButton: HTMLButtonElement;
  private readonly targetFaces = el('input', { type: 'number', min: '0', step: '1', 'aria-label': 'Faces to keep', class: 'small-input' });
  private readonly decimateButton: HTMLButtonElement;
  private readonly targetLength = el('input', { type: 'number', min: '0', step: 'any', placeholder: 'mean', 'aria-label': 'Target edge length (empty: the mean edge length)', class: 'small-input' });
  private readonly remeshIterations = el('input', { type: 'number', min: '0', step: '1', value: '3', 'aria-label': 'Remeshing iterations', class: 'small-input' });
  private readonly remeshButton: HTMLButtonElement;
  private unavailable: Record<CheckedOperation, string | null> | null = null;
  private readonly splitFrom = el('select', { 'aria-label': 'Split face from vertex' });
  private readonly splitTo = el('select', { 'aria-label': 'Split face to vertex' });
  private readonly splitButton: HTMLButtonElement;
  private mesh: HalfedgeMesh | null = null;
  private selection: Selection | null = null;
  private gizmoShown = false;
  /** The first edge of a weld, chosen and waiting for the second (null: none). */
  private weldFirst: number | null = null;

  constructor(
    container: HTMLElement,
    private readonly actions: OperationActions,
  ) {
    this.schemeButtons = schemes.map(({ scheme, label }) =>
      el('button', { type: 'button', 'data-operation': scheme, onclick: whenAvailable(() => actions.start({ kind: 'subdivide', scheme })) }, label),
    );
    this.editButtons = editButtons.map(({ kind, label }) =>
      el('button', { type: 'button', 'data-edit': kind, onclick: whenAvailable(() => this.runEdit(kind)) }, label),
    );
    this.gizmoButton = el('button', { type: 'button', 'aria-pressed': 'false', onclick: () => this.toggleGizmo() }, 'Show plane');
    this.rotateButton = el(
      'button',
      {
        type: 'button',
        'aria-pressed': 'false',
        title: 'Drag the gizmo to turn the plane instead of moving it',
        onclick: () => {
          const rotate = this.rotateButton.getAttribute('aria-pressed') !== 'true';
          this.rotateButton.setAttribute('aria-pressed', String(rotate));
          actions.setPlaneMode(rotate ? 'rotate' : 'translate');
        },
      },
      'Turn plane',
    );
    this.cutButton = el('button', { type: 'button', 'data-operation': 'cut', onclick: whenAvailable(() => actions.start(this.cutRequest())) }, 'Cut');
    this.splitButton = el('button', { type: 'button', 'data-edit': 'split-face', onclick: whenAvailable(() => this.runSplitFace()) }, 'Split face');
    this.smoothButton = el('button', { type: 'button', 'data-operation': 'smooth', onclick: whenAvailable(() => actions.start(this.smoothRequest())) }, 'Smooth');
    this.decimateButton = el('button', { type: 'button', 'data-operation': 'decimate', onclick: whenAvailable(() => actions.start(this.decimateRequest())) }, 'Decimate');
    this.remeshButton = el('button', { type: 'button', 'data-operation': 'remesh', onclick: whenAvailable(() => actions.start(this.remeshRequest())) }, 'Remesh');
    this.smoothMethod.addEventListener('change', () => this.updateChecked());
    this.targetFaces.addEventListener('input', () => this.updateChecked());
    for (const input of [this.targetLength, this.remeshIterations]) input.addEventListener('input', () => this.updateChecked());
    for (const input of this.plane) input.addEventListener('change', () => this.gizmoShown && actions.showPlane(this.planeValues()));
    for (const select of [this.splitFrom, this.splitTo]) select.addEventListener('change', () => this.updateSplitFace());
    replace(
      container,
      el('h3', {}, 'Subdivide'),
      el('div', { class: 'button-row' }, ...this.schemeButtons),
      el('h3', {}, 'Plane cut: a·x + b·y + c·z + d = 0'),
      el('div', { class: 'plane-row' }, ...this.plane.flatMap((input, i) => [el('span', {}, ['a', 'b', 'c', 'd'][i] + ' '), input])),
      el('div', { class: 'button-row' }, this.keep, el('label', {}, this.cap, ' cap'), this.gizmoButton, this.rotateButton, this.cutButton),
      el('h3', {}, 'Smooth'),
      el('div', { class: 'button-row' }, this.smoothMethod, this.boundary),
      el('div', { class: 'button-row' }, el('label', {}, 'iterations ', this.iterations), el('label', {}, 'λ ', this.lambda), el('label', {}, 'μ ', this.mu), this.smoothButton),
      el('h3', {}, 'Decimate (quadric error)'),
      el('div', { class: 'button-row' }, el('label', {}, 'keep ', this.targetFaces, ' faces'), this.decimateButton),
      el('h3', {}, 'Remesh (isotropic)'),
      el('div', { class: 'button-row' }, el('label', {}, 'edge length ', this.targetLength), el('label', {}, 'iterations ', this.remeshIterations), this.remeshButton),
      el('h3', {}, 'Edit the selection'),
      el('div', { class: 'button-row' }, ...this.editButtons),
      el('div', { class: 'button-row' }, 'from ', this.splitFrom, ' to ', this.splitTo, this.splitButton),
    );
  }

  /** The plane as typed. */
  planeValues(): [number, number, number, number] {
    return this.plane.map((input) => Number(input.value)) as [number, number, number, number];
  }

  /** Fills the form with a plane (the gizmo moved). */
  setPlane(plane: [number, number, number, number]): void {
    plane.forEach((value, i) => (this.plane[i].value = String(+value.toPrecision(6))));
  }

  /** `unavailable` comes with the snapshot (checking every face is the worker's job). */
  update(mesh: HalfedgeMesh, selection: Selection | null, unavailable: Record<CheckedOperation, string | null>): void {
    const newMesh = mesh !== this.mesh;
    this.mesh = mesh;
    this.selection = selection;
    this.unavailable = unavailable;
    if (newMesh) this.targetFaces.value = String(Math.max(4, Math.floor(mesh.nFaces / 2)));
    // a weld's first edge belongs to the mesh it was chosen on
    if (this.weldFirst !== null && (this.weldFirst >= mesh.edgeSlots || mesh.eDeleted[this.weldFirst])) this.weldFirst = null;
    schemes.forEach(({ scheme, label }, i) => setAvailability(this.schemeButtons[i], `Start ${label} subdivision`, unavailable[scheme]));
    setAvailability(this.cutButton, 'Start the plane cut', cannotStart(mesh, this.cutRequest()));
    this.updateChecked();
    editButtons.forEach(({ kind, label }, i) =>
      setAvailability(this.editButtons[i], kind === 'weld-edges' && this.weldFirst !== null ? `Weld e${this.weldFirst} to the selected edge` : label, this.reasonAgainst(kind)),
    );
    this.updateSplitFace();
  }

  private smoothRequest(): OperationRequest {
    return {
      kind: 'smooth',
      options: {
        method: this.smoothMethod.value as 'taubin' | 'laplacian' | 'cotan',
        iterations: Number(this.iterations.value),
        lambda: Number(this.lambda.value),
        mu: Number(this.mu.value),
        boundary: this.boundary.value as 'fixed' | 'smooth',
      },
    };
  }

  private decimateRequest(): OperationRequest {
    return { kind: 'decimate', options: { targetFaces: Number(this.targetFaces.value) } };
  }

  /** Remeshing to the length typed (none: the mean edge length), in the iterations typed. */
  private remeshRequest(): OperationRequest {
    const length = this.targetLength.value.trim();
    return { kind: 'remesh', options: { ...(length === '' ? {} : { targetEdgeLength: Number(length) }), iterations: Number(this.remeshIterations.value) } };
  }

  /** The smoothing, decimation and remeshing buttons: the worker's face checks, then the form's numbers. */
  private updateChecked(): void {
    const mesh = this.mesh;
    const unavailable = this.unavailable;
    if (!mesh || !unavailable) return;
    const noFaces = mesh.nFaces === 0 ? 'there are no faces' : null;
    const cotan = this.smoothMethod.value === 'cotan' ? unavailable.cotan : null;
    setAvailability(this.smoothButton, 'Start smoothing', noFaces ?? cotan);
    const target = Number(this.targetFaces.value);
    const badTarget = !Number.isInteger(target) || target < 0 ? 'the number of faces to keep must be a whole number ≥ 0' : target >= mesh.nFaces ? `the mesh has only ${mesh.nFaces} faces` : null;
    setAvailability(this.decimateButton, 'Start decimation', noFaces ?? unavailable.decimate ?? badTarget);
    const length = this.targetLength.value.trim();
    const iterations = Number(this.remeshIterations.value);
    const badRemesh =
      length !== '' && !(Number(length) > 0 && Number(length) < Infinity)
        ? 'the edge length must be a number > 0 (or empty, for the mean edge length)'
        : !Number.isInteger(iterations) || iterations < 1
          ? 'the number of iterations must be a whole number ≥ 1'
          : null;
    setAvailability(this.remeshButton, 'Start remeshing', noFaces ?? unavailable.remesh ?? badRemesh);
  }

  private cutRequest(): OperationRequest {
    return { kind: 'cut', plane: this.planeValues(), keep: this.keep.value as 'both' | 'above' | 'below', cap: this.cap.checked };
  }

  private request(kind: (typeof editButtons)[number]['kind']): EditRequest | string {
    const mesh = this.mesh!;
    const need = editButtons.find((e) => e.kind === kind)!.needs;
    if (need === 'mesh') return { kind: 'triangulate-mesh' };
    if (need === 'edge' || need === 'two edges') {
      const edge = selectedEdge(this.selection);
      if (need === 'edge' || this.weldFirst === null) return edge < 0 ? 'select an edge or a halfedge first' : need === 'edge' ? ({ kind, edge } as EditRequest) : weldStart(mesh, edge);
      if (edge < 0 || edge === this.weldFirst) return `select the boundary edge to weld e${this.weldFirst} to`;
      return { kind: 'weld-edges', edges: [this.weldFirst, edge] };
    }
    if (need === 'vertex') {
      const vertex = selectedVertex(mesh, this.selection);
      return vertex < 0 ? 'select a vertex or a halfedge from it first' : ({ kind, vertex } as EditRequest);
    }
    const face = selectedFace(mesh, this.selection);
    return face < 0 ? 'select a face or a halfedge inside one first' : ({ kind, face } as EditRequest);
  }

  private reasonAgainst(kind: (typeof editButtons)[number]['kind']): string | null {
    const request = this.request(kind);
    if (typeof request === 'string') return request;
    // the first edge of a weld only has to be on the boundary: the second decides the rest
    return request.kind === 'weld-edges' && this.weldFirst === null ? null : cannotEdit(this.mesh!, request);
  }

  private runEdit(kind: (typeof editButtons)[number]['kind']): void {
    const request = this.request(kind);
    if (typeof request === 'string') return;
    if (request.kind === 'weld-edges' && this.weldFirst === null) {
      this.weldFirst = request.edges[0];
      this.actions.say(`Weld: e${this.weldFirst} is the first edge. Select the boundary edge to weld it to, then Weld edges again.`);
      this.update(this.mesh!, this.selection, this.unavailable!);
      return;
    }
    if (request.kind === 'weld-edges') this.weldFirst = null;
    this.actions.edit(request);
  }

  private updateSplitFace(): void {
    const mesh = this.mesh!;
    const face = selectedFace(mesh, this.selection);
    const corners: number[] = [];
    if (face >= 0) {
      let h = mesh.faceHalfedge(face);
      do {
        corners.push(mesh.origin(h));
        h = mesh.next(h);
      } while (h !== mesh.faceHalfedge(face));
    }
    const keep = [this.splitFrom.value, this.splitTo.value];
    for (const [i, select] of [this.splitFrom, this.splitTo].entries()) {
      replace(select, ...corners.map((v) => el('option', { value: String(v) }, `v${v}`)));
      if (corners.map(String).includes(keep[i])) select.value = keep[i];
      else if (corners.length > 2) select.value = String(corners[i === 0 ? 0 : 2]);
    }
    const reason =
      face < 0
        ? 'select a face or a halfedge inside one first'
        : cannotEdit(mesh, { kind: 'split-face', face, from: Number(this.splitFrom.value), to: Number(this.splitTo.value) });
    setAvailability(this.splitButton, 'Split the face between the two vertices', reason);
  }

  private runSplitFace(): void {
    const face = selectedFace(this.mesh!, this.selection);
    if (face >= 0) this.actions.edit({ kind: 'split-face', face, from: Number(this.splitFrom.value), to: Number(this.splitTo.value) });
  }

  /** Hides the plane gizmo and unpresses its button (an operation ended: see App.show). */
  hidePlane(): void {
    this.gizmoShown = false;
    this.gizmoButton.setAttribute('aria-pressed', 'false');
    this.actions.showPlane(null);
  }

  private toggleGizmo(): void {
    this.gizmoShown = !this.gizmoShown;
    this.gizmoButton.setAttribute('aria-pressed', String(this.gizmoShown));
    this.actions.showPlane(this.gizmoShown ? this.planeValues() : null);
  }
}

/**
 * Marks a button available, or not with the reason as its tooltip and in its accessible name.
 * `aria-disabled` rather than `disabled`: a disabled button gets no hover, so no tooltip, and
 * cannot be focused to hear why. `tip`: the tooltip while available (the label unless given).
 */
export function setAvailability(button: HTMLButtonElement, label: string, reason: string | null, tip = label): void {
  button.setAttribute('aria-disabled', String(reason !== null));
  button.title = reason ?? tip;
  button.setAttribute('aria-label', reason ? `${label} (not available: ${reason})` : label);
}

/** A click handler that does nothing on a button marked unavailable. */
export function whenAvailable(action: () => void): (event: Event) => void {
  return (event) => {
    if ((event.currentTarget as HTMLElement).getAttribute('aria-disabled') !== 'true') action();
  };
}
