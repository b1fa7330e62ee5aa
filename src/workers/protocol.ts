/**
 * The whole conversation between the page and the session worker, as types.
 *
 * The worker hosts one editing session: the current mesh, its history, and the operation being
 * stepped. After every change it answers with a `Snapshot`: everything the page needs to draw the
 * mesh and to answer pointer questions ("what is next of h17?") without another round trip. The
 * snapshot's typed arrays are *transferred*, never copied a second time.
 *
 * Calls go through comlink (`SessionApi` is what `wrap()` returns on the page); errors cross the
 * boundary with their type and fields intact (`installErrorTransfer`).
 */
import { transferHandlers } from 'comlink';
import {
  type BoundingBox,
  type BoundingSphere,
  type BuildReport,
  changeBuffers,
  type ChangeRecord,
  errorFromJSON,
  type ErrorRecord,
  errorToJSON,
  meshBuffers,
  type MeshStats,
  type Phase,
  type PhaseElements,
  type PointerDiff,
  type SerializedMesh,
  type Violation,
} from '../core/index.js';
import type { SubdivisionScheme } from '../core/subdivision/index.js';
import type { ColourScale } from './colour-scale.js';
import type { EditRequest, OperationRequest } from './operations.js';

export type { EditRequest, OperationRequest };

/** What the file said about itself. */
export interface FileInfo {
  name: string;
  format: string;
  encoding: string;
  counts: { vertices: number; faces: number };
  comments: string[];
  notes: string[];
  /** The distance within which the file's vertices were welded (STL, glTF; 0: equal positions only). */
  weldTolerance: number;
  /** Edges where the file split its vertices (corner values differ across them: see `seamEdges`); null when it has no per-corner values. */
  seams: number | null;
}

/** How a file is read: the files a `.gltf` names (its `.bin` buffers), and the distance within which STL and glTF vertices weld. */
export interface OpenOptions {
  resources?: ReadonlyMap<string, Uint8Array<ArrayBuffer>>;
  weldTolerance?: number;
}

/** A parsed and built file, as the loader worker hands it over. */
export interface LoadedFile {
  mesh: SerializedMesh;
  report: BuildReport;
  file: FileInfo;
}

/**
 * Above this many triangles the page picks through a worker holding a bounding-volume hierarchy
 * (built while the mesh is on screen); up to it, the page tests a ray against each triangle (a few
 * milliseconds).
 */
export const PICK_IN_WORKER_ABOVE = 150_000;

/**
 * What the page draws, ready to upload: so the page's thread only hands buffers to the GPU. Every
 * buffer is indexed by slot and has room to grow (see `RenderLayout`); `counts` says how much of
 * each to draw.
 */
export interface RenderBuffers {
  /** x, y, z of every vertex slot, as float32. */
  positions: Float32Array;
  /** Vertex ids, three per triangle (polygons split; a triangle of no area where a face was). */
  triangles: Uint32Array;
  /** The face each triangle belongs to, for picking (-1 for a triangle of no area). */
  triangleFace: Int32Array;
  /** Vertex ids, two per edge slot (a deleted edge: one vertex twice). */
  edges: Uint32Array;
  /** One vertex id per vertex slot, to draw as dots (a deleted one: a live vertex again). */
  vertices: Uint32Array;
  /** Entries in use: vertex slots, edge slots, triangles. */
  counts: { vertices: number; edges: number; triangles: number };
  /** The normal of the plane every face lies in, for a 2D mesh; null for a 3D one. */
  planeNormal: [number, number, number] | null;
  /** The box and the sphere around every live vertex, measured here rather than on the page's thread. */
  bounds: RenderBounds;
  /**
   * Copies of `positions` and `triangles` for the picking worker (the page draws from the
   * originals), made here so that the page only passes them on; null up to PICK_IN_WORKER_ABOVE
   * triangles, where the page picks by itself.
   */
  picking: { positions: Float32Array; triangles: Uint32Array } | null;
}

/** How many elements of each kind a shown phase lists as created, moved, rewired and removed (a big mesh's phase touches millions). */
export const PHASE_MARKS = 5000;

/**
 * A phase as the page shows it: its name, explanation and values, and what it created, moved,
 * rewired and removed (the first PHASE_MARKS of each), read off its record in the worker. The
 * record itself comes as the snapshot's patch.
 */
export type ShownPhase = Omit<Phase, 'change'> & PhaseElements;

/**
 * The box and the sphere around every live vertex (`boundingBox`, `boundingSphere`): the view is
 * framed on them, and three.js culls by the sphere. No live vertex: a point at the origin.
 */
export type RenderBounds = BoundingBox & BoundingSphere;

/** A patch that writes more positions than this carries the bounds measured again; one that writes fewer, the page grows its own to take them in. */
export const REBOUND_ABOVE = 4096;

