/**
 * `halfedge-lab/worker`: the editing session in a Web Worker, for apps that must not freeze.
 *
 * @example
 *   import { SessionClient } from 'halfedge-lab/worker';
 *   const client = new SessionClient();
 *   const snapshot = await client.open(bytes, 'bunny.ply');
 *   await client.start({ kind: 'subdivide', scheme: 'loop' });
 *   const done = await client.runToEnd();
 */
export { CancelledError, SessionClient, type SessionClientOptions, WorkerStoppedError } from './client.js';
export { PageCopy, type PageSnapshot } from './page-copy.js';
export type { EditRequest, OperationRequest } from './operations.js';
export type { FileInfo, HistoryItem, LoadedFile, OpenOptions, ProgressEvent, MeshPatch, RenderBuffers, RenderPatch, SessionApi, Snapshot, SnapshotDetails, SteppingState } from './protocol.js';
export { EditingSession } from './session.js';
