import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { formatFloat32, formatFloat64 } from '../../src/core/io/output.js';
import { decodeText, encodeText, TextScanner } from '../../src/core/io/text.js';
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
