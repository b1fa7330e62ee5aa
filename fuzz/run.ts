/**
 * `npm run fuzz -- [--count N] [--seed S] [--only NAME] [--jobs J] [--timeout-ms T] [--json]`
 * `npm run fuzz -- --only NAME --seed S --replay INDEX`
 *
 * Runs cases [0, N) of each fuzz target (`targets.ts`) in child processes, J at a time, and
 * watches them: a case that takes longer than T ms is a hang, and a child that dies (V8's fatal
 * errors, such as running out of its capped heap, cannot be caught in the process) is a crash;
 * either is recorded with its index and the child is started again from the next case. Prints a
 * line per target (cases, refused, accepted, failures, cases per second) and each failure with the
 * command that replays it, which runs that one case here and prints it in full. Exit status 1
 * when anything failed.
 *
 * `--target-module PATH` takes the targets from another module (its export `targets`), which is
 * how the runner's own test plants a hang and a crash.
 */
import { type ChildProcess, fork } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import type { CaseOutcome, FuzzTarget } from './target.js';

interface Options {
  count: number;
  seed: number;
  only: string | undefined;
  jobs: number;
  timeoutMs: number;
  json: boolean;
  replay: number | undefined;
  targetModule: string | undefined;
}

/** A failure as the runner reports it: from the target, or a hang or crash it saw. */
interface Failure {
  index: number;
  reason: string;
  input: string;
}

interface Summary {
  target: string;
  seed: number;
  cases: number;
  refused: number;
  accepted: number;
  failures: Failure[];
  casesPerSecond: number;
}

/** Parent → child: run cases [from, to) of one target. */
interface Job {
  targetModule: string | undefined;
  target: string;
  seed: number;
  from: number;
  to: number;
}

/** Child → parent, after each case: its index and outcome ('r' refused, 'a' accepted, or the failure). */
type Report = [index: number, outcome: 'r' | 'a' | Failure];

/** Heap cap of each child: an unbounded allocation is then a crash, not a machine swapping for an hour. */
const CHILD_HEAP_MB = 2048;

function usage(message: string): never {
  console.error(`fuzz: ${message}`);
  console.error('usage: npm run fuzz -- [--count N] [--seed S] [--only NAME] [--jobs J] [--timeout-ms T] [--json] [--replay INDEX]');
  process.exit(2);
}

function parseOptions(args: string[]): Options {
  const value = (flag: string): string | undefined => {
    const i = args.indexOf(flag);
    if (i < 0) return undefined;
    if (i + 1 >= args.length) usage(`${flag} needs a value`);
    return args[i + 1];
  };
  const integer = (flag: string, fallback: number, min: number): number => {
    const text = value(flag);
    if (text === undefined) return fallback;
    const n = Number(text);
    if (!Number.isSafeInteger(n) || n < min) usage(`${flag} must be a whole number ≥ ${min}, not '${text}'`);
    return n;
  };
  const replay = value('--replay');
  return {
    count: integer('--count', 10_000, 0),
    seed: integer('--seed', 1, -(2 ** 31)),
    only: value('--only'),
    jobs: integer('--jobs', 2, 1),
    timeoutMs: integer('--timeout-ms', 5000, 1),
    json: args.includes('--json'),
    replay: replay === undefined ? undefined : integer('--replay', 0, 0),
    targetModule: value('--target-module'),
  };
}

async function loadTargets(targetModule: string | undefined): Promise<FuzzTarget[]> {
  if (targetModule === undefined) return (await import('./targets.js')).targets;
  const module = (await import(pathToFileURL(path.resolve(targetModule)).href)) as { targets?: FuzzTarget[] };
  if (!Array.isArray(module.targets)) usage(`${targetModule} exports no 'targets' list`);
  return module.targets;
}

/** In a child: runs the job's cases, reporting each. */
async function runChild(job: Job): Promise<void> {
  const target = (await loadTargets(job.targetModule)).find((t) => t.name === job.target)!;
  for (let index = job.from; index < job.to; index++) {
    const outcome = await target.runCase(job.seed, index);
    const report: Report = [index, outcome.kind === 'failure' ? { index, reason: outcome.reason, input: outcome.input } : outcome.kind === 'refused' ? 'r' : 'a'];
    process.send!(report);
  }
  process.disconnect();
}

/**
 * Runs cases [0, count) of `target` in up to `jobs` children at a time, each taking the next slice
 * of the cases; restarts a child after a hang or a crash, from the case after it.
 */
