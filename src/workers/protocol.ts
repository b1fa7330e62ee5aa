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
  type BuildReport,
  errorFromJSON,
  type ErrorRecord,
  errorToJSON,
  meshBuffers,
  type MeshStats,
  type Phase,
  type PointerDiff,
  type SerializedMesh,
  type Violation,
} from '../core/index.js';
import type { SubdivisionScheme } from '../core/subdivision/index.js';
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

/** What the page draws, ready to upload: so the page's thread only hands buffers to the GPU. */
export interface RenderBuffers {
  /** x, y, z of every vertex slot, as float32. */
  positions: Float32Array;
  /** Vertex ids, three per triangle (polygons split). */
  triangles: Uint32Array;
  /** The face each triangle belongs to, for picking. */
  triangleFace: Int32Array;
  /** Vertex ids, two per live edge. */
  edges: Uint32Array;
  /** The live vertices (to draw as dots). */
  vertices: Uint32Array;
  /** The normal of the plane every face lies in, for a 2D mesh; null for a 3D one. */
  planeNormal: [number, number, number] | null;
  /**
   * Copies of `positions` and `triangles` for the picking worker (the page draws from the
   * originals), made here so that the page only passes them on; null up to PICK_IN_WORKER_ABOVE
   * triangles, where the page picks by itself.
   */
  picking: { positions: Float32Array; triangles: Uint32Array } | null;
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
  | { kind: 'restore' };

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
  mesh: SerializedMesh;
  render: RenderBuffers;
  stats: MeshStats;
  /** What `validate()` found (empty: every invariant holds). */
  problems: Violation[];
  /** The build report of the file this mesh came from (until the first edit). */
  report: BuildReport | null;
  file: FileInfo | null;
  /** The phase that produced this mesh, when stepping. */
  phase: Phase | null;
  /** Pointers changed by the last phase or edit (absent on very large meshes). */
  diff: PointerDiff | null;
  stepping: SteppingState | null;
  history: { items: HistoryItem[]; index: number };
  /**
   * Why an operation that checks every face does not apply to this mesh (null: it does): each
   * subdivision scheme, cotangent smoothing and decimation (they need triangles).
   */
  unavailable: Record<CheckedOperation, string | null>;
}

export type CheckedOperation = SubdivisionScheme | 'cotan' | 'decimate';

export interface ProgressEvent {
  label: string;
  /** 0 … 1. */
  fraction: number;
}

export type ProgressListener = (event: ProgressEvent) => void;

/** The session worker's methods, as the page sees them (every call is asynchronous). */
export interface SessionApi {
  adopt(loaded: LoadedFile, sample: string | null): Promise<Snapshot>;
  /** Puts back a mesh the page kept (after the worker had to be restarted). */
  restore(mesh: SerializedMesh, label: string): Promise<Snapshot>;
  snapshot(): Promise<Snapshot>;
  start(request: OperationRequest): Promise<Snapshot>;
  step(): Promise<Snapshot>;
  runToEnd(): Promise<Snapshot>;
  cancel(): Promise<Snapshot>;
  edit(request: EditRequest): Promise<Snapshot>;
  undo(): Promise<Snapshot>;
  redo(): Promise<Snapshot>;
  jump(index: number): Promise<Snapshot>;
  exportMesh(format: string): Promise<Uint8Array>;
  setProgressListener(listener: ProgressListener | null): Promise<void>;
}

/** The loader worker: parses and builds one file, then is thrown away (cancel = terminate it). */
export interface LoaderApi {
  load(bytes: Uint8Array, name: string, onProgress: ProgressListener): Promise<LoadedFile>;
}

/** Every buffer of a snapshot or loaded file, for the transfer list. */
export function transferables(value: Snapshot | LoadedFile): ArrayBuffer[] {
  const buffers = meshBuffers(value.mesh);
  if ('render' in value) {
    const { positions, triangles, triangleFace, edges, vertices, picking } = value.render;
    const arrays = [positions, triangles, triangleFace, edges, vertices, ...(picking ? [picking.positions, picking.triangles] : [])];
    buffers.push(...arrays.map((a) => a.buffer as ArrayBuffer));
  }
  return buffers;
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
