/**
 * OFF, Geomview's Object File Format: a keyword, the counts, the vertices, the faces.
 *
 * ```
 * OFF                     [ST][C][N][4][n]OFF: the prefixes say what each vertex carries
 * 8 6 12                  vertices, faces, edges (the edge count is never used)
 * 0 0 0                   x y z [nx ny nz] [r g b [a]] [s t]
 * …
 * 4 0 3 2 1  1 0 0        corner count, vertex ids (from 0), then an optional face colour
 * ```
 *
 * The prefixes: `ST` texture coordinates, `C` colours, `N` normals, `4` a fourth, homogeneous
 * coordinate (x y z w, meaning x/w y/w z/w), `n` a dimension given after the keyword (any: a
 * vertex of fewer than 3 coordinates gets zeros, of more keeps x, y, z, and a note says how many
 * were dropped). A face colour is 0 numbers (none), 1 (an index into a colour map, ignored), or
 * 3–4 (RGB[A]): integers 0…255 or reals 0…1, kept as uint8 or float32 accordingly. `#` starts a
 * comment anywhere, which ends with its line.
 *
 * OFF is a stream of numbers: files write one vertex or face a line, but some put each index of
 * a face on a line of its own, with blank lines between faces. So a vertex whose line ends before
 * the numbers its keyword needs goes on over the next lines (and then takes exactly those
 * numbers), and a face's indices may run over several lines. Line ends matter in one place, as in
 * Geomview's own reader: a face's colour runs from its last index to the end of that line. Since a
 * line short of a number reads the same way, an error after such an element names the first one.
 *
 * `OFF BINARY` is followed by the same data as 32-bit ints and floats (for `nOFF BINARY`, the
 * dimension first, as an int; colours as four floats). Geomview's spec makes it big-endian with a
 * colour count after each face; pmp-library writes it little-endian without the count. Each
 * layout is tried; the one that uses the file up exactly wins.
 */
import { type FileLocation, ParseError } from '../errors.js';
import { plural } from '../report.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import { BinaryReader, viewOf } from './binary.js';
import { GrowableArray } from './growable.js';
import type { Locate, MeshFile, Progress, ReaderOutput } from './mesh-file.js';
import { type PlainLines, TextScanner } from './text.js';

/** `[ST][C][N][4][n]OFF`, possibly with the counts glued on (`OFF8 6 0`). */
const KEYWORD = /^(ST)?(C)?(N)?(4)?(n)?OFF/;

/** What each vertex line carries, from the keyword. */
interface OffShape {
  keyword: string;
  texcoords: boolean;
  colors: boolean;
  normals: boolean;
  homogeneous: boolean;
  /** Coordinates before the homogeneous one: 3 unless `nOFF` says otherwise. */
  dimension: number;
  /** `nOFF`: the dimension follows the keyword. */
  dimensionFollows: boolean;
}

/**
 * A dimension of at least 1, and no more numbers than the file has bytes (each vertex has that
 * many, and `values` arrays are made that long).
 */
function checkDimension(dimension: number, fileBytes: number, fail: (reason: string) => never): void {
  if (dimension < 1) fail(`the dimension must be at least 1, not ${dimension}`);
  if (dimension > fileBytes) fail(`the dimension ${dimension} is more numbers than the whole file holds`);
}

/** Numbers a vertex or face line may carry beyond the most its keyword and dimension need. */
const SPARE_VALUES_PER_LINE = 32;

/** The most numbers one vertex line of `shape` may carry: its coordinates, normal, colour, texture coordinates and spares. */
function maxValuesPerLine(shape: OffShape): number {
  return shape.dimension + 1 + 3 + 4 + 2 + SPARE_VALUES_PER_LINE;
}

/**
 * Reads an OFF file (text or `OFF BINARY`) into a polygon soup.
 * @throws ParseError with the line and column (text) or byte offset (binary).
 */
