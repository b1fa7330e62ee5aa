/**
 * A link that restores what a lecturer shows: the sample model, the operations and edits that led
 * from it to the mesh on screen (replayed on opening), the selection with the walk that led to it
 * (the breadcrumb), and the camera, written to be read:
 * `?model=torus.off&ops=cut(plane:0/0/1/0,keep:above);flip-edge(edge:3)&select=h17&walk=next,twin&naming=target&camera=…&mode=top&explode=on`.
 * Links written before, whose steps were JSON, still open. Uploaded files never leave the
 * browser, so a link can only name a sample model.
 */
import type { EditRequest, OperationRequest, Snapshot } from '../workers/protocol.js';
import type { Convention } from './records.js';
import { isMove, type Move, parseElementName, type Selection } from './selection.js';

/** One step from the sample to what is on screen: an operation run to its end, or a local edit. */
export type ReplayStep = { kind: 'operation'; request: OperationRequest } | { kind: 'edit'; request: EditRequest };

export interface ViewState {
  model: string | null;
  /** The steps from the model to the mesh shown, in order. */
  steps: ReplayStep[];
  /** Where the breadcrumb starts (the selection itself when nothing was walked)… */
  selection: Selection | null;
  /** …and the pointers followed from there to the selection. */
  walk: Move[];
  /** The halfedge naming the view speaks (origin or target); null: the page's default. */
  naming: Convention | null;
  /**
   * Camera position, orbit target, zoom (orthographic), and where the target is drawn: its shift
   * from the middle of the view as a share of the width and height (see `Viewer.frame`).
   */
  camera: { position: number[]; target: number[]; zoom: number; shift: [number, number] } | null;
  mode: 'perspective' | 'top' | null;
  /** The exploded view (the parts drawn pulled apart: a cut that kept both sides, a model of several). */
  exploded: boolean;
}

export function encodeViewState(state: ViewState): string {
  const params: Array<[string, string]> = [];
  if (state.model) params.push(['model', state.model]);
  if (state.steps.length > 0) params.push(['ops', state.steps.map(stepText).join(';')]);
  if (state.selection) params.push(['select', `${{ vertex: 'v', edge: 'e', face: 'f', halfedge: 'h' }[state.selection.kind]}${state.selection.id}`]);
  if (state.selection && state.walk.length > 0) params.push(['walk', state.walk.join(',')]);
  if (state.naming) params.push(['naming', state.naming]);
  if (state.camera) {
    const numbers = [...state.camera.position, ...state.camera.target, state.camera.zoom, ...state.camera.shift].map((x) => +x.toPrecision(6));
    params.push(['camera', numbers.join(',')]);
  }
  if (state.mode) params.push(['mode', state.mode]);
  if (state.exploded) params.push(['explode', 'on']);
  // the separators the steps and the camera use mean nothing else in a query: left as they are, so the link reads
  return params.map(([key, value]) => `${key}=${encodeURIComponent(value).replace(/%(2C|3A|3B|2F)/g, (escape) => decodeURIComponent(escape))}`).join('&');
}

/** The kinds of request that are operations; any other is an edit. */
const operationKinds = new Set(['subdivide', 'cut', 'smooth', 'decimate', 'remesh']);
/** The operations whose settings a request keeps under `options`. */
const withOptions = new Set(['smooth', 'decimate', 'remesh']);

/**
 * One step as text: its kind, then its settings as `name:value` (a list of numbers joined by
 * `/`), `cut(plane:0/0/1/0,keep:above)`; an operation's `options` are written as settings of its own.
 */
function stepText({ request }: ReplayStep): string {
  const { kind, ...rest } = request as { kind: string } & Record<string, unknown>;
  const settings = withOptions.has(kind) ? (rest.options as Record<string, unknown>) : rest;
  const fields = Object.entries(settings)
    .filter(([, value]) => value !== undefined)
    .map(([name, value]) => `${name}:${Array.isArray(value) ? value.join('/') : String(value)}`);
  return fields.length > 0 ? `${kind}(${fields.join(',')})` : kind;
}

/** A step's text read back; null when it is not one (the session checks each request again as it runs it). */
function parseStep(text: string): ReplayStep | null {
  const match = /^([a-z0-9-]+)(?:\((.*)\))?$/.exec(text);
  if (!match) return null;
  const [, kind, inside] = match;
  const settings: Record<string, unknown> = {};
  for (const field of inside ? inside.split(',') : []) {
    const colon = field.indexOf(':');
    if (colon <= 0) return null;
    const name = field.slice(0, colon);
    // a name from a link is data: never one that reaches an object's prototype
    if (!/^[a-zA-Z]+$/.test(name)) return null;
    settings[name] = fieldValue(field.slice(colon + 1));
  }
  if (!operationKinds.has(kind!)) return { kind: 'edit', request: { kind, ...settings } as EditRequest };
  const request = withOptions.has(kind!) ? { kind, options: settings } : { kind, ...settings };
  return { kind: 'operation', request: request as OperationRequest };
}

/** A setting's value: a list of numbers, a number, true or false, or a word. */
function fieldValue(text: string): unknown {
  if (text.includes('/')) return text.split('/').map(Number);
  if (text === 'true' || text === 'false') return text === 'true';
  return text !== '' && Number.isFinite(Number(text)) ? Number(text) : text;
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
    walk: walkMoves(params.get('walk')),
    naming: naming === 'origin' || naming === 'target' ? naming : null,
    camera,
    mode: mode === 'top' || mode === 'perspective' ? mode : null,
    exploded: params.get('explode') === 'on',
  };
}

/**
 * The steps of a link: the readable form, or the JSON of links written before it, each an
 * operation or an edit with a request object; anything else makes the whole list untrusted and
 * left out (the session checks each request again as it runs it).
 */
function replaySteps(text: string | null): ReplayStep[] {
  if (!text) return [];
  const steps = text.startsWith('[') ? jsonSteps(text) : text.split(';').map(parseStep);
  const isStep = (step: unknown): step is ReplayStep =>
    typeof step === 'object' &&
    step !== null &&
    ((step as ReplayStep).kind === 'operation' || (step as ReplayStep).kind === 'edit') &&
    typeof (step as ReplayStep).request === 'object' &&
    (step as ReplayStep).request !== null;
  return Array.isArray(steps) && steps.length <= 100 && steps.every(isStep) ? steps : [];
}

function jsonSteps(text: string): unknown {
  try {
    return JSON.parse(text);
  } catch {
    return null;
  }
}

/** The moves of a link's walk (`next,twin,prev.twin`); any that is not a move makes the walk left out. */
function walkMoves(text: string | null): Move[] {
  if (!text) return [];
  const moves = text.split(',');
  return moves.length <= 1000 && moves.every(isMove) ? moves : [];
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
