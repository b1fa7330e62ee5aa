/**
 * The outside of a practice sandbox: sends a solution and its fixtures to a fresh sandbox worker,
 * and watches the clock. A worker that has not answered a fixture `HARD_MARGIN_MS` past the
 * fixture's time budget (`budgetFor`, which grows with the fixture) is terminated (code that loops
 * without reading the mesh cannot be stopped any other way), the fixture is reported as stopped,
 * and a new worker takes the fixtures left. Works with the
 * browser's `Worker` and Node's worker threads through `SandboxPort`. The fixtures after one that
 * had to be terminated are not run (they would most likely spin too, each for the whole limit).
 */
import { serializeMesh } from '../core/index.js';
import { budgetFor } from '../core/practice/mesh-api.js';
import type { FixtureRun, SolutionRunner } from '../core/practice/grade-solution.js';
import type { RunOutput } from '../core/practice/run.js';
import { SolutionError } from '../core/practice/solution-error.js';
import type { SandboxMessage, SandboxRequest } from './practice-sandbox.js';

/** What the runner needs of a worker. */
export interface SandboxPort {
  post(request: SandboxRequest): void;
  /** Calls back with each message, and with an Error when the worker dies (out of memory, a crash). */
  listen(onMessage: (message: SandboxMessage) => void, onFailure: (error: Error) => void): void;
  terminate(): void;
}

/** This long past the sandbox's own time budget (checked as the code reads), the worker is terminated. */
export const HARD_MARGIN_MS = 500;

export function sandboxRunner(openSandbox: () => SandboxPort, hardMarginMs = HARD_MARGIN_MS): SolutionRunner {
  return async (source, runs) => {
    const outputs: RunOutput[] = [];
    while (outputs.length < runs.length) {
      const { done, stopped } = await runSome(openSandbox(), source, runs.slice(outputs.length), hardMarginMs);
      outputs.push(...done);
      if (stopped?.terminated) {
        outputs.push(stopped.output);
        const notRun = stoppedOutput('not run: your code did not return on an earlier fixture, so the others were not tried', 'NotRun');
        while (outputs.length < runs.length) outputs.push(notRun);
      } else if (stopped) outputs.push(stopped.output);
    }
    return outputs;
  };
}

function stoppedOutput(message: string, name = 'BudgetError'): RunOutput {
  return { writes: [], visits: [], reads: 0, value: undefined, error: { name, message, line: null } };
}

interface SomeRun {
  done: RunOutput[];
  /** The fixture the worker stopped on: it overran (`terminated`) or the worker died. */
  stopped: { output: RunOutput; terminated: boolean } | null;
}

/** Runs fixtures in one worker until they are done, or one of them overruns or kills the worker. */
function runSome(port: SandboxPort, source: string, runs: FixtureRun[], hardMarginMs: number): Promise<SomeRun> {
  return new Promise((resolve, reject) => {
    const done: RunOutput[] = [];
    let timer: ReturnType<typeof setTimeout>;
    const finish = (stopped: SomeRun['stopped']) => {
      clearTimeout(timer);
      port.terminate();
      resolve({ done, stopped });
    };
    // the clock of the fixture the worker is on now
    const arm = () => {
      clearTimeout(timer);
      const hardLimitMs = budgetFor(runs[done.length].mesh).milliseconds + hardMarginMs;
      const message = `your code ran for ${hardLimitMs / 1000} s without returning and without reading the mesh, so it was stopped: a loop whose condition never changes?`;
      timer = setTimeout(() => finish({ output: stoppedOutput(message), terminated: true }), hardLimitMs);
    };
    port.listen(
      (message) => {
        if (message.kind === 'refused') {
          clearTimeout(timer);
          port.terminate();
          reject(new SolutionError(message.message, message.line));
        } else if (message.kind === 'output') {
          done.push(message.output);
          if (done.length < runs.length) arm();
        } else {
          finish(null);
        }
      },
      (error) => finish({ output: stoppedOutput(`your code was stopped: ${error.message}`), terminated: false }),
    );
    arm();
    port.post({ source, runs: runs.map(({ mesh, input }) => ({ mesh: serializeMesh(mesh), input })) });
  });
}
