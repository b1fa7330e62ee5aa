/**
 * Grading a solution on every fixture of an exercise. Where the solution runs is the caller's: the
 * page passes a runner that uses a sandbox worker, the CLI one that uses a worker thread; both
 * hand back one `RunOutput` per fixture, and everything else happens here, the same everywhere.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { type Exercise, fixtureMesh } from './exercise.js';
import { type Check, type FixtureResult, gradeFixture } from './grade.js';
import type { RunOutput } from './run.js';
import { replayWrites } from './writes.js';

export interface FixtureRun {
  mesh: HalfedgeMesh;
  input: number | undefined;
}

/**
 * Runs `source` on each fixture (in a sandbox) and says what each run did; rejects with a
 * `SolutionError` when the source cannot be run at all.
 */
export type SolutionRunner = (source: string, runs: FixtureRun[]) => Promise<RunOutput[]>;

export interface GradeReport {
  exercise: string;
  passed: boolean;
  checks: Check[];
  fixtures: (FixtureResult & { before: HalfedgeMesh; input: number | undefined })[];
}

export async function gradeSolution(exercise: Exercise, source: string, run: SolutionRunner, files?: ReadonlyMap<string, Uint8Array>): Promise<GradeReport> {
  const meshes = exercise.fixtures.map((fixture) => fixtureMesh(fixture, files));
  const runs = meshes.map((mesh, i) => ({ mesh, input: exercise.fixtures[i].input }));
  const outputs = await run(source, runs);
  const references = await referenceResults(exercise, runs, run);
  const fixtures = exercise.fixtures.map((fixture, i) => ({
    ...gradeFixture(exercise, fixture, meshes[i], outputs[i], references[i]),
    before: meshes[i],
    input: fixture.input,
  }));
  const checks = fixtures.flatMap((result) => result.checks);
  return { exercise: exercise.id, passed: checks.every((c) => c.passed), checks, fixtures };
}

/** What the reference answers and leaves on each fixture (the library's function, or a reference solution run like any other). */
async function referenceResults(exercise: Exercise, runs: FixtureRun[], run: SolutionRunner): Promise<{ value: unknown; mesh: HalfedgeMesh }[]> {
  const reference = exercise.reference;
  if (typeof reference === 'function') {
    return runs.map(({ mesh, input }) => {
      const copy = mesh.clone();
      return { value: reference(copy, input), mesh: copy };
    });
  }
  const outputs = await run(reference, runs);
  return outputs.map((output, i) => {
    if (output.error) throw new Error(`the exercise's reference fails on fixture "${exercise.fixtures[i].name}": ${output.error.message}`);
    return { value: output.value, mesh: replayWrites(runs[i].mesh.clone(), output.writes) };
  });
}
