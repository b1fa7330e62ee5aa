/**
 * Grading a practice trace: the writes of one level of Loop subdivision on a fixture of `size`
 * triangles (a grid, as an exercise file would give it), made by the exercise's reference solution
 * (`tests/practice/solutions/loop-subdivision.js`, about 75 writes a triangle), with one of the
 * last `next` writes set wrong, so that the first broken write is searched through all of them.
 * What is timed is `gradeFixture`: the writes replayed, the result validated, the first broken
 * write found, the mesh compared with the library's and what to fix said.
 *
 * The peer is one `validate` of the mesh the writes leave, so the ratio says how many whole
 * validations the grading costs. The search it replaced validated after every write: a million
 * validations at 20,000 triangles, which it did not attempt (it gave up past 20M halfedge-writes).
 *
 * The trace is made in `prepare`, by the solution against the mesh API with no line lookup: the
 * sandbox's stack trace per write is most of a run's time, and none of the grading's. A fixture
 * has at most `MAX_FIXTURE_FACES` faces, so the case runs at the sizes up to that only.
 */
import { readFileSync } from 'node:fs';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { type Fixture, MAX_FIXTURE_FACES, type PracticeWrite, type RunOutput, type Solution } from '../../src/core/practice/index.js';
import type { BenchCase } from '../harness.js';
import { findExercise, fixtureMesh, gradeFixture, practiceMesh, replayWrites, solutionBody, validate } from '../library.js';

const SOLUTION = new URL('../../tests/practice/solutions/loop-subdivision.js', import.meta.url);

export function practiceCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    if (size > MAX_FIXTURE_FACES) return [];
    const side = Math.round(Math.sqrt(size / 2));
    const exercise = findExercise('loop-subdivision')!;
    const fixture: Fixture = { name: `a grid of ${2 * side * side} triangles`, shapes: [['grid', side, side]] };
    let before: HalfedgeMesh;
    let output: RunOutput;
    let reference: { value: unknown; mesh: HalfedgeMesh };
    let after: HalfedgeMesh;
    return [
      {
        case: 'practice-trace',
        size: 2 * side * side,
        prepare() {
          before = fixtureMesh(fixture);
          output = spoiledTrace(before);
          const mesh = before.clone();
          reference = { value: (exercise.reference as (m: HalfedgeMesh) => unknown)(mesh), mesh };
          after = replayWrites(before.clone(), output.writes);
        },
        run: () => {
          const result = gradeFixture(exercise, fixture, before, output, reference);
          if (!result.firstBroken) throw new Error('practice-trace: the spoiled write was not found');
          return result;
        },
        peer: { name: 'validate once', run: () => validate(after) },
      },
    ];
  });
}

/** The reference solution's writes on `before` (left as it was), the last `next` write made to point at its own halfedge. */
function spoiledTrace(before: HalfedgeMesh): RunOutput {
  const solution = new Function(solutionBody(readFileSync(SOLUTION, 'utf8')))() as Solution;
  const unlimited = { reads: Infinity, milliseconds: Infinity, newElements: Infinity };
  const { api, trace } = practiceMesh(before.clone(), () => null, unlimited);
  solution(Object.freeze(api), undefined);
  let last = trace.writes.length - 1;
  while (trace.writes[last].field !== 'next') last--;
  const write = trace.writes[last] as Extract<PracticeWrite, { new: number }>;
  trace.writes[last] = { ...write, new: write.index };
  return { ...trace, value: undefined, error: null };
}
