/** An exercise for `grade` and for a course: a built-in one by id, or an instructor's exercise file with the files it names. */
import { dirname, resolve } from 'node:path';
import { InvalidInputError } from '../core/errors.js';
import { type Exercise, exercises, findExercise, parseExercise } from '../core/practice/index.js';
import { readBytes, UsageError } from './io.js';

export interface LoadedExercise {
  exercise: Exercise;
  /** The bytes of the fixtures' mesh files, by the name each fixture gives. */
  files: Map<string, Uint8Array>;
  /** For an instructor's exercise: its file, and the names (relative to its folder) of the reference and fixture files it names. */
  source: { path: string; names: string[] } | null;
}

/**
 * A built-in exercise by id, or an instructor's exercise `.json` file with its reference and fixture files.
 * @throws UsageError naming the file and what is wrong in it.
 */
export function loadExercise(arg: string): LoadedExercise {
  const builtIn = findExercise(arg);
  if (builtIn) return { exercise: builtIn, files: new Map(), source: null };
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
    const fixtureFiles = [...new Set(exercise.fixtures.flatMap((f) => (f.file ? [f.file] : [])))];
    const files = new Map(fixtureFiles.map((name) => [name, readBytes(resolve(folder, name)) as Uint8Array]));
    return { exercise, files, source: { path: arg, names: [referencePath, ...fixtureFiles] } };
  } catch (error) {
    if (error instanceof InvalidInputError) throw new UsageError(`${arg}: ${error.message}`);
    throw error;
  }
}

export function readText(path: string): string {
  return new TextDecoder().decode(readBytes(path));
}
