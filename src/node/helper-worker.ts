/** The worker of `helper-thread.ts`: takes its task unless it was called off, runs it, and replies. */
import { type MessagePort, workerData } from 'node:worker_threads';
import type { TopologyTask } from '../core/subdivision/helper-thread.js';
import { runTopologyTask } from '../core/subdivision/topology-task.js';
import { DONE, FAILED, type HelperReply, TAKEN, UNUSED_WORKER_MS, WAITING } from './helper-thread.js';

const { state, port } = workerData as { state: Int32Array; port: MessagePort };

// a level that failed before handing over never joins: a worker left without a task goes
const unused = setTimeout(() => port.close(), UNUSED_WORKER_MS);

port.once('message', (task: TopologyTask) => {
  clearTimeout(unused);
  if (Atomics.compareExchange(state, 0, WAITING, TAKEN) === WAITING) {
    Atomics.notify(state, 0);
    let reply: HelperReply;
    try {
      reply = { slots: runTopologyTask(task) };
    } catch (error) {
      reply = { error: error instanceof Error ? error.message : String(error) };
    }
    port.postMessage(reply);
    Atomics.store(state, 0, 'slots' in reply ? DONE : FAILED);
    Atomics.notify(state, 0);
  }
  port.close();
});
