/**
 * An exercise: a task, starter code, hints, the meshes a solution is run on (fixtures) and the
 * reference it is compared with. The built-in ones are in `exercises.ts`; an instructor's is a
 * JSON file of the same shape whose reference is a solution's source (see docs/practice.md).
 */
import { buildMesh } from '../build.js';
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { readMesh } from '../io/read.js';
import * as shapes from '../shapes.js';
import { mergeSoups, type PolygonSoup } from '../soup.js';

/**
 * How a solution's return value is compared with the reference's:
 * - `exact`: the same value (numbers, booleans, arrays element by element);
 * - `cycle`: the same ids in the same cyclic order, starting anywhere;
 * - `vertex`: a vertex id, compared by where it is (the ids of new vertices may differ), or -1;
 * - `none`: the value is not looked at (an operation graded by the mesh it leaves).
 */
export type AnswerKind = 'exact' | 'cycle' | 'vertex' | 'none';

/** A query answers from the mesh and must leave it as it was; an edit changes it. */
export type ExerciseKind = 'query' | 'edit';

/** A generated shape: a function of `shapes.ts` and its arguments, e.g. `['disk', 2]`. */
export type ShapeCall = [name: ShapeName, ...args: number[]];

export const shapeNames = ['tetrahedron', 'cube', 'singleTriangle', 'fan', 'strip', 'annulus', 'disk', 'grid', 'torus', 'uvSphere'] as const;
export type ShapeName = (typeof shapeNames)[number];

export interface Fixture {
  /** Says what the case is about: "an interior edge", "a boundary vertex". */
  name: string;
  /** Generated shapes, each a component, laid side by side along x. */
  shapes?: ShapeCall[];
  /** A mesh file (PLY, OFF, OBJ, STL), relative to the exercise file. */
  file?: string;
  /** What the solution is called with (`undefined` for none). */
  input?: number;
}

/** The library's operation or query, applied to `mesh` (changed in place for an edit). */
export type ReferenceFunction = (mesh: HalfedgeMesh, input: number | undefined) => unknown;

export interface Exercise {
  id: string;
  title: string;
  kind: ExerciseKind;
  answer: AnswerKind;
  /** The task, as paragraphs of plain text. */
  task: string[];
  hints: string[];
  starter: string;
  fixtures: Fixture[];
  /** The library's own function, or the source of a solution that is right. */
  reference: ReferenceFunction | string;
}

export const MAX_FIXTURE_FACES = 2000;

/** The mesh of a fixture, built as a file would be (`files` holds the bytes of `fixture.file`). */
export function fixtureMesh(fixture: Fixture, files: ReadonlyMap<string, Uint8Array> = new Map()): HalfedgeMesh {
  let soup: PolygonSoup;
  if (fixture.file !== undefined) {
    const bytes = files.get(fixture.file);
    if (!bytes) throw new InvalidInputError(`fixture "${fixture.name}": the file ${fixture.file} was not given`);
    soup = readMesh(bytes, { fileName: fixture.file }).soup;
  } else {
    soup = sideBySide((fixture.shapes ?? []).map(shapeSoup));
  }
  const faces = soup.faceStarts.length - 1;
  if (faces < 1) throw new InvalidInputError(`fixture "${fixture.name}" has no faces: give it shapes or a file`);
  // a fixture is re-checked after every write a solution makes: it has to stay small
  if (faces > MAX_FIXTURE_FACES) throw new InvalidInputError(`fixture "${fixture.name}" has ${faces} faces; a fixture has at most ${MAX_FIXTURE_FACES}`);
  return buildMesh(soup).mesh;
}

