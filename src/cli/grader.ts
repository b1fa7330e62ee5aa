/**
 * Grading a Gradescope submission against a course: for each exercise, the file the course names
 * is looked for in the submission and run on every fixture in a sandbox, and each check becomes a
 * test of Gradescope's `results.json`, the exercise's points shared among its checks (in
 * hundredths, so they add up to the points exactly). A test's `max_score` never depends on the
 * submission: a missing file or a solution that cannot load fails the same tests, each saying why.
 * `grader-main.ts` is the program around it, bundled into the autograder zip.
 */
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { checkNames, gradeSolution, type SolutionRunner, SolutionError } from '../core/practice/index.js';
import { type CourseExercise, loadCourse } from './course.js';

/** One test of `results.json`. */
export interface GradescopeTest {
  name: string;
  score: number;
  max_score: number;
  status: 'passed' | 'failed';
  output: string;
}

/** Gradescope's `results.json`: the score, a summary for the student, and the tests. */
export interface GradescopeResults {
  score: number;
  output: string;
  tests: GradescopeTest[];
}

/** `points` shared among `count` checks in hundredths of a point, the first ones a hundredth more where it does not divide. */
export function sharePoints(points: number, count: number): number[] {
  const total = Math.round(points * 100);
  const each = Math.floor(total / count);
  return Array.from({ length: count }, (_, i) => each + (i < total - each * count ? 1 : 0));
}

/** Grades the submission in the folder `submission` against the course file `coursePath`. */
export async function gradeCourse(coursePath: string, submission: string, run: SolutionRunner): Promise<GradescopeResults> {
  const { exercises } = loadCourse(coursePath);
  const tests: GradescopeTest[] = [];
  const summary: string[] = [];
  let scored = 0;
  for (const exercise of exercises) {
    const { earned, outputs, note } = await gradeExercise(exercise, submission, run);
    const { id } = exercise.exercise;
    const shares = sharePoints(exercise.entry.points, earned.length);
    let got = 0;
    checkNames(exercise.exercise).forEach((check, i) => {
      // in hundredths of a point: a hard case refused cleanly earns its share in part (PARTIAL_CREDIT)
      const score = Math.round(shares[i] * earned[i]);
      got += score;
      tests.push({ name: `${id}: ${check}`, score: score / 100, max_score: shares[i] / 100, status: earned[i] === 1 ? 'passed' : 'failed', output: outputs[i] });
    });
    scored += got;
    summary.push(`${id} (${exercise.entry.file}): ${got / 100} of ${exercise.entry.points} points${note ? `; ${note}` : ''}`);
  }
  return { score: scored / 100, output: summary.join('\n'), tests };
}

interface ExerciseOutcome {
  /** Per check, in the order of `checkNames`: the part of its share it earns, 0 … 1. */
  earned: number[];
  outputs: string[];
  /** For the summary line: why every check failed, or where the file was found. */
  note: string | null;
}

async function gradeExercise({ exercise, files, entry }: CourseExercise, submission: string, run: SolutionRunner): Promise<ExerciseOutcome> {
  const count = checkNames(exercise).length;
  const failAll = (message: string): ExerciseOutcome => ({ earned: Array(count).fill(0), outputs: Array(count).fill(message), note: message });
  const found = findSubmitted(submission, entry.file);
  if ('missing' in found) return failAll(found.missing);
  try {
    const report = await gradeSolution(exercise, readFileSync(found.path, 'utf8'), run, files);
    if (report.checks.length !== count) throw new Error(`${report.checks.length} checks ran where ${count} were expected`);
    return { earned: report.checks.map((c) => c.score), outputs: report.checks.map((c) => c.message), note: found.note };
  } catch (error) {
    if (error instanceof SolutionError) return failAll(`${entry.file}: ${error.message}`);
    // the autograder's own failure (a reference that fails its fixture): no points, and why, for the instructor too
    console.error(error);
    return failAll(`the autograder could not grade ${entry.file}: ${(error as Error).message} (please tell your instructor)`);
  }
}

/** Folders below the submission's top that are looked through for a file not at the top. */
const MAX_DEPTH = 4;

/**
 * The submitted file named `name`: at the top of the submission, or else the one file of that name
 * anywhere below it (a submission uploaded as a folder, or from a repository).
 */
export function findSubmitted(submission: string, name: string): { path: string; note: string | null } | { missing: string } {
  const top = join(submission, name);
  if (isFile(top)) return { path: top, note: null };
  const found: string[] = [];
  const walk = (folder: string, depth: number) => {
    let entries;
    try {
      entries = readdirSync(folder, { withFileTypes: true });
    } catch {
      return;
    }
    for (const entry of entries) {
      if (entry.name.startsWith('.') || entry.name === 'node_modules') continue;
      const path = join(folder, entry.name);
      if (entry.isDirectory() && depth < MAX_DEPTH) walk(path, depth + 1);
      else if (entry.isFile() && entry.name === name) found.push(path);
    }
  };
  walk(submission, 0);
  const shown = (path: string) => relative(submission, path).split('\\').join('/');
  if (found.length === 1) return { path: found[0], note: `graded ${shown(found[0])}` };
  if (found.length > 1) return { missing: `${found.length} files are named ${name} (${found.map(shown).sort().join(', ')}): keep one, at the top of your submission` };
  const given = topFiles(submission);
  return { missing: `your submission has no file named ${name}: submit this exercise's solution as ${name}${given.length ? ` (it has ${given.join(', ')})` : ' (it is empty)'}` };
}

function isFile(path: string): boolean {
  try {
    return statSync(path).isFile();
  } catch {
    return false;
  }
}

/** The first few names at the top of the submission, to show a student what was received. */
function topFiles(submission: string): string[] {
  try {
    const names = readdirSync(submission).filter((name) => !name.startsWith('.')).sort();
    return names.length > 8 ? [...names.slice(0, 8), `and ${names.length - 8} more`] : names;
  } catch {
    return [];
  }
}
