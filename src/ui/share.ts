/**
 * A link that restores what a lecturer shows: the sample model, the selection and the camera.
 * `?model=torus.off&select=h17&camera=…&mode=top`. Uploaded files never leave the browser, so a
 * link can only name a sample model.
 */
import { parseElementName, type Selection } from './selection.js';

export interface ViewState {
  model: string | null;
  selection: Selection | null;
  /** Camera position, orbit target, zoom (orthographic). */
  camera: { position: number[]; target: number[]; zoom: number } | null;
  mode: 'perspective' | 'top' | null;
}

export function encodeViewState(state: ViewState): string {
  const params = new URLSearchParams();
  if (state.model) params.set('model', state.model);
  if (state.selection) params.set('select', `${{ vertex: 'v', edge: 'e', face: 'f', halfedge: 'h' }[state.selection.kind]}${state.selection.id}`);
  if (state.camera) {
    const numbers = [...state.camera.position, ...state.camera.target, state.camera.zoom].map((x) => +x.toPrecision(6));
    params.set('camera', numbers.join(','));
  }
  if (state.mode) params.set('mode', state.mode);
  return params.toString();
}

/** Reads a query string; anything malformed is left out rather than trusted. */
export function decodeViewState(query: string): ViewState {
  const params = new URLSearchParams(query);
  const numbers = (params.get('camera') ?? '').split(',').map(Number);
  const camera =
    numbers.length === 7 && numbers.every(Number.isFinite)
      ? { position: numbers.slice(0, 3), target: numbers.slice(3, 6), zoom: numbers[6] > 0 ? numbers[6] : 1 }
      : null;
  const mode = params.get('mode');
  return {
    model: params.get('model'),
    selection: parseElementName(params.get('select') ?? ''),
    camera,
    mode: mode === 'top' || mode === 'perspective' ? mode : null,
  };
}