export function readOff(bytes: Uint8Array, progress: Progress): ReaderOutput {
  const comments: string[] = [];
  const notes: string[] = [];
  const scanner = new TextScanner(bytes, 'off', { hashComments: true, comments });
  if (!scanner.skipBlankLines()) scanner.fail('the file holds no OFF data (only blank lines or comments)');
  if (scanner.token() === 'appearance') skipAppearanceBlock(scanner, notes);

  // the keyword
  const keywordAt = scanner.pos;
  const word = scanner.word();
  const match = KEYWORD.exec(word);
  const shape: OffShape = {
    keyword: match?.[0] ?? 'OFF',
    texcoords: !!match?.[1],
    colors: !!match?.[2],
    normals: !!match?.[3],
    homogeneous: !!match?.[4],
    dimension: 3,
    dimensionFollows: !!match?.[5],
  };
  if (match) {
    const glued = word.slice(match[0].length);
    if (glued && !/^\d/.test(glued)) {
      scanner.fail(`unknown keyword '${word}' (OFF, COFF, NOFF, STOFF, 4OFF, nOFF, …)`, keywordAt);
    }
    // counts glued to the keyword (OFF8 6 0): go back to read them as numbers
    scanner.pos = keywordAt + match[0].length;
  } else if (/^[-+.\d]/.test(word)) {
    scanner.pos = keywordAt;
    notes.push('no OFF keyword: read as plain OFF');
  } else {
    const found = scanner.token(keywordAt);
    scanner.fail(`expected the keyword OFF (or COFF, NOFF, STOFF, 4OFF, nOFF, …), found '${found}'`, keywordAt);
  }
  let binary = false;
  if (!scanner.atLineEnd() && scanner.token() === 'BINARY') {
    scanner.word();
    binary = true;
  }
  if (match?.[5] && !binary) {
    // nOFF: the dimension comes next (in a binary file, as its first int32: see readBinaryLayout)
    if (!scanner.skipBlankLines()) scanner.fail('the file ends before the dimension that nOFF announces');
    const at = scanner.pos;
    shape.dimension = scanner.integer();
    checkDimension(shape.dimension, bytes.length, (reason) => scanner.fail(reason, at));
  }

  let read: OffRead;
  if (binary) {
    scanner.nextLine();
    read = readBinaryOff(bytes, scanner.pos, shape, notes);
  } else {
    read = readTextOff(scanner, shape, notes, progress);
  }
  if (scanner.droppedComments > 0) {
    notes.push(`kept the first ${comments.length} comments, ${scanner.droppedComments} more not kept`);
  }
  return { file: { ...read.file, comments, notes }, locate: read.locate };
}

/** Geomview files may open with an `appearance { … }` block (braces nest); it is not geometry. */
function skipAppearanceBlock(scanner: TextScanner, notes: string[]): void {
  const start = scanner.location();
  scanner.word();
  let depth = 0;
  do {
    if (!scanner.skipBlankLines()) throw new ParseError('off', start, "the 'appearance { … }' block is never closed");
    const token = scanner.word();
    for (const ch of token) {
      if (ch === '{') depth++;
      else if (ch === '}') depth--;
    }
  } while (depth > 0);
  scanner.skipBlankLines();
  const lines = `lines ${start.line}–${scanner.line - 1}`;
  notes.push(`skipped a Geomview 'appearance { … }' block before the keyword (${lines})`);
}

// -------------------------------------------------------------------------------------------------
// What vertex and face lines carry, for both encodings

/** The arrays of an OFF mesh, filled vertex by vertex and face by face. */
class OffMesh {
  readonly shape: OffShape;
  readonly positions: Float64Array;
  readonly normals: Float32Array<ArrayBuffer> | null;
  readonly texcoords: Float32Array<ArrayBuffer> | null;
  readonly vertexColors: ColorCollector | null;
  readonly faceStarts: Uint32Array;
  readonly faceIndices: GrowableArray<Uint32Array<ArrayBuffer>>;
  readonly faceColors: ColorCollector;
  /** Faces whose colour was an index into a colour map (not kept). */
  colormapIndices = 0;
  /** Vertex lines with more numbers than the keyword announces (plain OFF files often have them). */
  vertexExtras = 0;

  constructor(shape: OffShape, vertexCount: number, faceCount: number) {
    this.shape = shape;
    this.positions = new Float64Array(3 * vertexCount);
    this.normals = shape.normals ? new Float32Array(3 * vertexCount) : null;
    this.texcoords = shape.texcoords ? new Float32Array(2 * vertexCount) : null;
    this.vertexColors = shape.colors ? new ColorCollector(vertexCount) : null;
    this.faceStarts = new Uint32Array(faceCount + 1);
    this.faceIndices = new GrowableArray((n) => new Uint32Array(n), 3 * faceCount);
    this.faceColors = new ColorCollector(faceCount);
  }

