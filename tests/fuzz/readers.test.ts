/**
 * The reader fuzzer, a short run (see `fuzz/readers.ts`; `npm run fuzz -- --only readers` runs it
 * long): mutated files must each read into a valid mesh that saves and reads back the same, or be
 * refused with a `ParseError`. Also: files cut short everywhere, and allocation bombs, refused
 * without allocating what they announce.
 */
import { describe, expect, it } from 'vitest';
import { builtInSamples, checkInput, corpusSamples, corpusTarget, readersTarget, readerTarget, refusal } from '../../fuzz/readers.js';
import type { CaseOutcome, FuzzTarget } from '../../fuzz/target.js';
import { type FileLocation, meshFromHalfedgeJSON, ParseError, readMesh } from '../../src/index.js';

const SEED = 20261125;

function failuresOf(target: FuzzTarget<CaseOutcome>, cases: number): string[] {
  const failures: string[] = [];
  for (let index = 0; index < cases; index++) {
    const outcome = target.runCase(SEED, index);
    if (outcome.kind === 'failure') failures.push(`case ${index}: ${outcome.reason}\n  ${outcome.input}`);
  }
  return failures;
}

describe(`the reader fuzzer (seed ${SEED})`, () => {
  it('finds no failure in 6000 mutations of the files the library writes', () => {
    expect(failuresOf(readersTarget, 6000)).toEqual([]);
  });

  const corpus = corpusSamples();
  it.skipIf(corpus.length === 0)(`finds no failure in 3000 mutations of the corpus's ${corpus.length} small files`, () => {
    expect(failuresOf(corpusTarget, 3000)).toEqual([]);
  });
  if (corpus.length === 0) console.warn('tests/fuzz/readers.test.ts: ../shared/corpus is absent: its mutations are skipped');

  it('cut short at every few bytes, each sample either reads back the same or is refused', () => {
    const failures: string[] = [];
    let refused = 0;
    for (const { name, bytes } of builtInSamples()) {
      const step = Math.max(1, Math.floor(bytes.length / 100));
      for (let end = 0; end < bytes.length; end += step) {
        const outcome = checkInput(name, bytes.subarray(0, end));
        if (outcome.kind === 'failure') failures.push(`${name} cut at ${end}: ${outcome.reason}`);
        if (outcome.kind === 'refused') refused++;
      }
    }
    expect(failures).toEqual([]);
    expect(refused).toBeGreaterThan(100);
  });

  it('counts a refusal that names no place in the file as a failure', () => {
    const nowhere = new ParseError('ply', {} as FileLocation, 'something is wrong');
    expect(refusal(nowhere)).toEqual({ kind: 'failure', reason: 'refused without saying where: ply: the document: something is wrong' });
    expect(refusal(new ParseError('ply', { byteOffset: 7 }, 'something is wrong')).kind).toBe('refused');
  });

  // the fuzzer must not pass by not looking: a check that breaks on some inputs is reported, and
  // the failure's input is the mutated file itself, which replays it
  it('reports a failure with the mutated bytes that replay it', () => {
    const planted = (name: string, bytes: Uint8Array) => {
      if (bytes.length % 7 === 3) return { kind: 'failure' as const, reason: `planted: ${bytes.length} bytes` };
      return checkInput(name, bytes);
    };
    const target = readerTarget('planted', builtInSamples(), planted);
    const failures = Array.from({ length: 200 }, (_, i) => target.runCase(SEED, i)).flatMap((o) => (o.kind === 'failure' ? [o] : []));
    expect(failures.length).toBeGreaterThan(5);
    for (const { reason, input } of failures) {
      const [, base64] = input.match(/bytes \(base64\) (\S*)$/)!;
      expect(reason).toBe(`planted: ${Buffer.from(base64, 'base64').length} bytes`);
    }
  });
});

describe('allocation bombs', () => {
  const encoder = new TextEncoder();
  const header = (encoding: string, vertices: number) =>
    `ply\nformat ${encoding} 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\nend_header\n0000`;
  const bombs: Array<[string, () => unknown]> = [
    ...['ascii', 'binary_little_endian', 'binary_big_endian'].map((encoding): [string, () => unknown] => [
      `a PLY (${encoding}) header announcing 2^31 vertices`,
      () => readMesh(encoder.encode(header(encoding, 2 ** 31)), { fileName: 'bomb.ply' }),
    ]),
    ['a PLY face list of 2^31 corners', () => readMesh(encoder.encode(`${header('binary_little_endian', 3).replace('end_header', 'element face 1\nproperty list uint int vertex_indices\nend_header')}${'\0'.repeat(32)}\xff\xff\xff\x7f`), { fileName: 'bomb.ply' })],
    ['an OFF header announcing 2^31 vertices', () => readMesh(encoder.encode('OFF\n2147483648 1 0\n0 0 0\n'), { fileName: 'bomb.off' })],
    ['an OFF face of 2^31 corners', () => readMesh(encoder.encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2147483648 0 1 2\n'), { fileName: 'bomb.off' })],
    ['a binary STL announcing 2^31 triangles', () => readMesh(Uint8Array.from([...new Uint8Array(80), 0, 0, 0, 0x80, ...new Uint8Array(50)]), { fileName: 'bomb.stl' })],
    ...[1e300, 2 ** 31].map((itemSize): [string, () => unknown] => [
      `halfedge JSON with an attribute of itemSize ${itemSize}`,
      () =>
        meshFromHalfedgeJSON({
          format: 'halfedge-json',
          version: 1,
          vertices: [{ id: 0, halfedge: -1, position: [0, 0, 0], attributes: { w: [1] } }],
          halfedges: [],
          edges: [],
          faces: [],
          attributes: [{ element: 'vertex', name: 'w', type: 'float32', itemSize, interpolation: 'linear' }],
        }),
    ]),
  ];
  for (const [name, read] of bombs) {
    it(`refuses ${name} with a ParseError, without allocating it`, () => {
      const before = process.memoryUsage();
      expect(read).toThrow(ParseError);
      const after = process.memoryUsage();
      const grown = after.heapUsed + after.arrayBuffers - (before.heapUsed + before.arrayBuffers);
      expect(grown).toBeLessThan(64 * 2 ** 20);
    });
  }
});
