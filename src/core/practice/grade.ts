/**
 * Grading one fixture from what the sandbox reported: the writes are replayed onto a copy of the
 * fixture (so nothing the solution did inside the sandbox is trusted but its log), the result is
 * validated and compared with the reference's, and when it is broken, the write after which the
 * first of its broken invariants began to fail is found (`brokenSince`, which re-runs after each
 * write only the checks that read what it wrote, so it is found at any size).
 *
 * ```
 *   writes:      w0   w1   w2   w3   w4   (end)
 *   next-prev:   ok   ok   BAD  ok   ok   ok      fixed again: a correct state in between, not blamed
 *   vertex-h:    ok   ok   ok   BAD  BAD  BAD     still broken at the end: first broken = w3
 * ```
 *
 * A hidden fixture is graded the same way, but what its checks say names nothing of its mesh (only
 * its rule), and its writes and reads are left out of the result. On a hidden fixture the library
 * handles, a solution that refuses cleanly (returns the exercise's `refusal` and changes nothing)
 * earns `PARTIAL_CREDIT` of each check, once every fixture that is shown passes.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { validate, type Violation } from '../validate.js';
import { brokenSince } from './broken-since.js';
import { compareAnswers, compareMeshes, compareTriangulation } from './compare.js';
import type { Exercise, ExerciseInput, Fixture } from './exercise.js';
import { checkProperties } from './properties.js';
import type { RunOutput } from './run.js';
import { whatToFix } from './what-to-fix.js';
import { describeWrite, type PracticeWrite, replayWrites } from './writes.js';

/**
 * `partial`: a hidden fixture (a hard case) the library handles, which the solution refused
 * cleanly (returned the exercise's `refusal` and left the mesh as it was): worth `PARTIAL_CREDIT`.
 */
export type CheckStatus = 'passed' | 'partial' | 'failed';

/** What a check refused cleanly on a hard case the library handles is worth, of its point. */
export const PARTIAL_CREDIT = 0.8;

export interface Check {
  /** "fixture name: what is checked". */
  name: string;
  /** True when the check passed in full (`status` is `passed`). */
  passed: boolean;
  status: CheckStatus;
  /** The part of its point the check earns: 1, `PARTIAL_CREDIT` or 0. */
  score: number;
  /** Why it failed, in words ('passed' when it passed); for a hidden fixture, never its ids, only its rule. */
  message: string;
  /** The check is on a hidden fixture: its mesh, input and writes are not shown. */
  hidden?: boolean;
}

/** The write after which an invariant that is still broken at the end first broke. */
export interface FirstBroken {
  /** Index in `writes`. */
  write: number;
  line: number | null;
  /** The invariant, in words ("next(h12) = h15 but prev(h15) = h11"). */
  invariant: string;
  elements: { halfedges: number[]; vertices: number[]; faces: number[] };
}

export interface FixtureResult {
  fixture: string;
  /** A hidden fixture: `writes`, `visits` and `firstBroken` are left empty, so nothing can show them. */
  hidden: boolean;
  checks: Check[];
  writes: PracticeWrite[];
  /** Halfedges the code read a pointer of, in order (the first `MAX_VISITS` of `reads`). */
  visits: number[];
  /** Pointer reads in all. */
  reads: number;
  firstBroken: FirstBroken | null;
  /** The mesh after the solution's writes. */
  after: HalfedgeMesh;
}

/**
 * What each fixture is checked for, by the kind of exercise: a query's answer; an edit's mesh
 * (valid) and result (as the library's, or, where there is no single right answer, the properties
 * the exercise asks for). A solution that cannot load fails the same checks, so an exercise is
 * always worth the same points.
 */
export function fixtureChecks(exercise: Exercise): readonly string[] {
  if (exercise.kind === 'query') return ['answer'];
  return ['valid mesh', exercise.compare === 'properties' ? 'properties held' : 'same as the library'];
}

/** The name of every check a graded run of `exercise` gives, in order. */
export function checkNames(exercise: Exercise): string[] {
  return exercise.fixtures.flatMap((fixture) => fixtureChecks(exercise).map((what) => `${fixture.name}: ${what}`));
}

