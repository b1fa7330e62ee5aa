import { checkNames, type Exercise, exercises, type GradeReport, gradeSolution, SolutionError } from '../../core/practice/index.js';
import { sandboxRunner } from '../../workers/practice-runner.js';
import { workerEntry } from '../../node/worker-entry.js';
import { loadExercise, readText } from '../exercise-file.js';
import { parseOptions, UsageError } from '../io.js';
import { workerSandbox } from '../sandbox.js';
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

const openWorkerSandbox = workerSandbox(workerEntry(import.meta.url, '../grade-worker'));
