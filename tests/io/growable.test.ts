import { describe, expect, it } from 'vitest';
import { GrowableArray } from '../../src/core/io/growable.js';

/** Fills `rows` rows of `perRow(row)` values through `reserveRow`, and says how the array grew. */
function fillRows(capacity: number, rows: number, perRow: (row: number) => number, most = Infinity) {
  const list = new GrowableArray((n) => new Uint32Array(n), capacity);
  const capacities = [list.data.length];
  for (let row = 0; row < rows; row++) {
    const count = perRow(row);
    const data = list.reserveRow(count, row, rows, most);
    for (let k = 0; k < count; k++) data[list.length++] = row;
    if (list.data.length !== capacities.at(-1)) capacities.push(list.data.length);
  }
  return { capacities, values: list.finish() };
}

describe('a list that grows row by row', () => {
  it('grows once, to what the rows need, when they all hold as many values (quads in room for triangles)', () => {
    const { capacities, values } = fillRows(3000, 1000, () => 4);
    expect(capacities).toEqual([3000, 4000]);
    expect(values.length).toBe(4000);
    expect(values.buffer.byteLength).toBe(4000 * 4); // no copy trimmed off at the end
    expect(values[3999]).toBe(999);
  });

  it('doubles when later rows hold more than the first did, so it grows a few times at most', () => {
    const { capacities, values } = fillRows(3000, 1000, (row) => (row < 500 ? 3 : 6));
    expect(capacities.length).toBeLessThanOrEqual(3);
    expect(values.length).toBe(500 * 3 + 500 * 6);
  });

  it('never grows past what the rest of the input can hold, however long the first row', () => {
    // a first row of 1,000 values would make 1,000,000 rows look like a billion values
    const { capacities } = fillRows(8, 1_000_000, (row) => (row === 0 ? 1000 : 0), 5000);
    expect(Math.max(...capacities)).toBeLessThanOrEqual(5000);
  });
});