/**
 * The checks of one fixture. `before` is the fixture's mesh (not changed); `reference` is what the
 * reference answered and left, and the fields it wrote in order (`inWriteOrder`), when known.
 * `partialCredit`: whether a hidden fixture the library handles and the solution refused cleanly
 * earns `PARTIAL_CREDIT` (it does once the solution passes every fixture that is not hidden:
 * refusing is worth something beside a working edit, not instead of one).
 */
export function gradeFixture(
  exercise: Exercise,
  fixture: Fixture,
  before: HalfedgeMesh,
  output: RunOutput,
  reference: { value: unknown; mesh: HalfedgeMesh; order?: readonly number[] },
  partialCredit = true,
): FixtureResult {
  const after = replayWrites(before.clone(), output.writes);
  const checks: Check[] = [];
  const [, outcome] = fixtureChecks(exercise);
  const check = (what: string, message: string | null) =>
    checks.push({ name: `${fixture.name}: ${what}`, passed: message === null, status: message === null ? 'passed' : 'failed', score: message === null ? 1 : 0, message: message ?? 'passed' });
  const failure = output.error ? describeError(output) : null;
  let firstBroken: FirstBroken | null = null;
  const refusal = exercise.refusal;
  // a clean refusal: the refusal returned and the mesh left as it was (up to ids)
  const refusedCleanly = exercise.kind === 'edit' && refusal !== undefined && !output.error && output.value === refusal && compareMeshes(after, before) === null;
  const libraryRefuses = refusal !== undefined && reference.value === refusal;

  if (exercise.kind === 'query') {
    const write = output.writes[0];
    check(
      'answer',
      failure ??
        (write ? `a query must leave the mesh as it is, but ${at(write.line)}wrote ${describeWrite(write)}` : null) ??
        compareAnswers(exercise.answer, output.value, reference.value, after, reference.mesh),
    );
  } else if (fixture.hidden && refusedCleanly && !libraryRefuses) {
    // a hard case refused cleanly that the library handles: part of the point, on both checks
    const refused = `your code refused this case cleanly (it returned ${String(refusal)} and left the mesh as it was), but the library does the edit`;
    for (const what of fixtureChecks(exercise)) {
      const name = `${fixture.name}: ${what}`;
      if (partialCredit) checks.push({ name, passed: false, status: 'partial', score: PARTIAL_CREDIT, message: `${refused}: ${PARTIAL_CREDIT} of the point` });
      else checks.push({ name, passed: false, status: 'failed', score: 0, message: `${refused} (a clean refusal earns ${PARTIAL_CREDIT} of the point once every fixture that is not hidden passes)` });
    }
  } else {
    const problems = validate(after, { limit: 50 });
    if (problems.length > 0) firstBroken = findFirstBroken(before, output.writes, problems);
    check('valid mesh', problems.length === 0 ? null : describeBroken(problems, firstBroken, output));
    const refusedNeedlessly = refusedCleanly && !libraryRefuses ? `your code returned ${String(refusal)} and changed nothing, but this case needs no refusing: the library does the edit` : null;
    check(outcome, failure ?? refusedNeedlessly ?? compareAnswers(exercise.answer, output.value, reference.value, after, reference.mesh) ?? compareResult(exercise, before, after, reference.mesh, fixture.input));
    // what to change, from the pointers the reference sets: not where the code threw (that comes
    // first), nor on a hidden fixture (it names ids), nor where more than one result is right (any
    // triangulation's diagonals, a remeshing or a simplification judged by its properties)
    const failed = checks.filter((c) => c.status === 'failed');
    const oneAnswer = (exercise.compare ?? 'mesh') === 'mesh';
    const hint = failed.length > 0 && !output.error && !fixture.hidden && oneAnswer ? whatToFix(before, after, output.writes, { mesh: reference.mesh, order: reference.order ?? [] }) : null;
    if (hint) for (const c of failed) c.message += `. To fix: ${hint}`;
  }
  if (fixture.hidden) {
    for (const c of checks) {
      c.hidden = true;
      // a clean refusal's message names no element; any other is said again without ids
      const why = refusedCleanly && !libraryRefuses ? c.message : hiddenFailure(c, output, refusal, libraryRefuses);
      if (c.status !== 'passed') c.message = `${why}. A hidden case: ${fixture.rule ?? 'its mesh is not shown'}`;
    }
    return { fixture: fixture.name, hidden: true, checks, writes: [], visits: [], reads: 0, firstBroken: null, after };
  }
  return { fixture: fixture.name, hidden: false, checks, writes: output.writes, visits: output.visits, reads: output.reads, firstBroken, after };
}

