/**
 * The helper thread of a subdivision level run straight through (see
 * `core/subdivision/helper-thread.ts`), in Node: a worker thread started as each level begins and
 * let go after it. It takes about 25 ms to begin, while this thread grows the mesh's arrays. A
 * worker kept between levels would keep its views of a level's shared arrays until its own garbage
 * collection, which it seldom needs: six Loop levels of a 1.3M-triangle mesh left 2.3 GB resident.
 *
 * A task's state, one shared number, goes from WAITING to TAKEN (the worker has the task and began)
 * and then to DONE or FAILED; or from WAITING to CALLED_OFF, when this thread asks (`begun`) before
 * the worker has begun: this thread then does the steps itself, so a worker slow to start, or failing
 * to, costs no more than the time it took to ask.
 */
import { MessageChannel, receiveMessageOnPort, Worker } from 'node:worker_threads';
import type { SlotCounts } from '../core/mesh-arrays.js';
import { type HelperRun, type HelperThread, type TopologyTask, useHelperThread } from '../core/subdivision/helper-thread.js';
import { workerEntry } from './worker-entry.js';

export const WAITING = 0;
export const TAKEN = 1;
export const DONE = 2;
export const FAILED = 3;
export const CALLED_OFF = 4;

/** What the worker posts when it stops: the slot counts the steps left, or the error they threw. */
export type HelperReply = { slots: SlotCounts } | { error: string };

export interface HelperOptions {
  /** The fewest faces a level must start from to get the helper (default 50,000: a smaller level takes under 25 ms). */
  minFaces?: number;
  /** How long `begun` waits for a worker that has not begun before the caller does the steps itself (default 0). */
  startWaitMs?: number;
}

/** How long a worker waits for its task before it goes (the caller grows the arrays meanwhile). */
export const UNUSED_WORKER_MS = 60_000;

/** The longest a task may run on the helper: far beyond any level that fits in memory. */
const MAX_TASK_MS = 10 * 60 * 1000;

const entry = workerEntry(import.meta.url, './helper-worker');

/** A helper thread for subdivision levels in Node. */
export function nodeHelperThread({ minFaces = 50_000, startWaitMs = 0 }: HelperOptions = {}): HelperThread {
  return { minFaces, start: () => startWorker(startWaitMs) };
}

function startWorker(startWaitMs: number): HelperRun {
  const state = new Int32Array(new SharedArrayBuffer(4));
  const { port1, port2 } = new MessageChannel();
  const worker = new Worker(entry.code, { eval: entry.eval, workerData: { state, port: port2 }, transferList: [port2] });
  worker.unref();
  let posted = false;
  let taken: boolean | null = null;
  const finish = () => {
    void worker.terminate();
    port1.close();
  };
  const begun = (): boolean => {
    if (taken === null) {
      if (posted && startWaitMs > 0) Atomics.wait(state, 0, WAITING, startWaitMs);
      taken = Atomics.compareExchange(state, 0, WAITING, CALLED_OFF) !== WAITING;
      if (!taken) finish();
    }
    return taken;
  };
  return {
    memory: (bytes) => new SharedArrayBuffer(bytes),
    post(task: TopologyTask) {
      port1.postMessage(task);
      posted = true;
    },
    begun,
    join(): SlotCounts {
      if (!begun()) throw new Error("subdivision's helper thread: joined, but it never began its task");
      const deadline = Date.now() + MAX_TASK_MS;
      while (Atomics.load(state, 0) === TAKEN && Date.now() < deadline) Atomics.wait(state, 0, TAKEN, 1000);
      const reply = receiveMessageOnPort(port1)?.message as HelperReply | undefined;
      finish();
      if (reply !== undefined && 'slots' in reply) return reply.slots;
      throw new Error(`subdivision's helper thread: ${reply?.error ?? `no answer in ${MAX_TASK_MS / 60000} minutes`}`);
    },
  };
}

/** Lets the subdivision levels run straight through (`subdivide`) use a helper thread from now on. */
export function installHelperThread(options?: HelperOptions): void {
  useHelperThread(nodeHelperThread(options));
}