function shapeSoup([name, ...args]: ShapeCall): PolygonSoup {
  if (!(shapeNames as readonly string[]).includes(name)) {
    throw new InvalidInputError(`unknown shape "${String(name)}" (known: ${shapeNames.join(', ')})`);
  }
  if (!args.every((a) => Number.isFinite(a) && Math.abs(a) <= 64)) {
    throw new InvalidInputError(`shape ${name}: its arguments must be numbers up to 64 (a fixture is small)`);
  }
  return (shapes[name] as (...a: number[]) => PolygonSoup)(...args);
}

/** The components one after another along x, each a unit apart from the last, as one soup. */
function sideBySide(soups: PolygonSoup[]): PolygonSoup {
  let x = 0;
  for (const soup of soups) {
    const p = soup.positions;
    let min = Infinity;
    let max = -Infinity;
    for (let i = 0; i < p.length; i += 3) {
      min = Math.min(min, p[i]);
      max = Math.max(max, p[i]);
    }
    const shift = x - min;
    for (let i = 0; i < p.length; i += 3) p[i] += shift;
    x += max - min + 1;
  }
  return soups.length === 1 ? soups[0] : mergeSoups(soups);
}

/**
 * An exercise from its JSON text, parsed (an instructor's file, see docs/practice.md), with the
 * reference solution's source read from the file its `reference` names.
 * @throws InvalidInputError naming the field that is missing or of the wrong kind.
 */
export function parseExercise(doc: unknown, referenceSource: string): Exercise {
  const bad = (field: string, what: string): never => {
    throw new InvalidInputError(`exercise: "${field}" ${what}`);
  };
  if (!doc || typeof doc !== 'object' || Array.isArray(doc)) bad('(document)', 'must be a JSON object');
  const d = doc as Record<string, unknown>;
  const text = (field: string) => (typeof d[field] === 'string' && d[field] ? (d[field] as string) : bad(field, 'must be a non-empty string'));
  const texts = (field: string) => (Array.isArray(d[field]) && (d[field] as unknown[]).every((t) => typeof t === 'string') ? (d[field] as string[]) : bad(field, 'must be a list of strings'));
  const kind = text('kind');
  if (kind !== 'query' && kind !== 'edit') bad('kind', 'must be "query" or "edit"');
  const answer = text('answer');
  if (!['exact', 'cycle', 'vertex', 'none'].includes(answer)) bad('answer', 'must be "exact", "cycle", "vertex" or "none"');
  if (!Array.isArray(d.fixtures) || d.fixtures.length === 0) bad('fixtures', 'must be a non-empty list');
  const fixtures = (d.fixtures as unknown[]).map((f, i): Fixture => {
    const where = `fixtures[${i}]`;
    if (!f || typeof f !== 'object') return bad(where, 'must be an object');
    const { name, shapes, file, input } = f as Record<string, unknown>;
    if (typeof name !== 'string' || !name) bad(`${where}.name`, 'must be a non-empty string');
    if (input !== undefined && (typeof input !== 'number' || !Number.isInteger(input))) bad(`${where}.input`, 'must be an integer id');
    if (file !== undefined) {
      if (typeof file !== 'string') bad(`${where}.file`, 'must be a file name');
      return { name: name as string, file: file as string, input: input as number | undefined };
    }
    const known = (name: unknown) => (shapeNames as readonly unknown[]).includes(name);
    const valid = Array.isArray(shapes) && shapes.length > 0 && shapes.every((s) => Array.isArray(s) && known(s[0]) && s.slice(1).every((a: unknown) => typeof a === 'number'));
    if (!valid) bad(`${where}.shapes`, `must be a list of shapes such as [["disk", 2]] (known: ${shapeNames.join(', ')}), or give "file"`);
    return { name: name as string, shapes: shapes as ShapeCall[], input: input as number | undefined };
  });
  return {
    id: text('id'),
    title: text('title'),
    kind: kind as ExerciseKind,
    answer: answer as AnswerKind,
    task: texts('task'),
    hints: d.hints === undefined ? [] : texts('hints'),
    starter: text('starter'),
    fixtures,
    reference: referenceSource,
  };
}