  /**
   * Stores vertex `v` from the `count` numbers of its line, `values[at]` on: coordinates, then
   * normal, colour and texture coordinates as the keyword says. A line that cannot be a vertex is
   * not stored: what is wrong with it is returned instead (null when it was stored).
   */
  setVertex(v: number, values: Float64Array, integral: Uint8Array, at: number, count: number): string | null {
    const { shape, positions } = this;
    const coordinates = shape.dimension + (shape.homogeneous ? 1 : 0);
    if (count < coordinates) {
      return `vertex ${v} has ${count} numbers, but ${shape.keyword} needs ${coordinates} coordinates`;
    }
    const w = shape.homogeneous ? values[at + shape.dimension] : 1;
    if (w === 0) return `vertex ${v} has w = 0: a point at infinity has no place in a mesh`;
    // x − x is 0 for every finite number, NaN for NaN and both infinities
    if (w - w !== 0) return `vertex ${v} has w = ${w}: the coordinate that divides the others must be a finite number`;
    const normalCount = shape.normals ? 3 : 0;
    const texcoordCount = shape.texcoords ? 2 : 0;
    const colorCount = count - coordinates - normalCount - texcoordCount;
    if (shape.colors ? colorCount !== 3 && colorCount !== 4 : colorCount < 0) {
      const parts = [
        shape.normals && 'a normal (3)',
        shape.colors && 'a colour (3 or 4)',
        shape.texcoords && 'texture coordinates (2)',
      ];
      const needs = parts.filter(Boolean).join(', ');
      return `vertex ${v} has ${count - coordinates} numbers after its coordinates, but ${shape.keyword} needs ${needs}`;
    }
    // fewer than 3 coordinates: the rest are 0; more: x, y, z are kept (`finish` says so)
    for (let k = 0; k < 3; k++) positions[3 * v + k] = k < shape.dimension ? values[at + k] / w : 0;
    at += coordinates;
    if (this.normals) {
      for (let k = 0; k < 3; k++) this.normals[3 * v + k] = values[at + k];
      at += 3;
    }
    if (this.vertexColors) {
      this.vertexColors.set(v, values, integral, at, colorCount);
      at += colorCount;
    } else if (colorCount > 0) {
      this.vertexExtras++;
    }
    if (this.texcoords) {
      for (let k = 0; k < 2; k++) this.texcoords[2 * v + k] = values[at + k];
    }
    return null;
  }

  /**
   * Stores the colour that follows face `f`'s vertex ids (0, 1, 3 or 4 numbers, `values[at]` on);
   * returns what is wrong with any other count (null when it was stored).
   */
  setFaceColor(f: number, values: Float64Array, integral: Uint8Array, at: number, count: number): string | null {
    if (count === 1) this.colormapIndices++;
    else if (count === 3 || count === 4) this.faceColors.set(f, values, integral, at, count);
    else if (count !== 0) {
      return `face ${f} has ${count} numbers after its vertex ids; a colour is 1, 3 or 4 (is its corner count right?)`;
    }
    return null;
  }

  finish(notes: string[]): PolygonSoup {
    const vertexCount = this.positions.length / 3;
    const vertexAttributes: SoupAttribute[] = [];
    if (this.normals) vertexAttributes.push({ name: 'normal', itemSize: 3, data: this.normals });
    const vertexColor = this.vertexColors?.finish('vertex', notes);
    if (vertexColor) vertexAttributes.push(vertexColor);
    if (this.texcoords) vertexAttributes.push({ name: 'texcoord', itemSize: 2, data: this.texcoords });
    const faceColor = this.faceColors.finish('face', notes);
    if (this.colormapIndices > 0) {
      notes.push(`ignored the colour-map indices of ${plural(this.colormapIndices, 'face')} (no colour map is loaded)`);
    }
    if (this.vertexExtras > 0) {
      notes.push(`ignored extra numbers after the coordinates of ${plural(this.vertexExtras, 'vertex', 'vertices')}`);
    }
    const faceCount = this.faceStarts.length - 1;
    if (vertexCount > 0 && faceCount === 0) notes.push('no faces: loaded as a point set');
    const { dimension, keyword } = this.shape;
    if (dimension > 3) {
      notes.push(`${keyword} vertices have ${dimension} coordinates: kept x, y and z, dropped the other ${dimension - 3}`);
    } else if (dimension < 3) {
      notes.push(`${keyword} vertices have ${plural(dimension, 'coordinate')}: the missing ones are 0`);
    }
    return {
      positions: this.positions,
      faceStarts: this.faceStarts,
      faceIndices: this.faceIndices.finish(),
      vertexAttributes,
      faceAttributes: faceColor ? [faceColor] : [],
    };
  }
}

