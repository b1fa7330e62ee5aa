/**
 * A course: the exercises of one Gradescope assignment, each with the name of the file a
 * submission gives for it and the points it is worth. Built-in exercises go by id; an
 * instructor's by the path of its `.json` file, relative to the course file:
 *
 * ```json
 * { "exercises": [
 *     { "id": "flip-edge", "file": "flip-edge.js", "points": 6 },
 *     { "exercise": "my/boundary-edges/exercise.json", "file": "boundary.js", "points": 4 } ] }
 * ```
 *
 * Every mistake is reported with its JSON path (`exercises[2].points: must be a positive number`).
 * `halfedge-lab autograder` reads a course; the grader inside the zip reads the copy it holds.
 */
import { dirname, join } from 'node:path';
import { InvalidInputError, ParseError } from '../core/errors.js';
import { checkNames, exercises, findExercise, fixtureMesh } from '../core/practice/index.js';
import { type LoadedExercise, loadExercise, readText } from './exercise-file.js';
import { UsageError } from './io.js';

export interface CourseEntry {
  /** A built-in exercise's id (this or `exercise`). */
  id?: string;
  /** An instructor's exercise file, relative to the course file. */
  exercise?: string;
  /** The name of the solution's file in a submission. */
  file: string;
  /** What the exercise is worth; its checks share it. */
  points: number;
}

export interface Course {
  exercises: CourseEntry[];
}

export interface CourseExercise extends LoadedExercise {
  entry: CourseEntry;
}

const COURSE_FIELDS = ['exercises'];
const ENTRY_FIELDS = ['id', 'exercise', 'file', 'points'];

/**
 * Checks a parsed course file's shape. `name`: the course file, which each message starts with.
 * @throws UsageError `name: path: what is wrong`, e.g. `course.json: exercises[2].points: must be a positive number`.
 */
export function parseCourse(doc: unknown, name: string): Course {
  const bad = (path: string, what: string): never => {
    throw new UsageError(`${name}: ${path}: ${what}`);
  };
  const isObject = (value: unknown): value is Record<string, unknown> => typeof value === 'object' && value !== null && !Array.isArray(value);
  if (!isObject(doc)) return bad('(document)', 'must be a JSON object such as { "exercises": [...] }');
  for (const key of Object.keys(doc)) if (!COURSE_FIELDS.includes(key)) bad(key, 'unknown field (a course has "exercises")');
  const list = doc.exercises;
  if (!Array.isArray(list) || list.length === 0) bad('exercises', 'must be a non-empty list of exercises');
  const fileOf = new Map<string, number>();
  const entries = (list as unknown[]).map((item, i): CourseEntry => {
    const at = `exercises[${i}]`;
    if (!isObject(item)) return bad(at, 'must be an object such as { "id": "flip-edge", "file": "flip-edge.js", "points": 6 }');
    for (const key of Object.keys(item)) if (!ENTRY_FIELDS.includes(key)) bad(`${at}.${key}`, 'unknown field (an exercise has "id" or "exercise", "file" and "points")');
    const { id, exercise, file, points } = item;
    // which exercise: one of the two
    if ((id === undefined) === (exercise === undefined)) bad(at, 'give "id" (a built-in exercise) or "exercise" (an exercise .json file), one of the two');
    if (id !== undefined && (typeof id !== 'string' || !findExercise(id))) {
      bad(`${at}.id`, `unknown exercise ${JSON.stringify(id)} (built in: ${exercises.map((e) => e.id).join(', ')})`);
    }
    if (exercise !== undefined && (typeof exercise !== 'string' || !exercise.endsWith('.json'))) {
      bad(`${at}.exercise`, 'must be the path of an exercise .json file, relative to the course file');
    }
    // the file a submission gives: a plain name, looked for in the submission
    if (typeof file !== 'string' || !/^[^/\\]+$/.test(file) || file === '.' || file === '..') {
      bad(`${at}.file`, 'must be a file name such as "flip-edge.js", without a folder');
    }
    const earlier = fileOf.get(file as string);
    if (earlier !== undefined) bad(`${at}.file`, `"${file}" is already the file of exercises[${earlier}]: each exercise needs a file of its own`);
    fileOf.set(file as string, i);
    if (typeof points !== 'number' || !Number.isFinite(points) || points <= 0) bad(`${at}.points`, 'must be a positive number');
    // shared among the checks in hundredths of a point, so totals add up exactly
    if (Math.abs(Math.round((points as number) * 100) - (points as number) * 100) > 1e-6) bad(`${at}.points`, 'must be a positive number in hundredths at most, such as 2.5');
    return id !== undefined ? { id: id as string, file: file as string, points: points as number } : { exercise: exercise as string, file: file as string, points: points as number };
  });
  return { exercises: entries };
}

/**
 * Reads a course file and every exercise it names: an instructor's with its reference and fixture
 * files, which must lie beside it or below (the autograder copies that folder), and each fixture's
 * mesh built once, so a broken one is reported now rather than when students submit.
 * @throws UsageError with the course file, the JSON path and what is wrong.
 */
export function loadCourse(path: string): { course: Course; exercises: CourseExercise[] } {
  let doc: unknown;
  try {
    doc = JSON.parse(readText(path));
  } catch (error) {
    if (error instanceof UsageError) throw error;
    throw new UsageError(`${path}: not JSON: ${(error as Error).message}`);
  }
  const course = parseCourse(doc, path);
  const idOf = new Map<string, number>();
  const loaded = course.exercises.map((entry, i): CourseExercise => {
    const at = `exercises[${i}]${entry.id !== undefined ? '.id' : '.exercise'}`;
    const bad = (what: string): never => {
      throw new UsageError(`${path}: ${at}: ${what}`);
    };
    let exercise: LoadedExercise;
    try {
      exercise = loadExercise(entry.id ?? join(dirname(path), entry.exercise!));
    } catch (error) {
      if (error instanceof UsageError) bad(error.message);
      throw error;
    }
    for (const name of exercise.source?.names ?? []) {
      if (name.includes('\\')) bad(`${exercise.source!.path}: "${name}": use / between folders`);
      if (name.startsWith('/') || /^[A-Za-z]:/.test(name) || name.split('/').includes('..')) bad(`${exercise.source!.path}: "${name}" must be beside the exercise file or in a folder below it`);
    }
    const { id } = exercise.exercise;
    const earlier = idOf.get(id);
    if (earlier !== undefined) bad(`the exercise "${id}" is already exercises[${earlier}]: each exercise once`);
    idOf.set(id, i);
    const checks = checkNames(exercise.exercise).length;
    if (Math.round(entry.points * 100) < checks) {
      throw new UsageError(`${path}: exercises[${i}].points: ${entry.points} cannot be shared among the exercise's ${checks} checks in hundredths: give it ${checks / 100} or more`);
    }
    for (const fixture of exercise.exercise.fixtures) {
      try {
        fixtureMesh(fixture, exercise.files);
      } catch (error) {
        const where = exercise.source?.path ?? id;
        if (error instanceof ParseError) bad(`${where}: fixture "${fixture.name}": ${fixture.file}: ${error.message}`);
        if (error instanceof InvalidInputError) bad(`${where}: ${error.message}`);
        throw error;
      }
    }
    return { ...exercise, entry };
  });
  return { course, exercises: loaded };
}
