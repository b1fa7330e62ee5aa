/**
 * Running a solution on one fixture, as the sandbox does: the function is called with the traced
 * mesh API and the fixture's input, and what comes back is plain data (the value, the writes, the
 * halfedges read, the error), which the grader checks outside the sandbox.
 */
import type { HalfedgeMesh } from '../mesh.js';
import { type ExerciseInput, frozenInput } from './exercise.js';
import { budgetFor, type PracticeBudget, type PracticeMesh, practiceMesh, type PracticeTrace } from './mesh-api.js';
import { currentSolutionLine, solutionLine } from './source.js';

export type Solution = (mesh: PracticeMesh, input: ExerciseInput | undefined) => unknown;

/** An error the solution's run ended with, at its line when the stack names one. */
export interface RunError {
  /** `Error`, `TypeError`, `BudgetError` (a budget ran out), `PracticeApiError` (a wrong use of the API), … */
  name: string;
  message: string;
  line: number | null;
}

export interface RunOutput extends PracticeTrace {
  /** The returned value, as structured data (functions and the like become their text). */
  value: unknown;
  error: RunError | null;
}

/**
 * Runs `solution` on `mesh` (changed in place by its writes). `lineOffset` is the number of lines
 * the engine puts before the compiled body (see `solutionLine`).
 */
export function runSolution(solution: Solution, mesh: HalfedgeMesh, input: ExerciseInput | undefined, lineOffset: number, budget: PracticeBudget = budgetFor(mesh)): RunOutput {
  const lineOf = () => currentSolutionLine(lineOffset);
  const { api, trace } = practiceMesh(mesh, lineOf, budget);
  try {
    const value = plain(solution(Object.freeze(api), frozenInput(input)));
    return { ...trace, value, error: null };
  } catch (error) {
    return { ...trace, value: undefined, error: runError(error, lineOffset) };
  }
}

function runError(error: unknown, lineOffset: number): RunError {
  if (error instanceof Error) {
    return { name: error.name, message: error.message, line: solutionLine(error.stack, lineOffset) };
  }
  return { name: 'Error', message: `your code threw ${String(error)}`, line: null };
}

/** The value as data that crosses a worker boundary and compares as JSON. */
function plain(value: unknown): unknown {
  if (value === undefined || value === null || typeof value === 'number' || typeof value === 'boolean' || typeof value === 'string') return value;
  if (Array.isArray(value)) return value.slice(0, 100_000).map(plain);
  return String(value);
}
