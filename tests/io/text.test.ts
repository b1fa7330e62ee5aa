import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { formatFloat32, formatFloat64 } from '../../src/core/io/output.js';
import { decodeText, encodeText, PlainLines, TextScanner } from '../../src/core/io/text.js';
import { ParseError } from '../../src/index.js';
import { parseError, text } from './helpers.js';

const SEED = 20261121;

function numbersOf(source: string): number[] {
  const scanner = new TextScanner(text(source), 'test');
  const values: number[] = [];
  while (scanner.skipBlankLines()) values.push(scanner.number());
  return values;
}

describe('the number scanner', () => {
  it('reads the forms mesh files use', () => {
    expect(numbersOf('12 -3 +4 0.5 .5 5. -0.25e2 1E-3 6.02e+23 007')).toEqual([12, -3, 4, 0.5, 0.5, 5, -25, 0.001, 6.02e23, 7]);
    expect(Object.is(numbersOf('-0')[0], -0)).toBe(true);
  });

  it(`reads every double exactly as the writers print it (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.double({ noNaN: true, noDefaultInfinity: true }), (x) => Object.is(numbersOf(formatFloat64(x))[0], x)),
      { seed: SEED, numRuns: 20000 },
    );
  });

  it(`reads short decimals to the nearest double, as the engine does (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.integer({ min: -99999999, max: 99999999 }), fc.integer({ min: -30, max: 30 }), (mantissa, exponent) => {
        const source = `${mantissa}e${exponent}`;
        return numbersOf(source)[0] === Number(source);
      }),
      { seed: SEED, numRuns: 20000 },
    );
  });

  it(`reads numbers of 16 to 19 digits, in every form, to the nearest double, as the engine does (seed ${SEED})`, () => {
    const digits = fc.bigInt({ min: 10n ** 15n, max: 10n ** 19n - 1n }).map(String);
    const written = fc.oneof(
      // a point placed among the digits, or before them after some zeros
      fc.tuple(digits, fc.integer({ min: 0, max: 19 }), fc.integer({ min: 0, max: 8 })).map(([d, point, zeros]) =>
        point === 0 ? `0.${'0'.repeat(zeros)}${d}` : `${d.slice(0, point)}.${d.slice(point)}`,
      ),
      // scientific notation, as the engine writes small and large doubles
      fc.tuple(digits, fc.integer({ min: -30, max: 30 })).map(([d, e]) => `${d[0]}.${d.slice(1)}e${e}`),
      // doubles printed with 16 to 19 digits
      fc.tuple(fc.double({ min: 1e-12, max: 1e6, noNaN: true }), fc.integer({ min: 16, max: 19 })).map(([x, p]) => x.toPrecision(p)),
    );
    fc.assert(
      fc.property(written, fc.boolean(), (source, negative) => {
        const signed = negative ? `-${source}` : source;
        return Object.is(numbersOf(signed)[0], Number(signed));
      }),
      { seed: SEED, numRuns: 100000 },
    );
  });

  it(`rounds 19-digit numbers just either side of the midpoint of two doubles as the engine does (seed ${SEED})`, () => {
    /** The first 19 digits of the midpoint between x and the next double up, and those plus one. */
    const nearMidpoint = (x: number): [string, string] => {
      const view = new DataView(new ArrayBuffer(8));
      view.setFloat64(0, x);
      const bits = view.getBigUint64(0);
      const shift = Number((bits >> 52n) & 0x7ffn) - 1075; // x = significand · 2^shift, shift < 0 here
      const significand = (bits & ((1n << 52n) - 1n)) | (1n << 52n);
      const scale = 1 - shift; // midpoint · 10^scale = (2 · significand + 1) · 5^scale · 2^(scale - 1 + shift)
      const digits = ((2n * significand + 1n) * 10n ** BigInt(scale)) >> BigInt(1 - shift);
      const text = digits.toString();
      const first = BigInt(text.slice(0, 19));
      const exponent = text.length - 19 - scale;
      return [`${first}e${exponent}`, `${first + 1n}e${exponent}`];
    };
    fc.assert(
      fc.property(fc.double({ min: 1e-3, max: 1e3, noNaN: true }), (x) =>
        nearMidpoint(x).every((source) => Object.is(numbersOf(source)[0], Number(source))),
      ),
      { seed: SEED, numRuns: 20000 },
    );
    // exactly halfway between two doubles, which only numbers of 2^32 and over can be with 22
    // decimals or fewer: the tie goes to the even one
    const ties = ['4503599627370497.5', '4503599627370498.5', '-9007199254740993.0', '9007199254740995.00', '18014398509481986.0'];
    expect(ties.map((source) => numbersOf(source)[0])).toEqual(ties.map(Number));
    // just below a power of two, where the double beneath is only half as far as the one above
    const belowPowers = ['0.49999999999999997', '0.499999999999999972', '0.99999999999999994', '0.999999999999999944', '1.9999999999999999'];
    expect(belowPowers.map((source) => numbersOf(source)[0])).toEqual(belowPowers.map(Number));
  });

  it('reads NaN and infinity written as words, and a number beyond a double as infinity, none of them whole', () => {
    const scanner = new TextScanner(text('nan -NaN inf -Infinity +INF 1e999 -1e999 12345678901234567890e300'), 'test');
    const read = Array.from({ length: 8 }, () => [scanner.number(), scanner.integral]);
    expect(read).toEqual([
      [Number.NaN, false],
      [Number.NaN, false],
      [Infinity, false],
      [-Infinity, false],
      [Infinity, false],
      [Infinity, false],
      [-Infinity, false],
      [Infinity, false],
    ]);
    // only the whole word: a token that starts like one is no number
    for (const token of ['nanx', 'infinit', 'in', '-nan1']) expect(parseError(() => numbersOf(token)).reason).toBe(`expected a number, found '${token}'`);
    // where `#` starts a comment, it ends the word as it ends a number
    const commented = new TextScanner(text('inf#c'), 'test', { hashComments: true });
    expect([commented.number(), commented.atLineEnd()]).toEqual([Infinity, true]);
  });

  it('says whether a number was written as an integer', () => {
    const scanner = new TextScanner(text('255 1.0 1e2'), 'test');
    const integral = [0, 1, 2].map(() => (scanner.number(), scanner.integral));
    expect(integral).toEqual([true, false, false]);
  });

  it('names the line, the column and the token it cannot read', () => {
    const scanner = new TextScanner(text('1 2\n\n  3 4x\n'), 'test');
    scanner.number();
    scanner.number();
    scanner.skipBlankLines();
    scanner.number();
    expect(parseError(() => scanner.number()).message).toBe("test: line 3, column 5: expected a number, found '4x'");
    const integers = new TextScanner(text('7 1.5'), 'test');
    integers.integer();
    expect(parseError(() => integers.integer()).message).toBe("test: line 1, column 3: expected a whole number, found '1.5'");
  });

  it('treats # as a comment only where the format says so', () => {
    const comments: string[] = [];
    const scanner = new TextScanner(text('1 # one\n2'), 'test', { hashComments: true, comments });
    expect([scanner.number(), scanner.atLineEnd()]).toEqual([1, true]);
    expect(comments).toEqual(['one']);
    expect(parseError(() => numbersOf('1 #2')).message).toMatch(/found '#2'/);
  });
});