/**
 * Colours of vertices or faces as written: RGB or RGBA, integers 0…255 or reals 0…1. Kept as
 * uint8 when every number was written as an integer, else as float32; RGB ones get an opaque
 * alpha when others have one. A value written as NaN is kept as it is (`finite.ts` drops it).
 */
class ColorCollector {
  /** RGBA of each element, the components it was given. */
  private values: Float32Array | null = null;
  /** How many components each element's colour has: 3, 4, or 0 for none. */
  private components: Uint8Array | null = null;
  private readonly count: number;
  private colored = 0;
  private hasAlpha = false;
  private integral = true;

  constructor(count: number) {
    this.count = count;
  }

  set(i: number, source: Float64Array, integral: Uint8Array, from: number, components: number): void {
    const values = (this.values ??= new Float32Array(4 * this.count));
    for (let k = 0; k < components; k++) {
      values[4 * i + k] = source[from + k];
      if (!integral[from + k]) this.integral = false;
    }
    (this.components ??= new Uint8Array(this.count))[i] = components;
    if (components === 4) this.hasAlpha = true;
    this.colored++;
  }

  finish(owner: 'vertex' | 'face', notes: string[]): SoupAttribute | null {
    const { values, components } = this;
    if (!values || !components) return null;
    const itemSize = this.hasAlpha ? 4 : 3;
    // (the components not given are 0, within range)
    const uint8 = this.integral && values.every((x) => x >= 0 && x <= 255);
    const data = uint8 ? new Uint8Array(itemSize * this.count) : new Float32Array(itemSize * this.count);
    const opaque = uint8 ? 255 : 1;
    for (let i = 0; i < this.count; i++) {
      for (let k = 0; k < itemSize; k++) {
        // an element without a colour is opaque black; an RGB colour among RGBA ones is opaque
        data[itemSize * i + k] = k < components[i] ? values[4 * i + k] : k === 3 ? opaque : 0;
      }
    }
    const missing = this.count - this.colored;
    if (missing > 0) {
      const elements =
        owner === 'vertex' ? plural(missing, 'vertex has', 'vertices have') : plural(missing, 'face has', 'faces have');
      notes.push(`${elements} no colour (left black)`);
    }
    return { name: 'color', itemSize, data };
  }
}

// -------------------------------------------------------------------------------------------------
// Text

/** What the text and binary readers give; `readOff` adds the comments and notes to the file. */
interface OffRead {
  file: Omit<MeshFile, 'comments' | 'notes'>;
  locate: Locate;
}

/**
 * Which of a vertex's `count` numbers item `item` of its value `name` was read from: coordinates,
 * normal, colour (3 or 4 numbers), texture coordinates, as the keyword says.
 */
function vertexNumber(shape: OffShape, name: string, item: number, count: number): number {
  const coordinates = shape.dimension + (shape.homogeneous ? 1 : 0);
  if (name === 'normal') return coordinates + item;
  if (name === 'color') return coordinates + (shape.normals ? 3 : 0) + item;
  if (name === 'texcoord') return count - 2 + item;
  return item;
}

