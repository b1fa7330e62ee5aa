import { dirname, resolve } from 'node:path';
import { Worker } from 'node:worker_threads';
import { InvalidInputError } from '../../core/errors.js';
import { checkNames, type Exercise, findExercise, exercises, type GradeReport, gradeSolution, parseExercise, SolutionError } from '../../core/practice/index.js';
import { type SandboxPort, sandboxRunner } from '../../workers/practice-runner.js';
import { MEMORY_LIMIT_MB } from '../../workers/practice-sandbox.js';
import { workerEntry } from '../../node/worker-entry.js';
import { parseOptions, readBytes, UsageError } from '../io.js';
import type { Command } from './index.js';


export const gradeCommand: Command = {
  usage: 'grade EXERCISE SOLUTION.js [--json] | grade --list',
  summary: 'run a practice solution (an exercise id or file); exit 0 all checks pass, 1 some fail, 2 it cannot load; --list prints the built-in exercise ids',
  async run(args) {
    if (args.length === 1 && args[0] === '--list') {
      for (const exercise of exercises) console.log(exercise.id);
      return 0;
    }
    const { values, positionals } = parseOptions(args, { json: { type: 'boolean' } }, 2);
    const [exerciseArg, solutionPath] = positionals as [string, string];
    const exercise = loadExercise(exerciseArg);
    const source = readText(solutionPath);
    let report: GradeReport;
    try {
      report = await gradeSolution(exercise.exercise, source, sandboxRunner(openWorkerSandbox), exercise.files);
    } catch (error) {
      if (!(error instanceof SolutionError)) throw error;
      if (values.json) console.log(JSON.stringify(gradescopeRefused(exercise.exercise, error.message), null, 2));
      throw new UsageError(`${solutionPath}: ${error.message}`);
    }
    if (values.json) console.log(JSON.stringify(gradescope(report), null, 2));
    else {
      const marks = { passed: 'pass', partial: 'PART', failed: 'FAIL' } as const;
      for (const check of report.checks) {
        const credit = check.status === 'partial' ? ` (${check.score} of a point)` : '';
        console.log(`${marks[check.status]}  ${check.name}${credit}${check.passed ? '' : `\n      ${check.message}`}`);
      }
      const passed = report.checks.filter((c) => c.passed).length;
      console.log(`${passed} of ${report.checks.length} checks pass; ${report.score} of ${report.maxScore} points`);
    }
    return report.passed ? 0 : 1;
  },
};

/**
 * A Gradescope `results.json`: one test per fixture and check, a point each. A check that earns
 * part of its point (a hard case refused cleanly) scores that part, e.g. 0.8; Gradescope knows
 * only "passed" and "failed", so it is "failed", and its output says it earned part.
 */
export function gradescope(report: GradeReport) {
  const tests = report.checks.map((check) => ({
    name: check.name,
    score: check.score,
    max_score: 1,
    status: check.passed ? 'passed' : 'failed',
    output: check.status === 'partial' ? `partial credit, ${check.score} of 1: ${check.message}` : check.message,
  }));
  return { score: report.score, max_score: report.maxScore, tests };
}

/** The same tests as `gradescope` would list, each failed with why the solution did not load: the same `max_score` either way. */
export function gradescopeRefused(exercise: Exercise, message: string) {
  const tests = checkNames(exercise).map((name) => ({ name, score: 0, max_score: 1, status: 'failed', output: message }));
  return { score: 0, max_score: tests.length, output: message, tests };
}

/** A built-in exercise by id, or an instructor's exercise file with its reference and fixture files. */
function loadExercise(arg: string): { exercise: Exercise; files: Map<string, Uint8Array> } {
  const builtIn = findExercise(arg);
  if (builtIn) return { exercise: builtIn, files: new Map() };
  if (!arg.endsWith('.json')) {
    throw new UsageError(`unknown exercise '${arg}' (built in: ${exercises.map((e) => e.id).join(', ')}; or give an exercise .json file)`);
  }
  let doc: unknown;
  try {
    doc = JSON.parse(readText(arg));
  } catch (error) {
    if (error instanceof UsageError) throw error;
    throw new UsageError(`${arg}: not JSON: ${(error as Error).message}`);
  }
  const folder = dirname(arg);
  const referencePath = (doc as { reference?: unknown })?.reference;
  if (typeof referencePath !== 'string') throw new UsageError(`${arg}: exercise: "reference" must name the reference solution's .js file`);
  try {
    const exercise = parseExercise(doc, readText(resolve(folder, referencePath)));
    const files = new Map(exercise.fixtures.filter((f) => f.file).map((f) => [f.file!, readBytes(resolve(folder, f.file!))]));
    return { exercise, files };
  } catch (error) {
    if (error instanceof InvalidInputError) throw new UsageError(`${arg}: ${error.message}`);
    throw error;
  }
}

function readText(path: string): string {
  return new TextDecoder().decode(readBytes(path));
}

const workerFile = workerEntry(import.meta.url, '../grade-worker');

function openWorkerSandbox(): SandboxPort {
  const worker = new Worker(workerFile.code, { eval: workerFile.eval, resourceLimits: { maxOldGenerationSizeMb: MEMORY_LIMIT_MB, maxYoungGenerationSizeMb: 32 }, stdout: true, stderr: true });
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
}