/** What reading a text line by line finds: each line's number, numbers and which are whole; then the error, if any. */
interface LinesRead {
  lines: Array<{ line: number; values: number[]; integral: boolean[] }>;
  error: string | null;
}

/** Reads every line token by token with `number()`: the oracle for the fast lane. */
function readByTokens(scanner: TextScanner, into: LinesRead): void {
  const line = scanner.line;
  const values: number[] = [];
  const integral: boolean[] = [];
  while (!scanner.atLineEnd()) {
    values.push(scanner.number());
    integral.push(scanner.integral);
  }
  into.lines.push({ line, values, integral });
  scanner.endLine('a line');
}

function readLines(source: string, fastLane: boolean): LinesRead {
  const scanner = new TextScanner(text(source), 'test');
  const batch = new PlainLines();
  const read: LinesRead = { lines: [], error: null };
  try {
    while (scanner.skipBlankLines()) {
      const lines = fastLane ? scanner.plainLines(batch, Infinity) : 0;
      for (let r = 0, from = 0; r < lines; from = batch.ends[r++]) {
        const numbers = Array.from(batch.values.subarray(from, batch.ends[r]));
        const whole = Array.from(batch.integral.subarray(from, batch.ends[r]), (x) => x === 1);
        read.lines.push({ line: batch.firstLine + r, values: numbers, integral: whole });
      }
      if (lines === 0) readByTokens(scanner, read);
    }
  } catch (error) {
    if (!(error instanceof ParseError)) throw error;
    read.error = error.message;
  }
  return read;
}

