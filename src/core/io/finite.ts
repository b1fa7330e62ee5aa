/**
 * Every number of a mesh must be finite. A binary file can hold NaN or infinity outright, a text
 * one can write them as words (`nan`, `inf`) or name a value beyond what its storage holds (`5e38`
 * read into a float32 normal). Such a value has no place in geometry, and no text format could
 * write it back, so:
 *
 * - a position that is not finite refuses the file, at the place it was read from;
 * - any other value that is not finite (a normal, a texture coordinate, a colour, a PLY
 *   `quality`) is dropped, and the mesh stays. Exporters do write these: a facet of no area has no
 *   normal, and some write NaN for it. The item that holds it (the whole normal, colour or
 *   texture coordinate of that element) is replaced by a neutral one: a face's normal is computed
 *   again from the face's corners (zero for a face without area, which has no normal); any other
 *   item becomes zeros, a colour opaque black. The attribute stays, so the mesh writes and reads
 *   back as it opened; a note says how many items were dropped, and where the first one was read
 *   (for the first few attributes: each place is found by reading the file again; one note tells
 *   of the rest).
 *
 * Checked once here, after a reader has filled the soup (glTF, whose values pass through node
 * transforms, checks each as it reads it, with `droppedValuesNote`). The writers refuse a mesh
 * that holds such a value (`firstNonFiniteValue`); they can no longer receive one from a reader.
 */
import { describeLocation, type FileLocation, ParseError } from '../errors.js';
import { plural } from '../report.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import type { Locate, MeshFile, SoupElement } from './mesh-file.js';
import { quoted, someOf } from './names.js';

const elementWords: Record<SoupElement, string> = { vertex: 'vertex', face: 'face', corner: 'face corner' };

/**
 * Attributes whose dropped values get a note of their own, naming where the first was read. Each
 * place is found by walking the file again: a file of a hundred thousand attributes gets this
 * many such notes, and one for the rest.
 */
const LOCATED_NOTES = 8;

/**
 * Refuses the file when a position is not finite; replaces every other value that is not, adding
 * a note per attribute to `file.notes`.
 * @throws ParseError at the first position that is NaN or infinite, where `locate` finds it.
 */
export function checkFiniteValues(file: MeshFile, locate: Locate): void {
  const { soup, notes } = file;
  const { positions } = soup;
  const i = firstNonFinite(positions, 0);
  if (i >= 0) {
    const vertex = Math.floor(i / 3);
    const what = `vertex ${vertex}'s position (item ${i % 3})`;
    throw new ParseError(file.format, locate('vertex', 'position', vertex, i % 3), `${what} ${nonFiniteWords(positions[i], storageOf(positions))}`);
  }
  const groups: Array<[SoupElement, SoupAttribute[] | undefined]> = [
    ['vertex', soup.vertexAttributes],
    ['face', soup.faceAttributes],
    ['corner', soup.cornerAttributes],
  ];
  /** The attributes beyond `LOCATED_NOTES` that had values dropped, and how many items those were. */
  const others: string[] = [];
  let otherItems = 0;
  let located = 0;
  for (const [element, attributes] of groups) {
    for (const attribute of attributes ?? []) {
      const dropped = dropNonFinite(soup, element, attribute);
      if (dropped === null) continue;
      if (located < LOCATED_NOTES) {
        notes.push(droppedNote(element, attribute, dropped, locate));
        located++;
      } else {
        others.push(quoted(attribute.name));
        otherItems += dropped.count;
      }
    }
  }
  if (others.length > 0) {
    const items = plural(otherItems, 'item');
    notes.push(`dropped NaN or infinite values of ${plural(others.length, 'more attribute')} (${someOf(others)}): ${items}, replaced as above`);
  }
}

/** What `dropNonFinite` replaced: how many items, and where in the data the first value was. */
interface Dropped {
  count: number;
  first: number;
}

/**
 * Replaces each item of `attribute` that holds a value that is not finite (see the top of this
 * file); returns what it replaced, or null when there was nothing to.
 */
function dropNonFinite(soup: PolygonSoup, element: SoupElement, attribute: SoupAttribute): Dropped | null {
  const { itemSize, data } = attribute;
  // only floating-point arrays can hold such a value
  if (!(data instanceof Float32Array || data instanceof Float64Array)) return null;
  const first = firstNonFinite(data, 0);
  if (first < 0) return null;
  const faceNormal = isFaceNormal(element, attribute);
  const opaque = isOpaqueColour(attribute);
  let count = 0;
  for (let i = first; i >= 0; count++) {
    const item = Math.floor(i / itemSize);
    if (faceNormal) setFaceNormal(soup, item, data);
    else {
      data.fill(0, item * itemSize, (item + 1) * itemSize);
      if (opaque) data[item * itemSize + 3] = 1;
    }
    i = firstNonFinite(data, (item + 1) * itemSize);
  }
  return { count, first };
}

