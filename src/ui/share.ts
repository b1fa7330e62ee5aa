/**
 * A link that restores what a lecturer shows: the sample model, the operations and edits that led
 * from it to the mesh on screen (replayed on opening), the selection and the camera.
 * `?model=torus.off&ops=[…]&select=h17&naming=target&camera=…&mode=top`. Uploaded files never leave the
 * browser, so a link can only name a sample model.
 */
import type { EditRequest, OperationRequest, Snapshot } from '../workers/protocol.js';
import type { Convention } from './records.js';
import { parseElementName, type Selection } from './selection.js';

/** One step from the sample to what is on screen: an operation run to its end, or a local edit. */
export type ReplayStep = { kind: 'operation'; request: OperationRequest } | { kind: 'edit'; request: EditRequest };

export interface ViewState {
  model: string | null;
  /** The steps from the model to the mesh shown, in order. */
  steps: ReplayStep[];
  selection: Selection | null;
  /** The halfedge naming the view speaks (origin or target); null: the page's default. */
  naming: Convention | null;
  /**
   * Camera position, orbit target, zoom (orthographic), and where the target is drawn: its shift
   * from the middle of the view as a share of the width and height (see `Viewer.frame`).
   */
  camera: { position: number[]; target: number[]; zoom: number; shift: [number, number] } | null;
  mode: 'perspective' | 'top' | null;
}

export function encodeViewState(state: ViewState): string {
  const params = new URLSearchParams();
  if (state.model) params.set('model', state.model);
  if (state.steps.length > 0) params.set('ops', JSON.stringify(state.steps));
  if (state.selection) params.set('select', `${{ vertex: 'v', edge: 'e', face: 'f', halfedge: 'h' }[state.selection.kind]}${state.selection.id}`);
  if (state.naming) params.set('naming', state.naming);
  if (state.camera) {
    const numbers = [...state.camera.position, ...state.camera.target, state.camera.zoom, ...state.camera.shift].map((x) => +x.toPrecision(6));
    params.set('camera', numbers.join(','));
  }
  if (state.mode) params.set('mode', state.mode);
  return params.toString();
}

/** Reads a query string; anything malformed is left out rather than trusted. */
export function decodeViewState(query: string): ViewState {
  const params = new URLSearchParams(query);
  const numbers = (params.get('camera') ?? '').split(',').map(Number);
  // a link made before the shift was kept has seven numbers: its target was in the middle
  const camera =
    (numbers.length === 7 || numbers.length === 9) && numbers.every(Number.isFinite)
      ? {
          position: numbers.slice(0, 3),
          target: numbers.slice(3, 6),
          zoom: numbers[6] > 0 ? numbers[6] : 1,
          shift: [Math.max(-0.5, Math.min(0.5, numbers[7] ?? 0)), Math.max(-0.5, Math.min(0.5, numbers[8] ?? 0))] as [number, number],
        }
      : null;
  const mode = params.get('mode');
  const naming = params.get('naming');
  return {
    model: params.get('model'),
    steps: replaySteps(params.get('ops')),
    selection: parseElementName(params.get('select') ?? ''),
    naming: naming === 'origin' || naming === 'target' ? naming : null,
    camera,
    mode: mode === 'top' || mode === 'perspective' ? mode : null,
  };
}

/**
 * The steps of a link, each an operation or an edit with a request object; anything else makes
 * the whole list untrusted and left out (the session checks each request again as it runs it).
 */
function replaySteps(text: string | null): ReplayStep[] {
  if (!text) return [];
  try {
    const steps: unknown = JSON.parse(text);
    const isStep = (step: unknown): step is ReplayStep =>
      typeof step === 'object' &&
      step !== null &&
      ((step as ReplayStep).kind === 'operation' || (step as ReplayStep).kind === 'edit') &&
      typeof (step as ReplayStep).request === 'object' &&
      (step as ReplayStep).request !== null;
    return Array.isArray(steps) && steps.length <= 100 && steps.every(isStep) ? steps : [];
  } catch {
    return [];
  }
}

/** The history entry that opened the model the current mesh came from, or null. */
export function openedEntry(snapshot: Pick<Snapshot, 'history'>): { name: string; sample: string | null; index: number } | null {
  const { items, index } = snapshot.history;
  for (let i = index; i >= 0; i--) {
    const source = items[i]!.source;
    if (source.kind === 'open') return { name: source.name, sample: source.sample, index: i };
  }
  return null;
}

/** The sample and the steps since it that lead to the current mesh; no model when a link cannot say. */
export function replayable(snapshot: Pick<Snapshot, 'history'>): { model: string | null; steps: ReplayStep[] } {
  const open = openedEntry(snapshot);
  if (!open?.sample) return { model: null, steps: [] };
  const steps: ReplayStep[] = [];
  for (const { source } of snapshot.history.items.slice(open.index + 1, snapshot.history.index + 1)) {
    if (source.kind === 'operation' || source.kind === 'edit') steps.push(source);
    else return { model: null, steps: [] };
  }
  return { model: open.sample, steps };
}
