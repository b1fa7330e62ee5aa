/**
 * The inside of a practice sandbox: a worker (a browser worker, or a Node worker thread for the
 * `grade` command) that compiles a student's solution and runs it on each fixture it is sent,
 * answering with plain data after each one, so the side that watches the clock knows how far it got.
 *
 * Before any student code runs, the worker shuts what a solution has no business touching: the
 * network (`fetch`, `XMLHttpRequest`, `WebSocket`, …), new code from strings (`eval`, the
 * `Function` constructors), other workers, timers, messaging, and Node's `process` and `require`.
 * Each becomes a getter that throws a sentence naming it, so the student sees the line that tried.
 * There is no DOM in a worker: `document` is simply not defined.
 */
import { deserializeMesh, type SerializedMesh } from '../core/index.js';
import { type PracticeBudget, runSolution, type RunOutput, type Solution, SOLUTION_FILE, SolutionError, solutionBody, solutionLine } from '../core/practice/index.js';

export interface SandboxRequest {
  source: string;
  runs: { mesh: SerializedMesh; input: number | undefined }[];
  budget?: PracticeBudget;
}

export type SandboxMessage =
  | { kind: 'output'; index: number; output: RunOutput }
  | { kind: 'refused'; message: string; line: number | null }
  | { kind: 'done' };

// taken before the lock-down: the sandbox's own way to compile the solution
const compile = Function;

const SHUT = [
  'fetch', 'XMLHttpRequest', 'WebSocket', 'WebTransport', 'EventSource', 'importScripts', 'indexedDB', 'caches',
  'BroadcastChannel', 'MessageChannel', 'Worker', 'SharedWorker', 'postMessage', 'close', 'onmessage',
  'setTimeout', 'setInterval', 'queueMicrotask', 'requestAnimationFrame', 'eval',
  'process', 'require', 'module', 'Buffer', 'global', 'navigator', 'location',
];

function shut(target: object, name: string): void {
  try {
    Object.defineProperty(target, name, {
      get() {
        throw new Error(`${name} is not available to a solution: it runs with only the mesh API, no network, no page`);
      },
      set() {},
      configurable: false,
    });
  } catch {
    // a property that cannot be redefined stays as the engine has it; the worker is thrown away after the run
  }
}

/** Shuts every name in `SHUT` on the global object and its prototypes, and the constructors that compile strings. */
export function lockDown(): void {
  for (let target: object | null = globalThis; target && target !== Object.prototype; target = Object.getPrototypeOf(target)) {
    for (const name of SHUT) if (target === globalThis || Object.hasOwn(target, name)) shut(target, name);
  }
  const generator = function* () {};
  const asyncFunction = async function () {};
  const asyncGenerator = async function* () {};
  for (const f of [compile, generator, asyncFunction, asyncGenerator]) shut(Object.getPrototypeOf(f), 'constructor');
}

/** Lines the engine puts before a compiled body, measured once (2 in V8: `function anonymous(` and `) {`). */
const lineOffset = (() => {
  try {
    compile(`throw new Error();\n//# sourceURL=${SOLUTION_FILE}`)();
  } catch (error) {
    return (solutionLine((error as Error).stack, 0) ?? 1) - 1;
  }
  return 0;
})();

function compileSolution(source: string): Solution {
  const body = solutionBody(source);
  let exported: unknown;
  try {
    exported = compile(body)();
  } catch (error) {
    // the module's own top level threw (it ran while being loaded)
    throw new SolutionError(`the module throws while loading: ${(error as Error).message}`, solutionLine((error as Error).stack, lineOffset));
  }
  if (typeof exported !== 'function') throw new SolutionError(`the default export is ${exported === null ? 'null' : typeof exported}, not a function`, null);
  return exported as Solution;
}

/** Answers one request: compiles, runs on every fixture in turn, and says each output as it comes. */
export function serveRequest(request: SandboxRequest, send: (message: SandboxMessage) => void): void {
  let solution: Solution;
  try {
    solution = compileSolution(request.source);
  } catch (error) {
    const line = error instanceof SolutionError ? error.line : null;
    const message = error instanceof SolutionError ? error.message.replace(/^line \d+: /, '') : String(error);
    send({ kind: 'refused', message, line });
    return;
  }
  request.runs.forEach((run, index) => {
    const output = runSolution(solution, deserializeMesh(run.mesh), run.input, lineOffset, request.budget);
    send({ kind: 'output', index, output });
  });
  send({ kind: 'done' });
}
