/**
 * An exercise: a task, starter code, hints, the meshes a solution is run on (fixtures) and the
 * reference it is compared with. The built-in ones are in `exercises.ts`; an instructor's is a
 * JSON file of the same shape whose reference is a solution's source (see docs/practice.md).
 */
import { buildMesh } from '../build.js';
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { readMesh } from '../io/read.js';
import { encodeText } from '../io/text.js';
import * as shapes from '../shapes.js';
import { mergeSoups, type PolygonSoup } from '../soup.js';
import type { ResultBounds } from './properties.js';

/**
 * How a solution's return value is compared with the reference's:
 * - `exact`: the same value (numbers, booleans, arrays element by element);
 * - `cycle`: the same ids in the same cyclic order, starting anywhere;
 * - `vertex`: a vertex id, compared by where it is (the ids of new vertices may differ), or -1;
 * - `face`: a face id, compared by where its corners are, in order (the ids of new faces may differ), or -1;
 * - `none`: the value is not looked at (an operation graded by the mesh it leaves).
 */
export type AnswerKind = 'exact' | 'cycle' | 'vertex' | 'face' | 'none';

export const answerKinds: readonly AnswerKind[] = ['exact', 'cycle', 'vertex', 'face', 'none'];

/**
 * How the mesh an edit leaves is compared with the library's:
 * - `mesh`: the same mesh up to ids (vertices by position, faces and holes by their corners);
 * - `triangulation`: the same vertices and holes, every face the library cut cut into triangles
 *   along any diagonals that do not fold over (so any correct triangulation passes, not only the
 *   library's ear clipping), and every face it left as it was left so;
 * - `properties`: not compared with the library's at all, for an operation with no single right
 *   answer (remeshing, simplification): triangles, the input's topology, and the exercise's
 *   `bounds` (see `properties.ts`).
 */
export type MeshComparison = 'mesh' | 'triangulation' | 'properties';

export const meshComparisons: readonly MeshComparison[] = ['mesh', 'triangulation', 'properties'];

/**
 * What a solution is called with: an element id (`7`), a list of ids (two edges to weld, `[3, 8]`),
 * or named numbers (`{ face: 3, offset: 0.5, inset: 0.25 }`).
 */
export type ExerciseInput = number | readonly number[] | { readonly [name: string]: number };

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
  /** A small mesh written out in OFF, for a shape no generator makes (a face with no area, a pentagon). */
  off?: string;
  /** What the solution is called with (`undefined` for none). */
  input?: ExerciseInput;
  /**
   * A hard case graded without showing it: the student sees whether it passed and its `rule`, never
   * its mesh, its input or its writes. Where the library does the edit and the solution refuses it
   * cleanly (see `Exercise.refusal`), its checks earn part of their point (`PARTIAL_CREDIT`).
   */
  hidden?: boolean;
  /** For a hidden fixture: the rule it checks, in one sentence ("a boundary vertex is bevelled too"). */
  rule?: string;
}

/** The library's operation or query, applied to `mesh` (changed in place for an edit). */
export type ReferenceFunction = (mesh: HalfedgeMesh, input: ExerciseInput | undefined) => unknown;

export interface Exercise {
  id: string;
  /** Older ids that still find this exercise (`poke-face` for `inset-vertex`). */
  aliases?: string[];
  title: string;
  kind: ExerciseKind;
  answer: AnswerKind;
  /**
   * What an edit returns when it does not apply (-1, or `false` for one that answers true or
   * false). A solution that returns it and leaves the mesh as it was has *refused cleanly*; on a
   * hidden fixture the library handles, that earns part of the point (see `Fixture.hidden`).
   */
  refusal?: -1 | false;
  /** How the mesh an edit leaves is compared (default `mesh`). */
  compare?: MeshComparison;
  /** What a result compared by `properties` must reach. */
  bounds?: ResultBounds;
  /** The task, as paragraphs of plain text. */
  task: string[];
  hints: string[];
  starter: string;
  fixtures: Fixture[];
  /** The library's own function, or the source of a solution that is right. */
  reference: ReferenceFunction | string;
}