function readTextOff(scanner: TextScanner, shape: OffShape, notes: string[], progress: Progress): OffRead {
  const bytes = scanner.bytes;
  // the counts: vertices and faces, then an optional edge count, on one line
  if (!scanner.skipBlankLines()) scanner.fail('the file ends before the counts (vertices, faces, edges)');
  const countsAt = scanner.location();
  const vertexCount = scanner.integer();
  if (scanner.atLineEnd() && !scanner.skipBlankLines()) scanner.fail('the file ends before the number of faces');
  const faceCount = scanner.integer();
  if (!scanner.atLineEnd()) scanner.integer();
  scanner.endLine('the counts are vertices, faces and edges');
  const rowsStart = { start: scanner.pos, line: scanner.line };
  if (vertexCount < 0 || faceCount < 0) {
    throw new ParseError('off', countsAt, `negative counts: ${vertexCount} vertices, ${faceCount} faces`);
  }
  // refuse counts the file cannot hold before allocating: a number takes at least 2 bytes
  const numbersPerVertex = shape.dimension + (shape.homogeneous ? 1 : 0);
  const leastBytes = 2 * (vertexCount * numbersPerVertex + faceCount * 2) - 1;
  const bytesLeft = bytes.length - scanner.pos;
  if (leastBytes > bytesLeft) {
    throw new ParseError(
      'off',
      countsAt,
      `the counts announce ${plural(vertexCount, 'vertex', 'vertices')} and ${plural(faceCount, 'face')}, ` +
        `but only ${plural(bytesLeft, 'byte')} follow: far too few`,
    );
  }

  const mesh = new OffMesh(shape, vertexCount, faceCount);
  const maxValues = maxValuesPerLine(shape);
  const values = new Float64Array(maxValues);
  const integral = new Uint8Array(maxValues);
  /** Reads the numbers left on the line of `element` `id` into `values`; returns how many. */
  const readLine = (element: 'vertex' | 'face', id: number): number => {
    let count = 0;
    while (!scanner.atLineEnd()) {
      if (count === maxValues) scanner.fail(`${element} ${id} has more than ${maxValues} numbers`);
      values[count] = scanner.number();
      integral[count++] = scanner.integral ? 1 : 0;
    }
    return count;
  };

  /** Reads one more number, from the next line when this one has ended; false at the end of the file. */
  const readOnward = (count: number): boolean => {
    if (scanner.atLineEnd() && !scanner.skipBlankLines()) return false;
    values[count] = scanner.number();
    integral[count] = scanner.integral ? 1 : 0;
    return true;
  };
  // the fewest numbers a vertex has: a vertex that ends its line before them goes on over the next
  const fewest = numbersPerVertex + (shape.normals ? 3 : 0) + (shape.colors ? 3 : 0) + (shape.texcoords ? 2 : 0);

  /**
   * OFF is a stream of numbers: an element may go on over several lines. That is rare, and is also
   * what a line with a number too few looks like, whose error then shows further on: the first
   * element that did so is named in any error after it.
   */
  let firstSpan: string | undefined;
  /** Reads vertex `v` token by token, from its first. */
  const readVertex = (v: number): void => {
    const line = scanner.line;
    let count = readLine('vertex', v);
    for (; count < fewest; count++) {
      if (!readOnward(count)) scanner.fail(`the file ends inside vertex ${v}`);
    }
    if (scanner.line !== line) firstSpan ??= `vertex ${v} went on from line ${line} onto line ${scanner.line}`;
    const problem = mesh.setVertex(v, values, integral, 0, count);
    if (problem !== null) scanner.fail(problem);
  };
  const { faceStarts, faceIndices } = mesh;
  /** Reads face `f` token by token, from its first. */
  const readFace = (f: number): void => {
    const at = scanner.pos;
    const line = scanner.line;
    const degree = scanner.integer();
    if (degree < 1) {
      scanner.fail(`face ${f} has ${degree} corners; a face needs at least one`, at);
    }
    // room for no more ids than the rest of the file holds (an id and a space take two bytes): a
    // count beyond it is refused where the ids run out, as in the same file with comments, longer
    const room = Math.floor((bytes.length - scanner.pos + 1) / 2);
    const indices = faceIndices.reserveRow(Math.min(degree, room), f, faceCount, faceIndices.length + room);
    let n = faceIndices.length;
    for (let k = 0; k < degree; k++) {
      if (scanner.atLineEnd() && !scanner.skipBlankLines()) {
        scanner.fail(`the file ends inside face ${f}, which announces ${degree} corners but lists ${k} vertex ids`);
      }
      const indexAt = scanner.pos;
      const index = scanner.integer();
      if (index < 0 || index >= vertexCount) scanner.fail(indexOutOfRange(f, index, vertexCount), indexAt);
      indices[n++] = index;
    }
    faceIndices.length = n;
    faceStarts[f + 1] = n;
    if (scanner.line !== line) firstSpan ??= `face ${f} went on from line ${line} onto line ${scanner.line}`;
    // the colour runs from the last index to the end of its line (Geomview's rule)
    const problem = mesh.setFaceColor(f, values, integral, 0, readLine('face', f));
    if (problem !== null) scanner.fail(problem);
    scanner.endLine(`face ${f} should end here`);
  };

  // each element goes by the fast lane, a batch of plain lines at a time, for as long as its line
  // holds it whole; the first other one is read token by token, which also says what is wrong with it
  try {
    scanner.readRows(
      vertexCount,
      (batch, lines, v) => storeVertices(mesh, batch, lines, v, fewest, maxValues),
      readVertex,
      (v) => `the file ends after ${v} of ${plural(vertexCount, 'vertex', 'vertices')}`,
      progress,
    );
    scanner.readRows(
      faceCount,
      (batch, lines, f, bytesLeft) => storeFaces(mesh, batch, lines, f, bytesLeft),
      readFace,
      (f) => `the file ends after ${f} of ${plural(faceCount, 'face')}`,
      progress,
    );
  } catch (error) {
    if (!(error instanceof ParseError) || firstSpan === undefined) throw error;
    throw new ParseError('off', error.location, `${error.reason} (note: ${firstSpan}; if it should not, it lists too few numbers)`);
  }
  if (scanner.skipBlankLines()) notes.push(`ignored the text after the last face (from line ${scanner.line})`);
  const file: OffRead['file'] = {
    format: 'off',
    encoding: 'ascii',
    soup: mesh.finish(notes),
    counts: { vertices: vertexCount, faces: faceCount },
  };
  const locate: Locate = (element, name, index, item) => {
    const row = new TextScanner(bytes, 'off', { hashComments: true, ...rowsStart });
    const numbers: FileLocation[] = [];
    for (let v = 0; v < (element === 'vertex' ? index : vertexCount); v++) readTextVertex(row, fewest, null);
    if (element === 'vertex') {
      readTextVertex(row, fewest, numbers);
      return numbers[vertexNumber(shape, name, item, numbers.length)];
    }
    // a face's only value is its colour, the numbers after its vertex ids
    for (let f = 0; f <= index; f++) readTextFace(row, f === index ? numbers : null);
    return numbers[item];
  };
  return { file, locate };
}

