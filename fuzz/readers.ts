/**
 * The reader fuzzer: real files of every format, mutated — bytes flipped or set to telling values,
 * pieces cut, repeated or moved, number tokens put in, header counts and names edited — must each
 * either raise a `ParseError` that says where (a line, a byte offset, or a path in the JSON) or
 * read into a soup the builder makes a valid mesh of, which then saves and reads back to the same
 * mesh (`reload.ts`). Anything else is a failure: another exception, a refusal that names no
 * place, an invalid mesh, a round trip that changed it; a hang or a crash is the runner's to see
 * (`run.ts`), as it cannot be caught here.
 *
 * Two targets: `readers` mutates files the library writes itself (every format and encoding, with
 * attributes), so its cases mean the same everywhere; `corpus` mutates the small real-world files
 * of `../shared/corpus` when they are there (a case names its file, so it replays while the
 * corpus is unchanged). Halfedge JSON is mutated as a document, field by field.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { buildMesh } from '../src/core/build.js';
import { ParseError } from '../src/core/errors.js';
import { meshFromHalfedgeJSON, meshToHalfedgeJSON } from '../src/core/io/halfedge-json.js';
import { concatBytes } from '../src/core/io/output.js';
import { readMesh } from '../src/core/io/read.js';
import { meshToSoup, writeSoup } from '../src/core/io/write.js';
import { writePly } from '../src/core/io/write-ply.js';
import { seededRandom } from '../src/core/random.js';
import { cube, fan, tetrahedron } from '../src/core/shapes.js';
import { validate } from '../src/core/validate.js';
import { reloadDifference } from './reload.js';
import { type CaseOutcome, caseSeed, type FuzzTarget } from './target.js';

export interface Sample {
  name: string;
  bytes: Uint8Array;
}

const encoder = new TextEncoder();

/** Files of every format and encoding, as the library writes them, and a few written by hand. */
export function builtInSamples(): Sample[] {
  const { mesh } = buildMesh(cube());
  mesh.vertexAttributes.add('color', 'uint8', 3).data.fill(128);
  mesh.vertexAttributes.add('normal', 'float32', 3).data.fill(0.5);
  mesh.faceAttributes.add('color', 'float32', 4).data.fill(0.5);
  mesh.halfedgeAttributes.add('texcoord', 'float32', 2).data.fill(0.25);
  const soup = meshToSoup(mesh);
  const fanSoup = fan(4);
  const text = (name: string, source: string) => ({ name, bytes: encoder.encode(source) });
  return [
    { name: 'cube.ply', bytes: writeSoup(soup, 'ply') },
    { name: 'cube-le.ply', bytes: writeSoup(soup, 'ply-binary') },
    { name: 'cube-be.ply', bytes: writePly(soup, 'binary_big_endian') },
    { name: 'cube.off', bytes: writeSoup(soup, 'off') },
    { name: 'cube.obj', bytes: writeSoup(soup, 'obj') },
    { name: 'tetra.off', bytes: writeSoup(tetrahedron(), 'off') },
    { name: 'fan.ply', bytes: writePly(fanSoup, 'binary_little_endian') },
    text(
      'strip.ply',
      'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n' +
        'element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 1 2 -1 3\n',
    ),
    text('colours.off', 'COFF\n# a square\n4 2 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n1 1 0 0 0 1 1\n0 1 0 1 1 1 1\n3 0 1 2 255 0 0\n3 0 2 3 0 255 0\n'),
    text('negative.obj', 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nf -4/-3/-1 -3/-2/-1 -2/-1/-1 -1/-1/-1\n'),
    text('two.stl', 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n'),
    { name: 'two-binary.stl', bytes: binaryStl() },
    { name: 'cube.json', bytes: encoder.encode(JSON.stringify(meshToHalfedgeJSON(mesh))) },
  ];
}

/** Two triangles of a unit square, as binary STL. */
function binaryStl(): Uint8Array {
  const triangles = [
    [0, 0, 0, 1, 0, 0, 0, 1, 0],
    [1, 0, 0, 1, 1, 0, 0, 1, 0],
  ];
  const bytes = new Uint8Array(84 + 50 * triangles.length);
  const view = new DataView(bytes.buffer);
  view.setUint32(80, triangles.length, true);
  triangles.forEach((corners, t) => corners.forEach((x, k) => view.setFloat32(84 + 50 * t + 12 + 4 * k, x, true)));
  return bytes;
}

/** The corpus's small PLY, OFF and OBJ files (under 4 KB), sorted by name; none when it is absent. */
export function corpusSamples(directory = path.resolve(import.meta.dirname, '../../shared/corpus')): Sample[] {
  if (!existsSync(directory)) return [];
  return readdirSync(directory)
    .filter((name) => /\.(ply|off|coff|obj|stl)$/i.test(name) && statSync(path.join(directory, name)).size < 4096)
    .sort()
    .map((name) => ({ name, bytes: new Uint8Array(readFileSync(path.join(directory, name))) }));
}

/** Values that find the edges of a reader: zero, huge, negative, out of every integer range, not numbers. */
const numberTokens = ['0', '-1', '-0', '1e308', '-1e308', '5e38', '1e-320', 'NaN', 'nan', 'inf', '-Infinity', '2147483647', '2147483648', '4294967296', '9007199254740993', '0x10', '1.5', '', '1e', '--1'];
/** Names that are members of every plain object. */
const objectNames = ['constructor', '__proto__', 'toString', 'hasOwnProperty', 'valueOf', 'prototype'];
const telling = [0, 0xff, 0x0a, 0x0d, 0x20, 0x2d, 0x30, 0x39, 0x23, 0x7f, 0x80];

type Random = () => number;
const below = (rand: Random, n: number) => Math.floor(rand() * n);

/** One mutation of a file's bytes; each says what it did, for the replay line. */
const mutations: Array<(bytes: Uint8Array, rand: Random) => [Uint8Array, string]> = [
  (bytes, rand) => {
    const out = bytes.slice();
    const at = below(rand, out.length);
    out[at] ^= 1 << below(rand, 8);
    return [out, `flip a bit at byte ${at}`];
  },
  (bytes, rand) => {
    const out = bytes.slice();
    const at = below(rand, out.length);
    out[at] = telling[below(rand, telling.length)];
    return [out, `set byte ${at} to ${out[at]}`];
  },
  (bytes, rand) => {
    const end = below(rand, bytes.length + 1);
    return [bytes.slice(0, end), `cut at byte ${end}`];
  },
  (bytes, rand) => {
    const [from, to] = range(bytes, rand);
    return [concatBytes([bytes.subarray(0, from), bytes.subarray(to)]), `delete bytes ${from}..${to}`];
  },
  (bytes, rand) => {
    const [from, to] = range(bytes, rand);
    return [concatBytes([bytes.subarray(0, to), bytes.subarray(from, to), bytes.subarray(to)]), `repeat bytes ${from}..${to}`];
  },
  (bytes, rand) => {
    const [from, to] = range(bytes, rand);
    return [concatBytes([bytes.subarray(0, from), bytes.subarray(to), bytes.subarray(from, to)]), `move bytes ${from}..${to} to the end`];
  },
  (bytes, rand) => {
    // replace one whitespace-separated token by a telling number
    const tokens = tokenSpans(bytes);
    if (tokens.length === 0) return [bytes, 'no token to replace'];
    const [from, to] = tokens[below(rand, tokens.length)];
    const token = numberTokens[below(rand, numberTokens.length)];
    return [concatBytes([bytes.subarray(0, from), encoder.encode(token), bytes.subarray(to)]), `token at byte ${from} → '${token}'`];
  },
  (bytes, rand) => {
    // a header count (the first few numbers) made huge or wrong
    const numbers = tokenSpans(bytes).filter(([from, to]) => /^\d+$/.test(latin1(bytes.subarray(from, to)))).slice(0, 6);
    if (numbers.length === 0) return [bytes, 'no count to edit'];
    const [from, to] = numbers[below(rand, numbers.length)];
    const count = ['0', '1', '2147483648', '4294967295', String(below(rand, 50))][below(rand, 5)];
    return [concatBytes([bytes.subarray(0, from), encoder.encode(count), bytes.subarray(to)]), `count at byte ${from} → ${count}`];
  },
  (bytes, rand) => {
    // a word (a type, element, property or keyword) renamed to a member of every object
    const words = tokenSpans(bytes).filter(([from, to]) => /^[a-z_]+$/i.test(latin1(bytes.subarray(from, to))));
    if (words.length === 0) return [bytes, 'no word to rename'];
    const [from, to] = words[below(rand, words.length)];
    const name = objectNames[below(rand, objectNames.length)];
    return [concatBytes([bytes.subarray(0, from), encoder.encode(name), bytes.subarray(to)]), `word at byte ${from} → ${name}`];
  },
];

function range(bytes: Uint8Array, rand: Random): [number, number] {
  const a = below(rand, bytes.length + 1);
  const b = Math.min(bytes.length, a + 1 + below(rand, 64));
  return [a, b];
}

function latin1(bytes: Uint8Array): string {
  return String.fromCharCode(...bytes.subarray(0, 64));
}

/** Byte spans of the whitespace-separated tokens in the first 4 KB (text formats and headers). */
function tokenSpans(bytes: Uint8Array): Array<[number, number]> {
  const spans: Array<[number, number]> = [];
  const end = Math.min(bytes.length, 4096);
  for (let i = 0; i < end; ) {
    while (i < end && bytes[i] <= 0x20) i++;
    const from = i;
    while (i < end && bytes[i] > 0x20) i++;
    if (i > from) spans.push([from, i]);
  }
  return spans;
}

/** One mutation of a halfedge-JSON document: a field set to a telling value, removed, or renamed. */
function mutateDocument(doc: unknown, rand: Random): string {
  const paths: Array<[Record<string, unknown> | unknown[], string | number]> = [];
  const walk = (value: unknown) => {
    if (paths.length > 5000 || value === null || typeof value !== 'object') return;
    for (const key of Object.keys(value)) {
      const container = value as Record<string, unknown>;
      paths.push([container, Array.isArray(value) ? Number(key) : key]);
      walk(container[key]);
    }
  };
  walk(doc);
  if (paths.length === 0) return 'nothing to change';
  const [container, key] = paths[below(rand, paths.length)];
  const record = container as Record<string | number, unknown>;
  const values: unknown[] = [null, -1, 0, 1e300, 2 ** 31, 1.5, 'x', [], {}, true, Number.MAX_SAFE_INTEGER];
  const choice = below(rand, 3);
  if (choice === 0) {
    record[key] = values[below(rand, values.length)];
    return `${String(key)} → ${JSON.stringify(record[key])}`;
  }
  if (choice === 1 && !Array.isArray(container)) {
    delete record[key];
    return `${String(key)} removed`;
  }
  if (!Array.isArray(container)) {
    const name = objectNames[below(rand, objectNames.length)];
    Object.defineProperty(record, name, { value: record[key], enumerable: true, configurable: true, writable: true });
    delete record[key];
    return `${String(key)} renamed ${name}`;
  }
  container.splice(key as number, 1);
  return `item ${String(key)} removed`;
}

/** At most this many bytes of a failing input go into its replay line, as base64. */
const MAX_INPUT_BYTES = 8192;

/** How one input ended: refused (with a place), accepted (and every check after held), or a failure. */
export type CheckOutcome = { kind: 'refused'; reason: string } | { kind: 'accepted' } | { kind: 'failure'; reason: string };

/** A `ParseError` is a refusal when it says where (its line, byte offset or JSON path), else a failure. */
export function refusal(error: ParseError): CheckOutcome {
  const { line, byteOffset, path } = error.location;
  if (line === undefined && byteOffset === undefined && path === undefined) return { kind: 'failure', reason: `refused without saying where: ${error.message}` };
  return { kind: 'refused', reason: error.message };
}

/** Runs one mutated input through reading, building, validation and reload; a failure's reason, or the outcome. */
export function checkInput(name: string, bytes: Uint8Array): CheckOutcome {
  try {
    let mesh;
    if (name.endsWith('.json')) {
      // the text itself, so that a refusal names its line and column
      mesh = meshFromHalfedgeJSON(new TextDecoder().decode(bytes));
      // the document is read as it is, broken or not; what it holds must write back the same
      const again = meshFromHalfedgeJSON(JSON.parse(JSON.stringify(meshToHalfedgeJSON(mesh))));
      if (JSON.stringify(meshToHalfedgeJSON(again)) !== JSON.stringify(meshToHalfedgeJSON(mesh))) {
        return { kind: 'failure', reason: 'halfedge JSON read back differently from what it wrote' };
      }
      return { kind: 'accepted' };
    }
    const file = readMesh(bytes, { fileName: name });
    mesh = buildMesh(file.soup).mesh;
    const problems = validate(mesh, { limit: 3 });
    if (problems.length > 0) return { kind: 'failure', reason: `built an invalid mesh: ${problems.map((p) => p.message).join('; ')}` };
    const difference = reloadDifference(mesh);
    if (difference) return { kind: 'failure', reason: `accepted, but saved and read back: ${difference}` };
    return { kind: 'accepted' };
  } catch (error) {
    if (error instanceof ParseError) return refusal(error);
    return { kind: 'failure', reason: `threw ${(error as Error)?.stack ?? String(error)}` };
  }
}

/** Case (seed, index) of a reader fuzzer: sample `index` (modulo), mutated 1 to 8 times (mostly once or twice); also the glTF fuzzer's. */
export function mutatedSample(samples: Sample[], seed: number, index: number): { sample: string; steps: string[]; bytes: Uint8Array } {
  const rand = seededRandom(caseSeed(seed, index));
  const sample = samples[index % samples.length];
  const steps: string[] = [];
  const count = 1 + below(rand, 1 + below(rand, 8));
  let bytes = sample.bytes;
  if (sample.name.endsWith('.json') && rand() < 0.8) {
    const doc = JSON.parse(new TextDecoder().decode(bytes));
    for (let i = 0; i < count; i++) steps.push(mutateDocument(doc, rand));
    bytes = encoder.encode(JSON.stringify(doc));
  } else {
    for (let i = 0; i < count; i++) {
      const [out, step] = mutations[below(rand, mutations.length)](bytes, rand);
      bytes = out;
      steps.push(step);
    }
  }
  return { sample: sample.name, steps, bytes };
}

/**
 * The fuzz target mutating `samples`, named `name`. Case (seed, index): 1 to 8 mutations of sample
 * `index` (modulo), put through `check` (the tests plant a broken one).
 */
export function readerTarget(name: string, samples: Sample[], check = checkInput): FuzzTarget<CaseOutcome> {
  return {
    name,
    runCase(seed: number, index: number): CaseOutcome {
      if (samples.length === 0) return { kind: 'refused', reason: 'no samples' };
      const input = mutatedSample(samples, seed, index);
      const outcome = check(input.sample, input.bytes);
      if (outcome.kind !== 'failure') return outcome;
      const bytes = input.bytes.length <= MAX_INPUT_BYTES ? ` bytes (base64) ${Buffer.from(input.bytes).toString('base64')}` : ` (${input.bytes.length} bytes)`;
      return { ...outcome, input: `${input.sample}: ${input.steps.join('; ')};${bytes}` };
    },
  };
}

export const readersTarget = readerTarget('readers', builtInSamples());
export const corpusTarget = readerTarget('corpus', corpusSamples());
