/**
 * Mutated files — cut short, bytes flipped, headers edited — must either load or raise a
 * ParseError: never another exception, never a hang, never a soup the builder chokes on.
 * Seeded, so a failure names an input that can be replayed.
 */
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { buildMesh, cube, ParseError, seededRandom, tetrahedron } from '../../src/index.js';
import { meshToSoup, readMesh, writeSoup } from '../../src/core/io/index.js';
import { writePly } from '../../src/core/io/write-ply.js';
import { text } from './helpers.js';

const SEED = 20261121;
/** Mutations per sample file: about 3 s in all. */
const ROUNDS = 1000;

interface Sample {
  name: string;
  bytes: Uint8Array;
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

const xyzHeader = (encoding: string, vertices: number | string) =>
  `ply\nformat ${encoding} 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\n`;

/** Files of every format and encoding, written here, plus the corpus's small files when present. */
function samples(): Sample[] {
  const { mesh } = buildMesh(cube());
  mesh.vertexAttributes.add('color', 'uint8', 3).data.fill(128);
  mesh.faceAttributes.add('color', 'float32', 4).data.fill(0.5);
  mesh.halfedgeAttributes.add('texcoord', 'float32', 2).data.fill(0.25);
  const soup = meshToSoup(mesh);
  const list: Sample[] = [
    { name: 'cube.ply', bytes: writeSoup(soup, 'ply') },
    { name: 'cube-le.ply', bytes: writeSoup(soup, 'ply-binary') },
    { name: 'cube-be.ply', bytes: writePly(soup, 'binary_big_endian') },
    { name: 'cube.off', bytes: writeSoup(soup, 'off') },
    { name: 'cube.obj', bytes: writeSoup(soup, 'obj') },
    { name: 'tetra.off', bytes: writeSoup(tetrahedron(), 'off') },
    {
      name: 'strip.ply',
      bytes: text(
        `${xyzHeader('ascii', 4)}element tristrips 1\nproperty list int int vertex_indices\nend_header\n` +
          '0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 1 2 -1 3\n',
      ),
    },
    {
      name: 'two.stl',
      bytes: text('solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n'),
    },
    { name: 'two-binary.stl', bytes: binaryStl() },
  ];
  const corpus = path.resolve(import.meta.dirname, '../../../shared/corpus');
  if (existsSync(corpus)) {
    for (const name of readdirSync(corpus)) {
      const file = path.join(corpus, name);
      if (/\.(ply|off|coff|obj)$/.test(name) && statSync(file).size < 1200) list.push({ name, bytes: readFileSync(file) });
    }
  }
  return list;
}

/** Header edits that real broken files have: huge counts, other types, other encodings. */
const headerEdits: Array<(source: string, rand: () => number) => string> = [
  (s) => s.replace(/(element \w+ )\d+/, '$12147483648'),
  (s, rand) => s.replace(/(element \w+ )\d+/g, (_, head: string) => head + Math.floor(rand() * 40)),
  (s) => s.replace(/property float /, 'property double '),
  (s) => s.replace(/uchar int/, 'int uchar'),
  (s) => s.replace(/list uchar/, 'list uint'),
  (s) => s.replace(/binary_little_endian/, 'binary_big_endian'),
  (s) => s.replace(/binary_\w+_endian|ascii 1\.0/, (m) => (m.startsWith('ascii') ? 'binary_little_endian 1.0' : 'ascii')),
  (s) => s.replace(/^(\S*OFF)\n\d+ \d+/m, '$1\n99999999 99999999'),
  (s) => s.replace(/\n(\d+) (\d+) (\d+)\n/, '\n$1 $2\n'),
  (s) => s.replace(/^v /m, 'v nan '),
  (s) => s.replace(/^f (\d+)/m, 'f -$1'),
  (s) => s.replace(/\n/g, '\r\n'),
  (s) => s.replace(/end_header\n/, 'end_header'),
];

function mutate(bytes: Uint8Array, rand: () => number): Uint8Array {
  const kind = rand();
  if (kind < 0.35) {
    const out = bytes.slice();
    const flips = 1 + Math.floor(rand() * 6);
    for (let i = 0; i < flips; i++) out[Math.floor(rand() * out.length)] = Math.floor(rand() * 256);
    return out;
  }
  if (kind < 0.55) {
    // cut and splice: a piece of the file moved elsewhere
    const a = Math.floor(rand() * bytes.length);
    const b = Math.floor(rand() * bytes.length);
    const [from, to] = a < b ? [a, b] : [b, a];
    return Uint8Array.from([...bytes.subarray(0, from), ...bytes.subarray(to), ...bytes.subarray(from, to)]);
  }
  // edit the text (a binary body passes through latin1 unchanged)
  const source = Array.from(bytes, (b) => String.fromCharCode(b)).join('');
  const edited = headerEdits[Math.floor(rand() * headerEdits.length)](source, rand);
  return Uint8Array.from(edited, (ch) => ch.charCodeAt(0) & 0xff);
}

/** Reads and builds; returns what happened, throws anything that is not a ParseError. */
function attempt(bytes: Uint8Array, fileName: string): 'read' | 'refused' {
  try {
    const file = readMesh(bytes, { fileName });
    buildMesh(file.soup);
    return 'read';
  } catch (error) {
    if (error instanceof ParseError) return 'refused';
    const message = error instanceof Error ? error.stack : String(error);
    throw new Error(`${fileName} (${bytes.length} bytes): ${message}`);
  }
}

describe(`fuzzed files (seed ${SEED})`, () => {
  const files = samples();

  it('cut short at every few bytes: each cut either loads or raises a ParseError', () => {
    const outcomes = { read: 0, refused: 0 };
    for (const { name, bytes } of files) {
      const step = Math.max(1, Math.floor(bytes.length / 150));
      for (let end = 0; end < bytes.length; end += step) outcomes[attempt(bytes.subarray(0, end), name)]++;
    }
    expect(outcomes.refused).toBeGreaterThan(0);
    expect(outcomes.read).toBeGreaterThan(0);
  });

  it('with bytes flipped, pieces moved and headers edited: never another exception', () => {
    const rand = seededRandom(SEED);
    const outcomes = { read: 0, refused: 0 };
    const started = performance.now();
    for (let round = 0; round < ROUNDS; round++) {
      for (const { name, bytes } of files) {
        const mutated = mutate(bytes, rand);
        const before = performance.now();
        outcomes[attempt(mutated, name)]++;
        expect(performance.now() - before, `${name}, round ${round}`).toBeLessThan(1000);
      }
    }
    expect(outcomes.refused).toBeGreaterThan(0);
    expect(performance.now() - started).toBeLessThan(20000);
  });

  it('refuses a tiny file claiming 2^31 rows in every encoding, quickly', () => {
    for (const encoding of ['ascii', 'binary_little_endian', 'binary_big_endian']) {
      const bytes = text(`${xyzHeader(encoding, 2147483648)}end_header\n0000`);
      const started = performance.now();
      expect(attempt(bytes, 'huge.ply')).toBe('refused');
      expect(performance.now() - started).toBeLessThan(50);
    }
  });
});