/**
 * The most faces a fixture may have: enough for a subdivision level on a real mesh. Grading costs
 * about what the solution's writes do (the first broken write is found from the checks each write
 * touched, vertices are matched through a grid), and the sandbox's budgets grow with the fixture
 * (`budgetFor`); what stays large is the run itself, a minute or so for a Loop level on 20,000 faces.
 */
export const MAX_FIXTURE_FACES = 20_000;

/** The largest argument of a generated shape: a side long enough for a shape of `MAX_FIXTURE_FACES` faces (a torus of 140 × 140 quads); the faces are counted after. */
const MAX_SHAPE_ARGUMENT = 150;

/** The mesh of a fixture, built as a file would be (`files` holds the bytes of `fixture.file`). */
export function fixtureMesh(fixture: Fixture, files: ReadonlyMap<string, Uint8Array> = new Map()): HalfedgeMesh {
  let soup: PolygonSoup;
  if (fixture.file !== undefined) {
    const bytes = files.get(fixture.file);
    if (!bytes) throw new InvalidInputError(`fixture "${fixture.name}": the file ${fixture.file} was not given`);
    soup = readMesh(bytes, { fileName: fixture.file }).soup;
  } else if (fixture.off !== undefined) {
    soup = readMesh(encodeText(fixture.off), { fileName: 'fixture.off' }).soup;
  } else {
    soup = sideBySide((fixture.shapes ?? []).map(shapeSoup));
  }
  const faces = soup.faceStarts.length - 1;
  if (faces < 1) throw new InvalidInputError(`fixture "${fixture.name}" has no faces: give it shapes or a file`);
  if (faces > MAX_FIXTURE_FACES) throw new InvalidInputError(`fixture "${fixture.name}" has ${faces} faces; a fixture has at most ${MAX_FIXTURE_FACES}`);
  return buildMesh(soup).mesh;
}

/** A fixture's input as the panel and the history label say it: `7`, `[3, 8]`, `{ face: 3, offset: 0.5 }`. */
export function describeInput(input: ExerciseInput | undefined): string {
  if (input === undefined) return 'no input';
  if (typeof input === 'number') return String(input);
  if (Array.isArray(input)) return `[${input.join(', ')}]`;
  return `{ ${Object.entries(input).map(([name, value]) => `${name}: ${value}`).join(', ')} }`;
}

/** The input as a solution gets it: a copy it cannot change (the reference gets its own). */
export function frozenInput(input: ExerciseInput | undefined): ExerciseInput | undefined {
  if (input === undefined || typeof input === 'number') return input;
  return Object.freeze(Array.isArray(input) ? [...input] : { ...input });
}

function isInput(value: unknown): value is ExerciseInput {
  const id = (x: unknown) => typeof x === 'number' && Number.isInteger(x);
  if (id(value)) return true;
  if (Array.isArray(value)) return value.length > 0 && value.every(id);
  return !!value && typeof value === 'object' && Object.values(value).length > 0 && Object.values(value).every((x) => typeof x === 'number' && Number.isFinite(x));
}

