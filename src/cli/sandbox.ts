/**
 * The Node side of a practice sandbox: a solution runs in a worker thread of its own, limited to
 * `MEMORY_LIMIT_MB`, whose output is kept from the terminal. `grade` starts `grade-worker`; the
 * Gradescope grader (`grader.ts`, one bundled file) starts itself again as the worker.
 */
import { parentPort, Worker } from 'node:worker_threads';
import type { WorkerEntry } from '../node/worker-entry.js';
import type { SandboxPort } from '../workers/practice-runner.js';
import { lockDown, MEMORY_LIMIT_MB, type SandboxRequest, serveRequest } from '../workers/practice-sandbox.js';

/** Opens a fresh sandbox on `entry` for each run (`workerData`: what the entry is told, if it plays more than one part). */
export function workerSandbox(entry: WorkerEntry, workerData?: unknown): () => SandboxPort {
  return () => {
    const worker = new Worker(entry.code, {
      eval: entry.eval,
      workerData,
      resourceLimits: { maxOldGenerationSizeMb: MEMORY_LIMIT_MB, maxYoungGenerationSizeMb: 32 },
      stdout: true,
      stderr: true,
    });
    return {
      post: (request) => worker.postMessage(request),
      listen(onMessage, onFailure) {
        worker.on('message', onMessage);
        worker.on('error', (error: Error & { code?: string }) =>
          onFailure(new Error(error.code === 'ERR_WORKER_OUT_OF_MEMORY' ? `it used more than ${MEMORY_LIMIT_MB} MB of memory` : error.message)),
        );
      },
      terminate: () => void worker.terminate(),
    };
  };
}

/** Inside the worker thread: answers the one request it will be sent, after shutting what a solution may not touch. */
export function serveSandboxThread(): void {
  const port = parentPort!;
  port.once('message', (request: SandboxRequest) => serveRequest(request, (message) => port.postMessage(message)));
  lockDown();
}