/**
 * Reads past a vertex as `readTextOff` reads it (the numbers of its line, and more from the lines
 * after while it has fewer than `fewest`), adding where each of its numbers is to `numbers`.
 */
function readTextVertex(scanner: TextScanner, fewest: number, numbers: FileLocation[] | null): void {
  scanner.skipBlankLines();
  let count = 0;
  for (; !scanner.atLineEnd(); count++) {
    numbers?.push(scanner.location());
    scanner.number();
  }
  for (; count < fewest; count++) {
    if (scanner.atLineEnd()) scanner.skipBlankLines();
    numbers?.push(scanner.location());
    scanner.number();
  }
}

/** Reads past a face as `readTextOff` reads it, adding where each number of its colour is to `numbers`. */
function readTextFace(scanner: TextScanner, numbers: FileLocation[] | null): void {
  scanner.skipBlankLines();
  const degree = scanner.integer();
  for (let k = 0; k < degree; k++) {
    if (scanner.atLineEnd()) scanner.skipBlankLines();
    scanner.integer();
  }
  while (!scanner.atLineEnd()) {
    numbers?.push(scanner.location());
    scanner.number();
  }
  scanner.nextLine();
}

/**
 * The fast lane's part for vertices: stores the lines of a batch (the first being vertex
 * `firstVertex`) for as long as each line holds one whole vertex (`fewest` to `most` numbers that
 * `setVertex` takes); returns how many it stored.
 */
function storeVertices(mesh: OffMesh, batch: PlainLines, lines: number, firstVertex: number, fewest: number, most: number): number {
  const { values, integral, ends } = batch;
  let r = 0;
  for (let from = 0; r < lines; r++) {
    const count = ends[r] - from;
    if (count < fewest || count > most || mesh.setVertex(firstVertex + r, values, integral, from, count) !== null) break;
    from = ends[r];
  }
  return r;
}

