/** The page's way to run a solution: a fresh sandbox worker per run, watched by `sandboxRunner`. */
import type { SolutionRunner } from '../core/practice/grade-solution.js';
import type { SandboxMessage } from '../workers/practice-sandbox.js';
import { sandboxRunner } from '../workers/practice-runner.js';

export const browserRunner: SolutionRunner = sandboxRunner(() => {
  const worker = new Worker(new URL('../workers/practice.worker.ts', import.meta.url), { type: 'module' });
  return {
    post: (request) => worker.postMessage(request),
    listen(onMessage, onFailure) {
      worker.onmessage = (event: MessageEvent<SandboxMessage>) => onMessage(event.data);
      worker.onerror = (event) => {
        event.preventDefault();
        onFailure(new Error(event.message || 'the sandbox failed'));
      };
    },
    terminate: () => worker.terminate(),
  };
});