/** New values for one range of one render buffer. */
export interface RenderWrite {
  buffer: 'positions' | 'triangles' | 'triangleFace' | 'edges' | 'vertices';
  /** The first entry written (a number, not an element: three per vertex position). */
  offset: number;
  data: Float32Array | Uint32Array | Int32Array;
}

/** What to rewrite in the page's render buffers after a change. */
export interface RenderPatch {
  writes: RenderWrite[];
  counts: RenderBuffers['counts'];
  /**
   * Copies of the writes to `positions` and `triangles` for the picking worker, made here so that
   * the page only passes them on (as `RenderBuffers.picking`); null where the page picks by itself.
   */
  picking: RenderWrite[] | null;
  /** The bounds again, when the patch writes more than REBOUND_ABOVE positions; else null. */
  bounds: RenderBounds | null;
}

/**
 * How the page's copy of the mesh becomes this snapshot's: `change` applied forwards to the mesh of
 * snapshot `from` (the one the page holds), and `render` to its buffers.
 */
export interface MeshPatch {
  from: number;
  change: ChangeRecord;
  render: RenderPatch;
}

export interface HistoryItem {
  label: string;
  vertices: number;
  faces: number;
  /** What made this entry, so a link can replay the way to it. */
  source: HistorySource;
}

/**
 * What made a history entry: opening a file (`sample`: the sample model it is, null for a file of
 * the user's), an operation run to its end, a local edit, or a mesh put back after a restart.
 */
export type HistorySource =
  | { kind: 'open'; name: string; sample: string | null }
  | { kind: 'operation'; request: OperationRequest }
  | { kind: 'edit'; request: EditRequest }
  | { kind: 'restore' }
  /** A state of a practice run: a fixture after some of a solution's writes (it may break invariants). */
  | { kind: 'practice' }
  /** An edit or operation the student's own solution made on the mesh in the view ("Use my code"): no link can replay it. */
  | { kind: 'solution'; exercise: string };

/** The operation being stepped, if any. */
export interface SteppingState {
  label: string;
  /** Phases done so far. */
  phases: number;
  /** Phases in all, when the operation says in advance. */
  total: number | null;
}

export interface Snapshot {
  /** Increases with every snapshot the session sends. */
  version: number;
  /** The whole mesh, or null when `patch` changes the page's copy into this snapshot's. */
  mesh: SerializedMesh | null;
  /** The buffers to draw, or null when `patch` changes the page's. */
  render: RenderBuffers | null;
  patch: MeshPatch | null;
  /**
   * Counts, checks and the operations that apply. `pending` after a change with a record from the
   * mesh the page holds (patched, or sent whole when too large to patch: a subdivision phase):
   * then the counts (V, E, F, χ, boundary edges) are exact, `problems` is the check of what the
   * change touched (on a mesh that had problems before, or after a change that rewrote whole
   * ranges, the last full pass's), and the rest is as the last full pass found it, until
   * `details()` brings the full pass of this snapshot.
   */
  details: SnapshotDetails & { pending: boolean };
  /** The build report of the file this mesh came from (until the first edit). */
  report: BuildReport | null;
  file: FileInfo | null;
  /** The phase that produced this mesh (while stepping, and after an operation in the history). */
  phase: ShownPhase | null;
  /** Pointers changed by the last phase or edit. */
  diff: PointerDiff | null;
  /** While stepping, the colours of the per-vertex values the phase reports (null: none, draw the surface plain). */
  colours: ColourScale | null;
  stepping: SteppingState | null;
  /**
   * The operation the last Step finished, while its last phase stays on show (`phase`, `diff`,
   * `colours`: until the mesh changes again); `stepBack` goes back into it.
   */
  ended: SteppingState | null;
  history: { items: HistoryItem[]; index: number };
}

/** What takes a pass over the whole mesh to know: sent with a whole mesh, or after a patch on request. */
export interface SnapshotDetails {
  /** The snapshot these are of. */
  version: number;
  stats: MeshStats;
  /** What `validate()` found (empty: every invariant holds). */
  problems: Violation[];
  /**
   * Why an operation that checks every face does not apply to this mesh (null: it does): each
   * subdivision scheme, cotangent smoothing, decimation and remeshing (they need triangles).
   */
  unavailable: Record<CheckedOperation, string | null>;
}

export type CheckedOperation = SubdivisionScheme | 'cotan' | 'decimate' | 'remesh';

export interface ProgressEvent {
  label: string;
  /** 0 … 1. */
  fraction: number;
}

export type ProgressListener = (event: ProgressEvent) => void;

/** The type of a verb's arguments, carried by the table (the value itself is empty). */
interface Arguments<A extends unknown[]> {
  readonly arguments?: A;
}
const takes = <A extends unknown[]>(): Arguments<A> => ({});

/**
 * The verbs a student can use, by clicking or through `window.halfedgeLab`: each changes the mesh
 * on screen (or the operation being stepped) and answers with a snapshot.
 */