/** Null when the mesh an edit left is right, as the exercise compares it, else the first difference. */
function compareResult(exercise: Exercise, before: HalfedgeMesh, after: HalfedgeMesh, reference: HalfedgeMesh, input: ExerciseInput | undefined): string | null {
  switch (exercise.compare ?? 'mesh') {
    case 'mesh':
      return compareMeshes(after, reference);
    case 'triangulation':
      return compareTriangulation(after, reference, before);
    case 'properties':
      return checkProperties(after, before, input, exercise.bounds!);
  }
}

/** What went wrong on a hidden fixture, without an id of its mesh (nor a value that would give one away). */
function hiddenFailure(check: Check, output: RunOutput, refusal: -1 | false | undefined, libraryRefuses: boolean): string {
  const error = output.error;
  if (error) {
    const where = error.line === null ? '' : ` at line ${error.line}`;
    return error.name === 'BudgetError' ? `your code was stopped${where}: it went past its budget of time, pointer reads, new elements or memory` : error.name === 'NotRun' ? error.message : `your code threw ${error.name}${where}`;
  }
  if (check.name.endsWith(': valid mesh')) return 'the mesh your code left breaks an invariant';
  if (check.name.endsWith(': answer')) return output.writes.length > 0 ? 'a query must leave the mesh as it is, but your code wrote to it' : "your answer is not the library's";
  if (libraryRefuses) return `the library refuses this case, but your code did not return ${String(refusal)} and leave the mesh as it was`;
  return check.name.endsWith(': properties held') ? 'your result lacks a property the exercise asks for' : "your result is not the library's";
}

function at(line: number | null): string {
  return line === null ? '' : `line ${line} `;
}

function describeError(output: RunOutput): string {
  const error = output.error!;
  const where = error.line === null ? '' : ` at line ${error.line}`;
  if (error.name === 'BudgetError') return `stopped${where}: ${error.message}`;
  if (error.name === 'PracticeApiError') return `${error.message}${where}`;
  if (error.name === 'NotRun') return error.message;
  return `your code threw ${error.name}${where}: ${error.message}`;
}

function describeBroken(problems: Violation[], first: FirstBroken | null, output: RunOutput): string {
  const more = problems.length > 1 ? ` (${problems.length >= 50 ? '50 or more' : problems.length} invariants are broken in all)` : '';
  if (!first) return `the mesh it leaves breaks an invariant: ${problems[0].message}${more}${output.error ? '; the code stopped before its end' : ''}`;
  const write = output.writes[first.write];
  return `the mesh it leaves breaks an invariant: ${first.invariant}, since write ${first.write + 1}, ${describeWrite(write)}${first.line === null ? '' : ` at line ${first.line}`}${more}`;
}

/**
 * The write after which the earliest of the `final` violations began its last unbroken stretch of
 * failing (the first of them, in `validate`'s order, among those that began at the same write).
 * `final` is not empty. Null when one of them was failing before the first write (or there are none).
 */
export function findFirstBroken(before: HalfedgeMesh, writes: readonly PracticeWrite[], final: Violation[]): FirstBroken | null {
  const since = brokenSince(before, writes, final);
  let first = 0;
  for (let k = 1; k < final.length; k++) if (since[k] < since[first]) first = k;
  if (since[first] < 0) return null;
  const violation = final[first];
  return {
    write: since[first],
    line: writes[since[first]].line,
    invariant: violation.message,
    elements: { halfedges: violation.halfedges ?? [], vertices: violation.vertices ?? [], faces: violation.faces ?? [] },
  };
}
