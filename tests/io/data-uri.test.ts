import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { dataUriBytes } from '../../src/core/io/data-uri.js';

const SEED = 20261127;

describe('data URIs', () => {
  it(`decode base64 to the bytes it encodes, padded or not (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.uint8Array({ maxLength: 200 }), fc.boolean(), (bytes, padded) => {
        const base64 = Buffer.from(bytes).toString('base64');
        const uri = `data:application/octet-stream;base64,${padded ? base64 : base64.replace(/=+$/, '')}`;
        expect(dataUriBytes(uri)).toEqual(bytes);
      }),
      { seed: SEED, numRuns: 2000 },
    );
  });

  it('refuse base64 with anything else in it, and a URI that is no data URI', () => {
    for (const uri of ['data:;base64,AAA*', 'data:;base64,AA-A', 'data:;base64,A', 'data:;base64,AA=A', 'data:application/oc', 'file.bin']) {
      expect(dataUriBytes(uri), uri).toBeNull();
    }
  });

  it('decode base64 broken by white space, as atob does', () => {
    expect(Array.from(dataUriBytes('data:;base64,AAEC\r\nAwQF\n')!)).toEqual([0, 1, 2, 3, 4, 5]);
  });

  it('decode percent-encoded text, when the URI does not say base64', () => {
    expect(Array.from(dataUriBytes('data:text/plain,a%20b')!)).toEqual([0x61, 0x20, 0x62]);
  });
});