function shapeSoup([name, ...args]: ShapeCall): PolygonSoup {
  if (!(shapeNames as readonly string[]).includes(name)) {
    throw new InvalidInputError(`unknown shape "${String(name)}" (known: ${shapeNames.join(', ')})`);
  }
  if (!args.every((a) => Number.isFinite(a) && Math.abs(a) <= MAX_SHAPE_ARGUMENT)) {
    throw new InvalidInputError(`shape ${name}: its arguments must be numbers up to ${MAX_SHAPE_ARGUMENT} (a fixture has at most ${MAX_FIXTURE_FACES.toLocaleString('en')} faces)`);
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
  if (!(answerKinds as readonly string[]).includes(answer)) bad('answer', `must be ${answerKinds.map((a) => `"${a}"`).join(', ')}`);
  if (d.refusal !== undefined && d.refusal !== -1 && d.refusal !== false) bad('refusal', 'must be -1 or false: what the solution returns when the edit does not apply');
  if (d.compare !== undefined && !(meshComparisons as readonly unknown[]).includes(d.compare)) bad('compare', `must be ${meshComparisons.map((c) => `"${c}"`).join(', ')}`);
  if (d.compare === 'properties') parseBounds(d.bounds, bad);
  else if (d.bounds !== undefined) bad('bounds', 'is for "compare": "properties" only');
  if (!Array.isArray(d.fixtures) || d.fixtures.length === 0) bad('fixtures', 'must be a non-empty list');
  const fixtures = (d.fixtures as unknown[]).map((f, i): Fixture => {
    const where = `fixtures[${i}]`;
    if (!f || typeof f !== 'object') return bad(where, 'must be an object');
    const { name, shapes, file, off, input, hidden, rule } = f as Record<string, unknown>;
    if (typeof name !== 'string' || !name) bad(`${where}.name`, 'must be a non-empty string');
    if (input !== undefined && !isInput(input)) bad(`${where}.input`, 'must be an integer id, a list of ids ([3, 8]) or named numbers ({ "face": 3, "offset": 0.5 })');
    if (hidden !== undefined && typeof hidden !== 'boolean') bad(`${where}.hidden`, 'must be true or false');
    if (hidden === true && (typeof rule !== 'string' || !rule)) bad(`${where}.rule`, 'must say, in a sentence, the rule a hidden fixture checks (the student sees it, not the mesh)');
    if (rule !== undefined && typeof rule !== 'string') bad(`${where}.rule`, 'must be a sentence');
    const common = { name: name as string, input: input as ExerciseInput | undefined, ...(hidden ? { hidden: true, rule: rule as string } : rule ? { rule: rule as string } : {}) };
    if (file !== undefined) {
      if (typeof file !== 'string') bad(`${where}.file`, 'must be a file name');
      return { ...common, file: file as string };
    }
    if (off !== undefined) {
      if (typeof off !== 'string' || !off) bad(`${where}.off`, 'must be the text of a mesh in OFF');
      return { ...common, off: off as string };
    }
    const known = (name: unknown) => (shapeNames as readonly unknown[]).includes(name);
    const valid = Array.isArray(shapes) && shapes.length > 0 && shapes.every((s) => Array.isArray(s) && known(s[0]) && s.slice(1).every((a: unknown) => typeof a === 'number'));
    if (!valid) bad(`${where}.shapes`, `must be a list of shapes such as [["disk", 2]] (known: ${shapeNames.join(', ')}), or give "file" or "off"`);
    return { ...common, shapes: shapes as ShapeCall[] };
  });
  if (fixtures.every((f) => f.hidden)) bad('fixtures', 'must have one that is not hidden, for the student to see what the exercise is about');
  return {
    id: text('id'),
    title: text('title'),
    kind: kind as ExerciseKind,
    answer: answer as AnswerKind,
    ...(d.refusal !== undefined ? { refusal: d.refusal as -1 | false } : {}),
    ...(d.compare !== undefined ? { compare: d.compare as MeshComparison } : {}),
    ...(d.bounds !== undefined ? { bounds: d.bounds as ResultBounds } : {}),
    task: texts('task'),
    hints: d.hints === undefined ? [] : texts('hints'),
    starter: text('starter'),
    fixtures,
    reference: referenceSource,
  };
}

/** Checks the `bounds` of an exercise graded by properties: shares in (0, 1], at least one target. */
function parseBounds(bounds: unknown, bad: (field: string, what: string) => never): void {
  if (!bounds || typeof bounds !== 'object' || Array.isArray(bounds)) bad('bounds', 'must be an object such as { "shareNearTarget": 0.6, "maxDistance": 0.02 }');
  const b = bounds as Record<string, unknown>;
  const share = (x: unknown) => typeof x === 'number' && x > 0 && x <= 1;
  if (!share(b.maxDistance)) bad('bounds.maxDistance', 'must be a share of the input\'s size, above 0 and at most 1');
  for (const name of ['shareNearTarget', 'shareOfTargetFaces']) {
    if (b[name] !== undefined && !share(b[name])) bad(`bounds.${name}`, 'must be a share, above 0 and at most 1');
  }
  const known = ['maxDistance', 'shareNearTarget', 'shareOfTargetFaces'];
  const unknown = Object.keys(b).find((name) => !known.includes(name));
  if (unknown) bad(`bounds.${unknown}`, `is not a bound (known: ${known.join(', ')})`);
}
