/**
 * The page's side of the session: a typed client that talks to the session worker, loads files
 * in a throw-away loader worker, and survives the session worker dying.
 *
 *   - `open` parses and builds in a separate loader worker, so cancelling a huge file is
 *     `terminate()` and the session (current mesh and history) is never touched;
 *   - every snapshot's mesh is remembered, so if the session worker dies (out of memory, say), a
 *     fresh one is started with the last good mesh and `onRestart` tells the page.
 *
 * @example
 *   const client = new SessionClient();
 *   client.onProgress = ({ label, fraction }) => bar.update(label, fraction);
 *   const snapshot = await client.open(new Uint8Array(await file.arrayBuffer()), file.name);
 */
import { proxy, type Remote, transfer, wrap } from 'comlink';
import { meshFingerprint, serializeMesh } from '../core/index.js';
import { PageCopy, type PageSnapshot } from './page-copy.js';
import {
  installErrorTransfer,
  type LoaderApi,
  type OpenOptions,
  type ProgressEvent,
  type SessionApi,
  type Snapshot,
  type SnapshotDetails,
  type SnapshotVerb,
  snapshotVerbNames,
  type SnapshotVerbs,
  transferables,
  type VerbArguments,
} from './protocol.js';

installErrorTransfer();

export interface SessionClientOptions {
  /** Defaults to the package's own session worker. */
  createSessionWorker?: () => Worker;
  /** Defaults to the package's own loader worker. */
  createLoaderWorker?: () => Worker;
}

/** A load or operation stopped by `cancel()`. */
export class CancelledError extends Error {
  override readonly name = 'CancelledError';
}

/** The worker stopped (usually: it ran out of memory). */
export class WorkerStoppedError extends Error {
  override readonly name = 'WorkerStoppedError';
}

interface LiveWorker<T> {
  worker: Worker;
  remote: Remote<T>;
  /** Rejects when the worker stops (or is stopped). */
  stopped: Promise<never>;
  stop: (error: Error) => void;
}

export class SessionClient {
  onProgress: ((event: ProgressEvent) => void) | null = null;
  /**
   * Called after the session worker died: restarted with `snapshot` (null if there was no mesh yet),
   * or, when it died before it ever answered (its script could not load), not restarted at all.
   */
  onRestart: ((message: string, snapshot: PageSnapshot | null) => void) | null = null;

  private session: LiveWorker<SessionApi>;
  private loader: LiveWorker<LoaderApi> | null = null;
  /** Calls under way that may report progress (see `report`). */
  private running = 0;
  /** The mesh and buffers of the last snapshot, which patches change in place. */
  private readonly copy = new PageCopy();
  private readonly createSessionWorker: () => Worker;
  private readonly createLoaderWorker: () => Worker;

  constructor(options: SessionClientOptions = {}) {
    this.createSessionWorker =
      options.createSessionWorker ?? (() => new Worker(new URL('./session.worker.js', import.meta.url), { type: 'module' }));
    this.createLoaderWorker =
      options.createLoaderWorker ?? (() => new Worker(new URL('./loader.worker.js', import.meta.url), { type: 'module' }));
    this.session = this.startSession();
  }

  /**
   * Parses and builds a file off the session, then makes it the current mesh. `bytes` is
   * transferred (it is empty afterwards). A parse error leaves the session as it was.
   * `options`: the files a `.gltf` names (its `.bin` buffers), opened together with it; the
   * distance within which STL and glTF vertices weld.
   */
  async open(bytes: Uint8Array, name: string, sample: string | null = null, options: OpenOptions = {}): Promise<PageSnapshot> {
    this.stopLoading(new CancelledError(`opening ${name} replaced an earlier load`));
    const loader = (this.loader = live<LoaderApi>(this.createLoaderWorker(), () =>
      new WorkerStoppedError(`the loader stopped while reading ${name} (is the file larger than this browser can hold?)`),
    ));
    try {
      this.running++;
      const loaded = await Promise.race([loader.remote.load(transfer(bytes, [bytes.buffer as ArrayBuffer]), name, proxy(this.report), options), loader.stopped]).finally(() => this.running--);
      return await this.call((session) => session.adopt(transfer(loaded, transferables(loaded)), sample));
    } finally {
      if (this.loader === loader) this.loader = null;
      loader.worker.terminate();
    }
  }

  /** Stops a load in progress, or the operation being stepped or run. */
  async cancel(): Promise<PageSnapshot | null> {
    if (this.loader) {
      this.stopLoading(new CancelledError('loading cancelled'));
      return null;
    }
    return this.request('cancel');
  }

  /**
   * Asks the session for one of its verbs (the table in protocol.ts; each is also a method of this
   * client: `client.step()` is `client.request('step')`), answering with the page's copy.
   */
  request<V extends ClientVerb>(verb: V, ...args: VerbArguments<V>): Promise<PageSnapshot> {
    return this.call((session) => (session[verb] as (...args: unknown[]) => Promise<Snapshot>)(...args));
  }

