/**
 * Every number a file gives must be finite. A binary file can hold NaN or infinity outright, and a
 * text one can name a value beyond what its storage holds (`5e38` read into a float32 normal);
 * such a value has no place in geometry, and no text format could write it back, so a file that
 * holds one is refused, and a mesh that holds one is not written. Checked once here, after a
 * reader has filled the soup and before a writer takes it, for every format alike.
 */
import type { PolygonSoup, SoupAttribute } from '../soup.js';

/**
 * The first value of the soup that is NaN or infinite, said in words ("vertex 3's normal is
 * infinite (item 2): …"), or null when there is none. Positions first, then the attributes of
 * vertices, faces and face corners.
 */
export function firstNonFiniteValue(soup: PolygonSoup): string | null {
  type Values = Pick<SoupAttribute, 'name' | 'itemSize'> & { data: ArrayLike<number> };
  const groups: Array<[string, Values[]]> = [
    ['vertex', [{ name: 'position', itemSize: 3, data: soup.positions }, ...(soup.vertexAttributes ?? [])]],
    ['face', soup.faceAttributes ?? []],
    ['face corner', soup.cornerAttributes ?? []],
  ];
  for (const [element, attributes] of groups) {
    for (const { name, itemSize, data } of attributes) {
      // only floating-point arrays can hold such a value
      if (!(data instanceof Float32Array || data instanceof Float64Array)) continue;
      const i = firstNonFinite(data);
      if (i < 0) continue;
      const x = data[i];
      const where = `${element} ${Math.floor(i / itemSize)}'s ${name}${itemSize > 1 ? ` (item ${i % itemSize})` : ''}`;
      const storage = data instanceof Float32Array ? 'float32' : 'float64';
      return Number.isNaN(x)
        ? `${where} is NaN, not a number`
        : `${where} is ${x > 0 ? '' : 'minus '}infinity: a value written as infinite, or beyond the range of ${storage}, where it is kept`;
    }
  }
  return null;
}

/** Where the first NaN or infinite value of `data` is, or -1. */
function firstNonFinite(data: Float32Array | Float64Array): number {
  for (let i = 0; i < data.length; i++) {
    const x = data[i];
    // x − x is 0 for every finite number, NaN for NaN and both infinities
    if (x - x !== 0) return i;
  }
  return -1;
}