const isFaceNormal = (element: SoupElement, { name, itemSize }: SoupAttribute) => element === 'face' && name === 'normal' && itemSize === 3;
const isOpaqueColour = ({ name, itemSize }: SoupAttribute) => name === 'color' && itemSize === 4;

/** The note for the items of `attribute` that `dropNonFinite` replaced, naming where the first was read. */
function droppedNote(element: SoupElement, attribute: SoupAttribute, { count, first }: Dropped, locate: Locate): string {
  const { name, itemSize } = attribute;
  const index = Math.floor(first / itemSize);
  const item = first % itemSize;
  const firstWords = `${elementWords[element]} ${index}'s${itemSize > 1 ? ` (item ${item})` : ''}`;
  const values = `${elementWords[element]} ${valueWords.get(name) ?? `${quoted(name)} value`}`;
  const replacement = isFaceNormal(element, attribute)
    ? 'computed again from the corners of its face (zero for a face without area)'
    : name === 'color'
      ? `set to ${isOpaqueColour(attribute) ? 'opaque ' : ''}black`
      : 'set to zero';
  return droppedValuesNote(count, values, replacement, firstWords, locate(element, name, index, item));
}

/** What the attributes of the names readers give are called in a note (a Map: a file's name is any text). */
const valueWords = new Map([
  ['normal', 'normal'],
  ['color', 'colour'],
  ['texcoord', 'texture coordinate'],
]);

/**
 * The note for `count` values (`values`: "face normal") that were NaN or infinite and were
 * replaced as `replacement` says, the first being `first` ("face 0's"), read at `location`.
 */
export function droppedValuesNote(count: number, values: string, replacement: string, first: string, location: FileLocation): string {
  const were = count === 1 ? 'that was' : 'that were';
  return `dropped ${plural(count, values)} ${were} NaN or infinite, ${replacement}; the first is ${first}, at ${describeLocation(location)}`;
}

/**
 * Face `f`'s unit normal from its corners (Newell's method, which any polygon suits), zero when
 * the face has no area, into `target[3f…3f+3)`. The corners are scaled by their largest
 * coordinate first, so that huge coordinates cannot overflow the products.
 */
function setFaceNormal(soup: PolygonSoup, f: number, target: Float32Array | Float64Array): void {
  const { positions, faceStarts, faceIndices } = soup;
  const start = faceStarts[f];
  const end = faceStarts[f + 1];
  let scale = 0;
  for (let c = start; c < end; c++) {
    for (let k = 0; k < 3; k++) scale = Math.max(scale, Math.abs(positions[3 * faceIndices[c] + k]));
  }
  let [nx, ny, nz] = [0, 0, 0];
  for (let c = start; c < end && scale > 0; c++) {
    const a = 3 * faceIndices[c];
    const b = 3 * faceIndices[c + 1 < end ? c + 1 : start];
    const [ax, ay, az] = [positions[a] / scale, positions[a + 1] / scale, positions[a + 2] / scale];
    const [bx, by, bz] = [positions[b] / scale, positions[b + 1] / scale, positions[b + 2] / scale];
    nx += (ay - by) * (az + bz);
    ny += (az - bz) * (ax + bx);
    nz += (ax - bx) * (ay + by);
  }
  const length = Math.hypot(nx, ny, nz);
  const unit = length > 0 ? 1 / length : 0;
  target[3 * f] = nx * unit;
  target[3 * f + 1] = ny * unit;
  target[3 * f + 2] = nz * unit;
}

/**
 * The first value of the soup that is NaN or infinite, said in words ("vertex 3's normal (item 2)
 * is infinity: …"), or null when there is none: what the writers refuse. Positions first, then the
 * attributes of vertices, faces and face corners.
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
      const i = firstNonFinite(data, 0);
      if (i < 0) continue;
      const where = `${element} ${Math.floor(i / itemSize)}'s ${name}${itemSize > 1 ? ` (item ${i % itemSize})` : ''}`;
      return `${where} ${nonFiniteWords(data[i], storageOf(data))}`;
    }
  }
  return null;
}

const storageOf = (data: Float32Array | Float64Array) => (data instanceof Float32Array ? 'float32' : 'float64');

/** "is NaN, not a number", or "is infinity: …", for `x`, naming the type it is kept in. */
export function nonFiniteWords(x: number, storage: 'float32' | 'float64'): string {
  return Number.isNaN(x)
    ? 'is NaN, not a number'
    : `is ${x > 0 ? '' : 'minus '}infinity: a value written as infinite, or beyond the range of ${storage}, where it is kept`;
}

/** Where the first NaN or infinite value of `data` from `from` on is, or -1. */
function firstNonFinite(data: Float32Array | Float64Array, from: number): number {
  for (let i = from; i < data.length; i++) {
    const x = data[i];
    // x − x is 0 for every finite number, NaN for NaN and both infinities
    if (x - x !== 0) return i;
  }
  return -1;
}