  /** The full counts and checks of the last snapshot (after a patched one). */
  details(): Promise<SnapshotDetails> {
    return Promise.race([this.session.remote.details(), this.session.stopped]);
  }
  /** The seam edges of the mesh on screen (see `seamEdges`). */
  seams(): Promise<Int32Array> {
    return Promise.race([this.session.remote.seams(), this.session.stopped]);
  }

  /** The session's fingerprint of its mesh, and this page's of its copy: equal when the copy is right. */
  async fingerprints(): Promise<{ session: string; page: string | null }> {
    const session = await Promise.race([this.session.remote.fingerprint(), this.session.stopped]);
    return { session, page: this.copy.mesh ? meshFingerprint(this.copy.mesh) : null };
  }
  exportMesh(format: string): Promise<Uint8Array> {
    return Promise.race([this.session.remote.exportMesh(format), this.session.stopped]);
  }
  /** Stops the session worker as if it had crashed (for tests of the recovery). */
  simulateCrash(): void {
    this.session.stop(new WorkerStoppedError('the worker was stopped'));
  }

  dispose(): void {
    this.stopLoading(new CancelledError('the session was closed'));
    this.session.worker.terminate();
  }

  private async call(method: (session: Remote<SessionApi>) => Promise<Snapshot>): Promise<PageSnapshot> {
    const { remote, stopped } = this.session;
    this.running++;
    try {
      let snapshot = await Promise.race([method(remote), stopped]);
      // a patch of a mesh this page does not hold (a snapshot went astray): ask for the whole one
      if (!this.copy.accepts(snapshot)) snapshot = await Promise.race([remote.snapshot(), stopped]);
      return this.copy.take(snapshot);
    } finally {
      this.running--;
    }
  }

  /**
   * Passes a progress report on while a call is under way. Reports travel on a port of their own,
   * so the last ones of a run may arrive after its answer: then nothing is under way, and a bar
   * they showed would stay over the view.
   */
  private readonly report = (event: ProgressEvent): void => {
    if (this.running > 0) this.onProgress?.(event);
  };

  private startSession(): LiveWorker<SessionApi> {
    const session = live<SessionApi>(this.createSessionWorker(), () =>
      new WorkerStoppedError('the editing worker stopped (most likely it ran out of memory)'),
    );
    // a worker that never answered could not even load: starting it again would fail the same way, forever
    let answered = false;
    session.stopped.catch((error: Error) => {
      session.worker.terminate();
      if (this.session !== session) return;
      if (answered) void this.recover(error.message);
      else this.onRestart?.('the editing worker could not start; reload the page to try again', null);
    });
    void session.remote.setProgressListener(proxy(this.report)).then(() => (answered = true));
    return session;
  }

  /** A fresh session worker, given the last mesh the page saw. */
  private async recover(reason: string): Promise<void> {
    this.session = this.startSession();
    // sent as a copy: the page keeps drawing from its own arrays
    const mesh = this.copy.mesh ? serializeMesh(this.copy.mesh) : null;
    const snapshot = mesh ? await this.request('restore', mesh, 'restored after a restart') : null;
    this.onRestart?.(`${reason}; restarted${snapshot ? ' with the last good mesh' : ''}`, snapshot);
  }

  private stopLoading(error: Error): void {
    if (!this.loader) return;
    this.loader.stop(error);
    this.loader.worker.terminate();
    this.loader = null;
  }
}

/** The verbs of the table as methods; `adopt` is `open`'s, and `cancel` also stops a load. */
type ClientVerb = Exclude<SnapshotVerb, 'adopt'>;
export interface SessionClient extends SnapshotVerbs<Promise<PageSnapshot>, Exclude<ClientVerb, 'cancel'>> {}
for (const verb of snapshotVerbNames) {
  if (verb === 'adopt' || Object.hasOwn(SessionClient.prototype, verb)) continue;
  Object.defineProperty(SessionClient.prototype, verb, {
    value(this: SessionClient, ...args: unknown[]) {
      return (this.request as (verb: ClientVerb, ...args: unknown[]) => Promise<PageSnapshot>)(verb, ...args);
    },
  });
}

function live<T>(worker: Worker, stoppedError: () => Error): LiveWorker<T> {
  let stop!: (error: Error) => void;
  const stopped = new Promise<never>((_, reject) => {
    stop = reject;
  });
  stopped.catch(() => {}); // callers race against it; an unobserved rejection is not an error here
  worker.addEventListener('error', (event) => {
    event.preventDefault();
    stop(stoppedError());
  });
  return { worker, remote: wrap<T>(worker), stopped, stop };
}
