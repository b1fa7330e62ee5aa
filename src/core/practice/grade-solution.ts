/**
 * Grading a solution on every fixture of an exercise. Where the solution runs is the caller's: the
 * page passes a runner that uses a sandbox worker, the CLI one that uses a worker thread; both
 * hand back one `RunOutput` per fixture, and everything else happens here, the same everywhere.
 */
import { inWriteOrder } from '../change/recorder.js';
import type { HalfedgeMesh } from '../mesh.js';
import { type Exercise, type ExerciseInput, fixtureMesh, frozenInput } from './exercise.js';
import { type Check, type FixtureResult, gradeFixture } from './grade.js';
import type { RunOutput } from './run.js';
import { writeOrderOf } from './what-to-fix.js';
import { replayWrites } from './writes.js';

export interface FixtureRun {
  mesh: HalfedgeMesh;
  input: ExerciseInput | undefined;
}

/**
 * Runs `source` on each fixture (in a sandbox) and says what each run did; rejects with a
 * `SolutionError` when the source cannot be run at all.
 */
export type SolutionRunner = (source: string, runs: FixtureRun[]) => Promise<RunOutput[]>;

export interface GradeReport {
  exercise: string;
  /** Every check passed in full. */
  passed: boolean;
  /** The points earned: a point per check passed, `PARTIAL_CREDIT` per check partly earned. */
  score: number;
  /** A point per check, whatever the solution did (`checkNames(exercise).length`). */
  maxScore: number;
  checks: Check[];
  /** Per fixture; a hidden one's `input` is left out, as are its writes and reads (see `FixtureResult`). */
  fixtures: (FixtureResult & { before: HalfedgeMesh; input: ExerciseInput | undefined })[];
}

export async function gradeSolution(exercise: Exercise, source: string, run: SolutionRunner, files?: ReadonlyMap<string, Uint8Array>): Promise<GradeReport> {
  return gradeOn(exercise, exercise.fixtures.map((fixture) => fixtureMesh(fixture, files)), source, run);
}

/**
 * Grades `source` on a mesh that is no fixture of the exercise (the mesh in the app's view, when
 * the student's code does the app's edits: "Use my code"), as a fixture that is shown is graded.
 */
export function gradeOnMesh(exercise: Exercise, source: string, run: SolutionRunner, mesh: HalfedgeMesh, input: ExerciseInput | undefined, name: string): Promise<GradeReport> {
  return gradeOn({ ...exercise, fixtures: [{ name, input }] }, [mesh], source, run);
}

/** Grades `source` on the exercise's fixtures, whose meshes are `meshes` (not changed). */
async function gradeOn(exercise: Exercise, meshes: HalfedgeMesh[], source: string, run: SolutionRunner): Promise<GradeReport> {
  // each run gets its own copy of the input, so that code which changes it changes nothing else
  const runsOf = () => meshes.map((mesh, i) => ({ mesh, input: frozenInput(exercise.fixtures[i].input) }));
  const outputs = await run(source, runsOf());
  const references = await referenceResults(exercise, runsOf(), run);
  // the fixtures shown first: a hard case refused cleanly earns part of its point only beside them all passing
  const graded = (i: number, partialCredit = true) => ({
    ...gradeFixture(exercise, exercise.fixtures[i], meshes[i], outputs[i], references[i], partialCredit),
    before: meshes[i],
    input: exercise.fixtures[i].hidden ? undefined : exercise.fixtures[i].input,
  });
  const shown = new Map(exercise.fixtures.flatMap((fixture, i) => (fixture.hidden ? [] : [[i, graded(i)] as const])));
  const shownPass = [...shown.values()].every((result) => result.checks.every((c) => c.passed));
  const fixtures = exercise.fixtures.map((_, i) => shown.get(i) ?? graded(i, shownPass));
  const checks = fixtures.flatMap((result) => result.checks);
  // summed in hundredths, so that five checks of 0.8 make 4, not 4.000000000000001
  const score = Math.round(checks.reduce((sum, c) => sum + c.score, 0) * 100) / 100;
  return { exercise: exercise.id, passed: checks.every((c) => c.passed), score, maxScore: checks.length, checks, fixtures };
}

/**
 * What the reference answers and leaves on each fixture (the library's function, or a reference
 * solution run like any other), and the fields it wrote, in order.
 */
async function referenceResults(exercise: Exercise, runs: FixtureRun[], run: SolutionRunner): Promise<{ value: unknown; mesh: HalfedgeMesh; order: number[] }[]> {
  const reference = exercise.reference;
  if (typeof reference === 'function') {
    return runs.map(({ mesh, input }) => {
      const copy = mesh.clone();
      const { value, fields } = inWriteOrder(copy, () => reference(copy, input));
      return { value, mesh: copy, order: fields };
    });
  }
  const outputs = await run(reference, runs);
  return outputs.map((output, i) => {
    if (output.error) throw new Error(`the exercise's reference fails on fixture "${exercise.fixtures[i].name}": ${output.error.message}`);
    return { value: output.value, mesh: replayWrites(runs[i].mesh.clone(), output.writes), order: writeOrderOf(output.writes) };
  });
}
