/**
 * The library the benchmarks time: the built package's Node entry (`dist/node/index.js`, what
 * `import 'halfedge-lab'` gives a program in Node, its helper thread for subdivision included),
 * and its practice grader (`dist/core/practice`, which the `grade` command runs), both of which
 * `run.ts` builds before it measures. Timing the source instead measured another program:
 * run under the TypeScript loader, with no helper thread, it put decimation at 1.15 ×
 * meshoptimizer where the built package stood at 0.72–1.03 ×. The inputs are made with the source
 * (their making is not timed, and a polygon soup is plain arrays); everything timed, and every
 * mesh it is given, comes from here. The types are the source's, which the build compiles.
 */
import type * as Practice from '../src/core/practice/index.js';
import type * as Library from '../src/node/index.js';

const builtEntry = new URL('../dist/node/index.js', import.meta.url).href;
const built = (await import(builtEntry)) as typeof Library;

export const { buildMesh, cutMesh, decimate, meshByteLength, readMesh, smooth, subdivide, validate } = built;

const builtPractice = new URL('../dist/core/practice/index.js', import.meta.url).href;
const practice = (await import(builtPractice)) as typeof Practice;

export const { findExercise, fixtureMesh, gradeFixture, practiceMesh, replayWrites, solutionBody } = practice;
