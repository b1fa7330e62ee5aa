/** The colours of a phase's per-vertex values: the scale's ends, its two kinds, and the percentile it stops at. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { colourScale, select } from '../../src/workers/colour-scale.js';

describe('the colour scale of per-vertex values', () => {
  it('finds the k-th smallest value, as a sort would', () => {
    fc.assert(
      fc.property(fc.array(fc.double({ noNaN: true, min: -1e6, max: 1e6 }), { minLength: 1, maxLength: 400 }), fc.nat(), (list, n) => {
        const k = n % list.length;
        const sorted = Float64Array.from(list).sort();
        expect(select(Float64Array.from(list), k)).toBe(sorted[k]);
      }),
      { seed: 20261125, numRuns: 300 },
    );
  });

  it('runs light to dark over values of one sign, stopping at the 98th percentile of a thousand', () => {
    const values = Float64Array.from({ length: 1000 }, (_, i) => i);
    const scale = colourScale(values);
    expect(scale).toMatchObject({ diverging: false, low: 0, high: 979 });
    const at = (i: number) => Array.from(scale.colours.subarray(3 * i, 3 * i + 3));
    // #F0E442 at the low end and #0072B2 from the percentile on, in linear RGB
    expect(at(0).map((c) => +c.toFixed(3))).toEqual([0.871, 0.776, 0.054]);
    expect(at(999)).toEqual(at(979));
    expect(at(999).map((c) => +c.toFixed(3))).toEqual([0, 0.168, 0.445]);
  });

  it('runs blue through white to vermillion over values of both signs, with grey where a value is missing', () => {
    const scale = colourScale([-2, 0, 2, Number.NaN]);
    expect(scale).toMatchObject({ diverging: true, low: -2, high: 2 });
    expect(Array.from(scale.colours.subarray(3, 6))).toEqual([1, 1, 1]);
    const grey = Array.from(scale.colours.subarray(9, 12));
    expect(grey[0]).toBeCloseTo(0.323, 3);
    expect(new Set(grey).size).toBe(1);
  });
});