/**
 * The fast lane's part for faces: stores the lines of a batch (the first being face `firstFace`,
 * `bytesLeft` bytes of the file after it) for as long as each line holds one whole face (a corner
 * count, that many vertex ids in range, whole numbers all, then what `setFaceColor` takes);
 * returns how many it stored.
 */
function storeFaces(mesh: OffMesh, batch: PlainLines, lines: number, firstFace: number, bytesLeft: number): number {
  const vertexCount = mesh.positions.length / 3;
  const faceCount = mesh.faceStarts.length - 1;
  const { values, integral, ends } = batch;
  const { faceStarts, faceIndices } = mesh;
  let r = 0;
  for (let from = 0; r < lines; r++) {
    const to = ends[r];
    const degree = values[from];
    if (!integral[from] || !(degree >= 1 && degree < to - from)) break;
    const last = from + degree;
    let k = from + 1;
    while (k <= last && integral[k] && values[k] >= 0 && values[k] < vertexCount) k++;
    if (k <= last || mesh.setFaceColor(firstFace + r, values, integral, last + 1, to - last - 1) !== null) break;
    // what the rest of the batch and the file after it can hold: an index takes at least two bytes
    const indices = faceIndices.reserveRow(degree, firstFace + r, faceCount, faceIndices.length + ends[lines - 1] + bytesLeft / 2);
    let n = faceIndices.length;
    for (k = from + 1; k <= last; k++) indices[n++] = values[k];
    faceIndices.length = n;
    faceStarts[firstFace + r + 1] = n;
    from = to;
  }
  return r;
}

function indexOutOfRange(f: number, index: number, vertexCount: number): string {
  if (vertexCount === 0) return `face ${f}: vertex index ${index} refers to a vertex, but the file has none`;
  return `face ${f}: vertex index ${index} is out of range 0..${vertexCount - 1}`;
}

// -------------------------------------------------------------------------------------------------
// Binary

interface BinaryLayout {
  littleEndian: boolean;
  /** Geomview's spec: each face ends with a colour count and that many floats. */
  faceColorCount: boolean;
}

const binaryLayouts: BinaryLayout[] = [
  { littleEndian: false, faceColorCount: true },
  { littleEndian: true, faceColorCount: true },
  { littleEndian: true, faceColorCount: false },
  { littleEndian: false, faceColorCount: false },
];

function readBinaryOff(bytes: Uint8Array, start: number, shape: OffShape, notes: string[]): OffRead {
  // try each layout; the one that ends exactly at the end of the file is the file's
  let best: { result: BinaryResult; layout: BinaryLayout } | null = null;
  let furthest: ParseError | null = null;
  for (const layout of binaryLayouts) {
    try {
      const result = readBinaryLayout(bytes, start, shape, layout);
      if (result.end === bytes.length) {
        best = { result, layout };
        break;
      }
      best ??= { result, layout };
    } catch (error) {
      if (!(error instanceof ParseError)) throw error;
      if (!furthest || (error.location.byteOffset ?? 0) > (furthest.location.byteOffset ?? 0)) furthest = error;
    }
  }
  if (!best) throw furthest!;
  const { result, layout } = best;
  const order = layout.littleEndian ? 'little-endian' : 'big-endian';
  const counts = layout.faceColorCount ? 'with a colour count after each face' : 'without face colour counts';
  const spec = layout.littleEndian || !layout.faceColorCount ? ' (the Geomview spec says big-endian, with counts)' : '';
  notes.push(`OFF BINARY read as ${order} ${counts}${spec}`);
  if (result.end < bytes.length) notes.push(`ignored ${plural(bytes.length - result.end, 'byte')} after the last face`);
  const file: OffRead['file'] = {
    format: 'off',
    encoding: layout.littleEndian ? 'binary_little_endian' : 'binary_big_endian',
    soup: result.mesh.finish(notes),
    counts: { vertices: result.vertexCount, faces: result.faceCount },
  };
  const { mesh, vertexStart, floatsPerVertex } = result;
  const view = viewOf(bytes);
  const int32At = (offset: number) => view.getInt32(offset, layout.littleEndian);
  const locate: Locate = (element, name, index, item) => {
    if (element === 'vertex') {
      return { byteOffset: vertexStart + 4 * (index * floatsPerVertex + vertexNumber(mesh.shape, name, item, floatsPerVertex)) };
    }
    // a face's only value is its colour, after its corner count, its vertex ids and its colour count
    let offset = vertexStart + 4 * floatsPerVertex * result.vertexCount;
    for (let f = 0; f < index; f++) {
      offset += 4 + 4 * int32At(offset);
      offset += 4 + 4 * int32At(offset);
    }
    offset += 4 + 4 * int32At(offset);
    return { byteOffset: offset + 4 + 4 * item };
  };
  return { file, locate };
}