describe('the fast lane for lines of plain numbers', () => {
  const token = fc.oneof(
    { weight: 8, arbitrary: fc.integer({ min: -999999, max: 999999 }).map(String) },
    { weight: 8, arbitrary: fc.tuple(fc.integer({ min: -99999999, max: 99999999 }), fc.integer({ min: -25, max: 25 })).map(([m, e]) => `${m}e${e}`) },
    { weight: 8, arbitrary: fc.double({ noNaN: true, noDefaultInfinity: true, min: -1e6, max: 1e6 }).map((x) => x.toFixed(6)) },
    { weight: 2, arbitrary: fc.double({ noNaN: true, noDefaultInfinity: true }).map(formatFloat64) },
    { weight: 1, arbitrary: fc.constantFrom('+4', '.5', '5.', '-0', '007', '1e', '-', '.', 'abc', 'nan', '#', '1#', '1.5e400', '12345678901234567890') },
  );
  const space = fc.constantFrom(' ', '  ', '\t', ' \r', '\u0000');
  const line = fc.array(fc.tuple(token, space), { maxLength: 70 }).map((parts) => parts.map(([t, s]) => t + s).join(''));
  const source = fc.tuple(fc.array(line, { maxLength: 40 }), fc.boolean()).map(([lines, lastFeed]) => lines.join('\n') + (lastFeed ? '\n' : ''));

  it(`reads what number() reads, line by line, and leaves every other line to it (seed ${SEED})`, () => {
    fc.assert(
      fc.property(source, (text) => {
        expect(readLines(text, true)).toEqual(readLines(text, false));
      }),
      { seed: SEED, numRuns: 3000 },
    );
  });

  it('keeps count of lines across batches, and moves back to a line it read', () => {
    const source = Array.from({ length: 5000 }, (_, i) => `${i} ${i / 4}`).join('\n');
    const scanner = new TextScanner(text(`${source}\n`), 'test', { line: 3 });
    const batch = new PlainLines();
    let rows = 0;
    for (let lines; (lines = scanner.plainLines(batch, Infinity)) > 0; rows += lines) {
      expect([batch.values[0], batch.firstLine]).toEqual([rows, 3 + rows]);
    }
    expect([rows, scanner.line, scanner.skipBlankLines()]).toEqual([5000, 5003, false]);

    const again = new TextScanner(text(`${source}\n`), 'test', { line: 3 });
    expect(again.plainLines(batch, 100)).toBe(100);
    again.backTo(batch, 40);
    expect([again.location(), again.number(), again.number()]).toEqual([{ line: 43, column: 1 }, 40, 10]);
  });
});

describe('text helpers', () => {
  it(`formats float32 values with the fewest digits that read back as the same float32 (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.float({ noNaN: true, noDefaultInfinity: true }), (x) => {
        const written = formatFloat32(x);
        const digits = written.replace(/e.*$/, '').replace(/[-.]/g, '').replace(/^0+/, '').replace(/0+$/, '');
        return Object.is(Math.fround(Number(written)), x) && digits.length <= 9;
      }),
      { seed: SEED, numRuns: 20000 },
    );
    expect([0.1, 0.5, 1 / 3].map((x) => formatFloat32(Math.fround(x)))).toEqual(['0.1', '0.5', '0.33333334']);
  });

  it('decodes and encodes UTF-8, with U+FFFD for malformed bytes', () => {
    const source = 'cube 立方体 🧊 ü';
    expect(decodeText(encodeText(source))).toBe(source);
    expect(encodeText(source)).toEqual(new TextEncoder().encode(source));
    expect(decodeText(new Uint8Array([0x61, 0xff, 0xe6, 0x62]))).toBe('a\ufffd\ufffdb');
  });
});