export const studentVerbs = {
  start: takes<[request: OperationRequest]>(),
  step: takes<[]>(),
  /** Back one phase (after the last Step, back into the operation that Step ended). */
  stepBack: takes<[]>(),
  runToEnd: takes<[]>(),
  cancel: takes<[]>(),
  edit: takes<[request: EditRequest]>(),
  undo: takes<[]>(),
  redo: takes<[]>(),
  jump: takes<[index: number]>(),
};

/**
 * Every verb of the session that answers with a snapshot, listed once: `EditingSession` has each as
 * a method, the worker exposes each (transferring the snapshot), `SessionClient` has each but
 * `adopt` (which its `open` calls) answering with the page's copy, and `window.halfedgeLab` and the
 * app have the student's.
 */
export const snapshotVerbs = {
  ...studentVerbs,
  /** Makes a parsed file the current mesh; `sample` names the sample model it is. */
  adopt: takes<[loaded: LoadedFile, sample?: string | null]>(),
  /** Puts back a mesh the page kept (after the worker had to be restarted). */
  restore: takes<[mesh: SerializedMesh, label: string]>(),
  /** Shows a state of a practice run, with the write that led to it as the diff; replaces the practice state shown before. */
  practice: takes<[mesh: SerializedMesh, label: string, diff: PointerDiff | null]>(),
  /**
   * Applies the record of a student's solution's writes on the current mesh (valid: the page
   * checked it) as an edit: an entry undo takes back, sent to the page as a patch.
   */
  solution: takes<[change: ChangeRecord, label: string, exercise: string]>(),
  /** The current snapshot, with the whole mesh. */
  snapshot: takes<[]>(),
};

export type SnapshotVerb = keyof typeof snapshotVerbs;
export type StudentVerb = keyof typeof studentVerbs;
export type VerbArguments<V extends SnapshotVerb> = NonNullable<(typeof snapshotVerbs)[V]['arguments']>;
/** The verbs as methods answering `R`. */
export type SnapshotVerbs<R, V extends SnapshotVerb = SnapshotVerb> = { [K in V]: (...args: VerbArguments<K>) => R };
export const snapshotVerbNames = Object.keys(snapshotVerbs) as SnapshotVerb[];
export const studentVerbNames = Object.keys(studentVerbs) as StudentVerb[];

/** The session worker's methods, as the page sees them (every call is asynchronous). */
export interface SessionApi extends SnapshotVerbs<Promise<Snapshot>> {
  /** The full counts and checks of the current mesh (after a patched snapshot). */
  details(): Promise<SnapshotDetails>;
  exportMesh(format: string): Promise<Uint8Array>;
  /** The fingerprint of the mesh of the last snapshot (`meshFingerprint`), to check the page's copy. */
  fingerprint(): Promise<string>;
  /** The seam edges of the mesh of the last snapshot (`seamEdges`). */
  seams(): Promise<Int32Array>;
  setProgressListener(listener: ProgressListener | null): Promise<void>;
}

/** The loader worker: parses and builds one file, then is thrown away (cancel = terminate it). */
export interface LoaderApi {
  load(bytes: Uint8Array, name: string, onProgress: ProgressListener, options?: OpenOptions): Promise<LoadedFile>;
}

/**
 * The buffers of a snapshot or loaded file to transfer rather than copy: the whole mesh and render
 * buffers and a patch's record (the session sends a copy of a record its history keeps), made for
 * the page alone.
 */
export function transferables(value: Snapshot | LoadedFile): ArrayBuffer[] {
  const buffers = value.mesh ? meshBuffers(value.mesh) : [];
  const render = 'render' in value ? value.render : null;
  if (render) {
    const { positions, triangles, triangleFace, edges, vertices, picking } = render;
    const arrays = [positions, triangles, triangleFace, edges, vertices, ...(picking ? [picking.positions, picking.triangles] : [])];
    buffers.push(...arrays.map((a) => a.buffer as ArrayBuffer));
  }
  if ('patch' in value && value.patch) {
    const { writes, picking } = value.patch.render;
    buffers.push(...[...writes, ...(picking ?? [])].map((w) => w.data.buffer as ArrayBuffer), ...changeBuffers(value.patch.change));
  }
  if ('colours' in value && value.colours) buffers.push(value.colours.colours.buffer as ArrayBuffer);
  // a buffer may hold several of the arrays: each goes once
  return [...new Set(buffers)];
}

/**
 * Makes comlink carry errors as `errorToJSON` records, rebuilt with `errorFromJSON` on the other
 * side, so a `ParseError` arrives as a `ParseError` with its format and location. Both the page
 * and the workers call this once.
 */
export function installErrorTransfer(): void {
  const builtIn = transferHandlers.get('throw')!;
  transferHandlers.set('throw', {
    canHandle: builtIn.canHandle,
    serialize: ({ value }: { value: unknown }) => [errorToJSON(value), []],
    deserialize: (record: ErrorRecord) => {
      throw errorFromJSON(record);
    },
  } as typeof builtIn);
}