interface BinaryResult {
  mesh: OffMesh;
  vertexCount: number;
  faceCount: number;
  /** Where the vertices begin, and how many float32 each is. */
  vertexStart: number;
  floatsPerVertex: number;
  end: number;
}

function readBinaryLayout(bytes: Uint8Array, start: number, keywordShape: OffShape, layout: BinaryLayout): BinaryResult {
  const reader = new BinaryReader(bytes, 'off', layout.littleEndian, start);
  const shape = { ...keywordShape };
  if (shape.dimensionFollows) {
    // nOFF BINARY: the dimension is the first int32 after the header line, before the counts
    reader.need(4, 'the dimension that nOFF announces');
    shape.dimension = reader.int32();
    checkDimension(shape.dimension, bytes.length, (reason) => reader.fail(reason, start));
  }
  reader.need(12, 'the counts (vertices, faces, edges)');
  const vertexCount = reader.int32();
  const faceCount = reader.int32();
  reader.int32();
  // every vertex is its floats (binary colours are always RGBA); every face at least a corner
  // count and one index
  const coordinates = shape.dimension + (shape.homogeneous ? 1 : 0);
  const floatsPerVertex = coordinates + (shape.normals ? 3 : 0) + (shape.colors ? 4 : 0) + (shape.texcoords ? 2 : 0);
  if (vertexCount < 0 || faceCount < 0 || 4 * (vertexCount * floatsPerVertex + 2 * faceCount) > reader.remaining) {
    const counts = `${vertexCount} vertices, ${faceCount} faces`;
    reader.fail(`the counts (${counts}) do not fit in the ${plural(reader.remaining, 'byte')} that follow`, start);
  }
  const mesh = new OffMesh(shape, vertexCount, faceCount);
  const values = new Float64Array(maxValuesPerLine(shape));
  const integral = new Uint8Array(values.length);
  const vertexStart = reader.offset;
  for (let v = 0; v < vertexCount; v++) {
    for (let k = 0; k < floatsPerVertex; k++) values[k] = reader.float32();
    const problem = mesh.setVertex(v, values, integral, 0, floatsPerVertex);
    if (problem !== null) reader.fail(problem);
  }
  const { faceStarts, faceIndices } = mesh;
  for (let f = 0; f < faceCount; f++) {
    reader.need(4, `face ${f}`);
    const degreeAt = reader.offset;
    const degree = reader.int32();
    if (degree < 1) reader.fail(`face ${f} has ${degree} corners; a face needs at least one`, degreeAt);
    if (4 * degree > reader.remaining) {
      reader.fail(`face ${f} announces ${degree} corners, more than the rest of the file holds`, degreeAt);
    }
    const indices = faceIndices.reserveRow(degree, f, faceCount, faceIndices.length + reader.remaining / 4);
    let n = faceIndices.length;
    for (let k = 0; k < degree; k++) {
      const indexAt = reader.offset;
      const index = reader.int32();
      if (index < 0 || index >= vertexCount) reader.fail(indexOutOfRange(f, index, vertexCount), indexAt);
      indices[n++] = index;
    }
    faceIndices.length = n;
    faceStarts[f + 1] = n;
    if (!layout.faceColorCount) continue;
    const colorAt = reader.offset;
    const colorCount = reader.int32();
    if (colorCount < 0 || colorCount > 4) {
      reader.fail(`face ${f} announces ${colorCount} colour components (0 to 4 expected)`, colorAt);
    }
    for (let k = 0; k < colorCount; k++) values[k] = reader.float32();
    const problem = mesh.setFaceColor(f, values, integral, 0, colorCount);
    if (problem !== null) reader.fail(problem);
  }
  return { mesh, vertexCount, faceCount, vertexStart, floatsPerVertex, end: reader.offset };
}
