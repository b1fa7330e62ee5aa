/**
 * The program inside a course's autograder zip, bundled with everything it needs into one ES
 * module for Node ≥ 20 (`grader.mjs`, by `vite.grader.config.ts`). `run_autograder` runs it with
 * no network: it grades `$AUTOGRADER_ROOT/submission/` (default root `/autograder`) against the
 * `course.json` beside it and writes `$AUTOGRADER_ROOT/results/results.json`. Started again as a
 * worker thread, the same file is the sandbox each solution runs in.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { isMainThread, workerData } from 'node:worker_threads';
import { selfEntry } from '../node/worker-entry.js';
import { sandboxRunner } from '../workers/practice-runner.js';
import { gradeCourse, type GradescopeResults } from './grader.js';
import { serveSandboxThread, workerSandbox } from './sandbox.js';

/** What the grader tells the copy of itself that it starts as a sandbox. */
const SANDBOX = 'halfedge-lab sandbox';

async function main(): Promise<number> {
  const root = process.env.AUTOGRADER_ROOT || '/autograder';
  const course = join(dirname(fileURLToPath(import.meta.url)), 'course.json');
  let results: GradescopeResults;
  try {
    results = await gradeCourse(course, join(root, 'submission'), sandboxRunner(workerSandbox(selfEntry(import.meta.url), SANDBOX)));
  } catch (error) {
    // the course itself is broken (it was checked when the zip was made): no tests, and why
    console.error(error);
    results = { score: 0, output: `the autograder could not run: ${(error as Error).message} (please tell your instructor)`, tests: [] };
  }
  mkdirSync(join(root, 'results'), { recursive: true });
  writeFileSync(join(root, 'results', 'results.json'), `${JSON.stringify(results, null, 2)}\n`);
  // the instructor sees this (Gradescope keeps stdout); the student sees results.json
  console.log(`${results.output}\nscore: ${results.score}`);
  return 0;
}

if (!isMainThread && workerData === SANDBOX) serveSandboxThread();
else if (isMainThread) main().then((status) => (process.exitCode = status));