function runTarget(target: string, options: Options, progress: (done: number, failures: number) => void): Promise<Summary> {
  const summary: Summary = { target, seed: options.seed, cases: 0, refused: 0, accepted: 0, failures: [], casesPerSecond: 0 };
  const started = performance.now();
  const slice = Math.max(1, Math.min(50_000, Math.ceil(options.count / (4 * options.jobs))));
  let nextFrom = 0;
  const takeSlice = (): [number, number] | null => {
    if (nextFrom >= options.count) return null;
    const from = nextFrom;
    nextFrom = Math.min(options.count, from + slice);
    return [from, nextFrom];
  };
  const self = fileURLToPath(import.meta.url);

  return new Promise((resolve) => {
    let running = 0;
    const start = (from: number, to: number) => {
      running++;
      const child: ChildProcess = fork(self, ['--child'], {
        execArgv: ['--import', 'tsx', `--max-old-space-size=${CHILD_HEAP_MB}`],
        stdio: ['ignore', 'ignore', 'pipe', 'ipc'],
      });
      let stderr = '';
      child.stderr!.on('data', (chunk: Buffer) => {
        stderr = (stderr + chunk.toString()).slice(-2000);
      });
      let next = from; // the case running now (or about to)
      let lastHeard = performance.now();
      let hung = false;
      const watchdog = setInterval(() => {
        if (performance.now() - lastHeard > options.timeoutMs) {
          hung = true;
          child.kill('SIGKILL');
        }
      }, Math.min(250, options.timeoutMs));
      child.on('message', ([index, outcome]: Report) => {
        lastHeard = performance.now();
        next = index + 1;
        summary.cases++;
        if (outcome === 'r') summary.refused++;
        else if (outcome === 'a') summary.accepted++;
        else summary.failures.push(outcome);
        if ((summary.cases & 0x3ff) === 0) progress(summary.cases, summary.failures.length);
      });
      child.on('exit', (code, signal) => {
        clearInterval(watchdog);
        running--;
        if (next < to) {
          // the case at `next` never reported: it hung, or it took the process down
          summary.cases++;
          const reason = hung
            ? `hang: no result within ${options.timeoutMs} ms`
            : `crash: the process ended (${signal ?? `exit code ${code}`}) during the case: ${stderr.trim().split('\n').slice(-6).join(' | ')}`;
          summary.failures.push({ index: next, reason, input: '(replay it to see the input)' });
          if (next + 1 < to) start(next + 1, to);
        }
        const more = takeSlice();
        if (more) start(...more);
        if (running === 0) {
          summary.casesPerSecond = Math.round(summary.cases / ((performance.now() - started) / 1000));
          summary.failures.sort((a, b) => a.index - b.index);
          resolve(summary);
        }
      });
      child.send({ targetModule: options.targetModule, target, seed: options.seed, from, to } satisfies Job);
    };
    for (let j = 0; j < options.jobs; j++) {
      const first = takeSlice();
      if (first) start(...first);
    }
    if (running === 0) resolve(summary);
  });
}

function replayCommand(target: string, options: Options, index: number): string {
  const module = options.targetModule ? ` --target-module ${options.targetModule}` : '';
  return `npm run fuzz -- --only ${target} --seed ${options.seed} --replay ${index}${module}`;
}

async function main(): Promise<void> {
  const args = process.argv.slice(2);
  if (args.includes('--child')) {
    process.once('message', (job: Job) => void runChild(job));
    return;
  }
  const options = parseOptions(args);
  const all = await loadTargets(options.targetModule);
  const chosen = options.only === undefined ? all : all.filter((t) => t.name === options.only);
  if (chosen.length === 0) usage(`no target named '${options.only}' (targets: ${all.map((t) => t.name).join(', ')})`);

  if (options.replay !== undefined) {
    if (chosen.length !== 1) usage('--replay needs --only NAME');
    const outcome: CaseOutcome = await chosen[0].runCase(options.seed, options.replay);
    console.log(JSON.stringify({ target: chosen[0].name, seed: options.seed, index: options.replay, ...outcome }, null, 2));
    process.exitCode = outcome.kind === 'failure' ? 1 : 0;
    return;
  }

  let failed = false;
  for (const target of chosen) {
    const summary = await runTarget(target.name, options, (done, failures) => {
      if (!options.json) process.stderr.write(`\r${target.name}: ${done} of ${options.count} cases, ${failures} failures `);
    });
    failed ||= summary.failures.length > 0;
    if (options.json) {
      console.log(JSON.stringify(summary));
      continue;
    }
    process.stderr.write('\r\x1b[K');
    const { cases, refused, accepted, failures, casesPerSecond } = summary;
    console.log(`${target.name}: ${cases} cases (seed ${options.seed}): ${refused} refused, ${accepted} accepted, ${failures.length} failures; ${casesPerSecond} cases/s`);
    for (const failure of failures) {
      console.log(`  FAIL case ${failure.index}: ${failure.reason}`);
      console.log(`    input: ${failure.input}`);
      console.log(`    replay: ${replayCommand(target.name, options, failure.index)}`);
    }
  }
  process.exitCode = failed ? 1 : 0;
}

await main();
