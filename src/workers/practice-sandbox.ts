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
 *
 * It also counts the memory the solution's arrays take as they are made and grown, and stops the
 * solution past `MEMORY_LIMIT_MB`: a browser can neither limit nor measure a worker's memory, and a
 * worker that reaches the engine's own limit takes the whole page down with it.
 */
import { deserializeMesh, type SerializedMesh } from '../core/index.js';
import { BudgetError, type ExerciseInput, type PracticeBudget, runSolution, type RunOutput, type Solution, SOLUTION_FILE, SolutionError, solutionBody, solutionLine } from '../core/practice/index.js';

/** Memory a solution may use (its arrays, in the sandbox; the `grade` command's worker thread, in all). */
export const MEMORY_LIMIT_MB = 256;

export interface SandboxRequest {
  source: string;
  runs: { mesh: SerializedMesh; input: ExerciseInput | undefined }[];
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

/** What one value of an array takes, as an engine stores it uncompressed. */
const BYTES_PER_ELEMENT = 8;
/** Bytes of arrays the solution made or grew in its run on the current fixture (counted while `metering`). */
let allocated = 0;
let metering = false;

function charge(bytes: number): void {
  if (!metering) return;
  allocated += bytes;
  if (allocated > MEMORY_LIMIT_MB * 2 ** 20) throw new BudgetError(`your code used more than ${MEMORY_LIMIT_MB} MB of memory for arrays without returning: a list that keeps growing?`);
}

/**
 * Counts what the built-ins that make and grow arrays allocate: the constructors of arrays, typed
 * arrays and buffers, and the array methods that add elements or return a new array. An array
 * literal or a string escapes the count; code that keeps making those is stopped by time.
 */
function meterArrays(): void {
  const size = (value: unknown) => (Array.isArray(value) ? value.length * BYTES_PER_ELEMENT : ArrayBuffer.isView(value) || value instanceof ArrayBuffer ? value.byteLength : 0);
  const made = <T>(result: T) => (charge(size(result)), result);
  // before Array itself is wrapped: these make their array without calling the constructor again
  for (const name of ['from', 'of'] as const) {
    const make = Array[name] as (...args: unknown[]) => unknown[];
    Object.defineProperty(Array, name, { value: (...args: unknown[]) => made(make.apply(Array, args)), writable: true, configurable: true });
  }
  const global = globalThis as unknown as Record<string, object>;
  const typed = ['Int8Array', 'Uint8Array', 'Uint8ClampedArray', 'Int16Array', 'Uint16Array', 'Int32Array', 'Uint32Array', 'Float32Array', 'Float64Array', 'BigInt64Array', 'BigUint64Array'];
  for (const name of ['Array', 'ArrayBuffer', ...typed]) {
    global[name] = new Proxy(global[name] as (...args: unknown[]) => object, {
      apply: (target, self, args) => made(Reflect.apply(target, self, args)),
      construct: (target, args, newTarget) => made(Reflect.construct(target, args, newTarget)),
    });
  }
  const methods = Array.prototype as unknown as Record<string, (...args: unknown[]) => unknown>;
  for (const name of ['push', 'unshift']) {
    const grow = methods[name]!;
    methods[name] = function (this: unknown, ...items: unknown[]) {
      charge(items.length * BYTES_PER_ELEMENT);
      return Reflect.apply(grow, this, items);
    };
  }
  for (const name of ['concat', 'slice', 'map', 'filter', 'flat', 'flatMap']) {
    const make = methods[name]!;
    methods[name] = function (this: unknown, ...args: unknown[]) {
      return made(Reflect.apply(make, this, args));
    };
  }
}

/** Shuts every name in `SHUT` on the global object and its prototypes, and the constructors that compile strings, and meters arrays. */
export function lockDown(): void {
  meterArrays();
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
    const mesh = deserializeMesh(run.mesh);
    allocated = 0;
    metering = true;
    const output = runSolution(solution, mesh, run.input, lineOffset, request.budget);
    metering = false;
    send({ kind: 'output', index, output });
  });
  send({ kind: 'done' });
}
