/**
 * OBJ (Wavefront): one statement a line, named by its first word.
 *
 * ```
 * v 0 0 0                 a vertex: x y z (then an optional w, or a colour r g b)
 * vt 0.5 1                a texture coordinate: u [v [w]]
 * vn 0 0 1                a normal
 * f 1/1/1 2/2/1 3/3/1     a face; each corner is v, v/vt, v//vn or v/vt/vn
 * ```
 *
 * Indices count from 1 in the order the statements come; a negative one counts back from the
 * latest (-1 is the vertex just above). Each corner names its own texture coordinate and normal,
 * so one vertex may have several (along a texture seam): they become the corner attributes
 * `texcoord` and `normal`, which the builder turns into halfedge attributes. Groups, objects,
 * materials, smoothing groups, lines and points mean nothing to a halfedge mesh: each kind is
 * counted in the notes and skipped.
 */
import { type FileLocation, ParseError } from '../errors.js';
import { plural } from '../report.js';
import type { SoupAttribute } from '../soup.js';
import { GrowableArray } from './growable.js';
import { type Locate, type MeshFile, type Progress, PROGRESS_ROWS, type ReaderOutput } from './mesh-file.js';
import { PlainLines, TextScanner } from './text.js';

const SLASH = 47;
const SPACE = 32;
const HASH = 35;
const LOWER_F = 102;
const LOWER_V = 118;

/** A face index read before its element was defined, kept to check once the file is read. */
interface ForwardReference {
  index: number;
  face: number;
  line: number;
  column: number;
}

/** Indices into one list (v, vt or vn) as the file gives them. */
class IndexResolver {
  readonly name: string;
  count = 0;
  /** The largest index met that was beyond the list at the time. */
  furthest: ForwardReference | null = null;

  constructor(name: string) {
    this.name = name;
  }

  /** The 0-based index that `written` (1-based, or negative: relative) names. */
  resolve(written: number, face: number, scanner: TextScanner, at: number): number {
    if (written === 0) scanner.fail(`face ${face}: OBJ ${this.name} indices count from 1; 0 names nothing`, at);
    const index = written > 0 ? written - 1 : this.count + written;
    if (index < 0) {
      const reason = `${this.name} index ${written} reaches back before the first ${this.name} (${this.count} so far)`;
      scanner.fail(`face ${face}: ${reason}`, at);
    }
    if (index >= this.count && (this.furthest === null || index > this.furthest.index)) {
      this.furthest = { index, face, ...scanner.location(at) };
    }
    return index;
  }

  /** @throws ParseError when an index named an element the file never defined. */
  check(): void {
    const furthest = this.furthest;
    if (furthest === null || furthest.index < this.count) return;
    const { index, face, line, column } = furthest;
    const range = this.count === 0 ? `the file has no ${this.name}` : `it is out of range 1..${this.count}`;
    const reason = `face ${face}: ${this.name} index ${index + 1} names nothing: ${range}`;
    throw new ParseError('obj', { line, column }, reason);
  }
}

/**
 * Reads an OBJ file into a polygon soup, with per-corner texture coordinates and normals.
 * @throws ParseError with the line and column.
 */
export function readObj(bytes: Uint8Array, progress: Progress): ReaderOutput {
  const comments: string[] = [];
  const notes: string[] = [];
  const scanner = new TextScanner(bytes, 'obj', { hashComments: true, comments });
  const guess = bytes.length >> 6;
  const positions = new GrowableArray((n) => new Float64Array(n), 3 * guess);
  const texcoords = new GrowableArray((n) => new Float32Array(n), 0);
  const normals = new GrowableArray((n) => new Float32Array(n), 0);
  // typed by assertion: `addVertex` sets it, where the compiler does not look when it narrows
  let colors = null as GrowableArray<Float32Array<ArrayBuffer>> | null;
  /** Vertices without a colour in a file that colours some (left black). */
  let uncolored = 0;
  const faceStarts = new GrowableArray((n) => new Uint32Array(n), guess);
  faceStarts.push(0);
  const faceIndices = new GrowableArray((n) => new Uint32Array(n), 3 * guess);
  // per corner: which vt and vn it names (-1: none); made when the first corner names one
  let cornerTexcoords: GrowableArray<Int32Array<ArrayBuffer>> | null = null;
  let cornerNormals: GrowableArray<Int32Array<ArrayBuffer>> | null = null;
  const vertexIds = new IndexResolver('vertex');
  const texcoordIds = new IndexResolver('texture coordinate');
  const normalIds = new IndexResolver('normal');
  const ignored = new Map<string, number>();
  const values = new Float64Array(8);
  let statements = 0;

  /** The numbers left on this line (at most 8), in `values`. */
  const readNumbers = (what: string): number => {
    let count = 0;
    while (!scanner.atLineEnd()) {
      if (count === values.length) scanner.fail(`${what} has more than ${values.length} numbers`);
      values[count++] = scanner.number();
    }
    return count;
  };
  /** Whether a number follows right here (not a space, a slash or the end of the line). */
  const numberFollows = (): boolean => {
    const c = bytes[scanner.pos];
    return c !== undefined && c > SPACE && c !== SLASH && c !== HASH;
  };
  /** Per-corner ids, for when the first corner names one: the corners before it name none. */
  const noneSoFar = () => {
    const ids = new GrowableArray((n) => new Int32Array(n), faceIndices.data.length);
    ids.pushRepeated(-1, faceIndices.length - 1);
    return ids;
  };

  /**
   * Adds a vertex from the `count` numbers at `source[at]`: x y z, then an optional w (dropped) or
   * a colour r g b; false, adding nothing, for any other count.
   */
  const addVertex = (source: Float64Array, at: number, count: number): boolean => {
    if (count !== 3 && count !== 4 && count !== 6) return false;
    const data = positions.reserve(3);
    for (let k = 0; k < 3; k++) data[positions.length++] = source[at + k];
    if (count === 6) {
      if (!colors) {
        colors = new GrowableArray((n) => new Float32Array(n), positions.data.length);
        uncolored = vertexIds.count;
        colors.pushRepeated(0, 3 * uncolored);
      }
      for (let k = 3; k < 6; k++) colors.push(source[at + k]);
    } else if (colors) {
      colors.pushRepeated(0, 3);
      uncolored++;
    }
    vertexIds.count++;
    return true;
  };

  // the fast lane: runs of plain 'v x y z' and 'f i j k' lines, a batch at a time, each stored
  // when it is a whole vertex, or a face of vertices already defined; the first other line, and
  // every other statement, is read token by token, which also says what is wrong with it
  const batch = new PlainLines();
  const { values: numbers, integral, ends } = batch;
  /** Stores the batch's `lines` vertex lines for as long as each is a vertex; returns how many. */
  const storeVertices = (lines: number): number => {
    let r = 0;
    for (let from = 0; r < lines && addVertex(numbers, from, ends[r] - from); r++) from = ends[r];
    return r;
  };
  /** The 0-based vertex a face's corner names, or -1 for a number the token path must read (and may refuse). */
  const cornerVertex = (k: number): number => {
    const written = numbers[k];
    const index = written > 0 ? written - 1 : vertexIds.count + written;
    return integral[k] && written !== 0 && index >= 0 && index < vertexIds.count ? index : -1;
  };
  /** Stores the batch's `lines` face lines for as long as each names vertices already defined; returns how many. */
  const storeFaces = (lines: number): number => {
    let r = 0;
    for (let from = 0; r < lines; r++) {
      const to = ends[r];
      let k = from;
      while (k < to && cornerVertex(k) >= 0) k++;
      if (k < to) break;
      for (k = from; k < to; k++) {
        faceIndices.push(cornerVertex(k));
        cornerTexcoords?.push(-1);
        cornerNormals?.push(-1);
      }
      faceStarts.push(faceIndices.length);
      from = to;
    }
    return r;
  };

  while (scanner.skipBlankLines()) {
    const lead = bytes[scanner.pos];
    if (lead === LOWER_V || lead === LOWER_F) {
      const lines = scanner.plainLines(batch, Infinity, lead);
      const r = lead === LOWER_V ? storeVertices(lines) : storeFaces(lines);
      if ((statements ^ (statements + r)) > PROGRESS_ROWS) progress(scanner.pos / bytes.length);
      statements += r;
      if (r > 0 && r === lines) continue;
      if (r < lines) scanner.backTo(batch, r);
    }
    if ((++statements & PROGRESS_ROWS) === 0) progress(scanner.pos / bytes.length);
    const keywordAt = scanner.pos;
    const keyword = scanner.word();
    switch (keyword) {
      case 'v': {
        const count = readNumbers('a vertex');
        if (!addVertex(values, 0, count)) {
          const reason = `a vertex has x y z (then an optional w, or a colour r g b), not ${plural(count, 'number')}`;
          scanner.fail(reason, keywordAt);
        }
        break;
      }
      case 'vt': {
        const count = readNumbers('a texture coordinate');
        if (count < 1 || count > 3) {
          scanner.fail(`a texture coordinate has u [v [w]], not ${plural(count, 'number')}`, keywordAt);
        }
        texcoords.push(values[0]);
        texcoords.push(count > 1 ? values[1] : 0);
        texcoordIds.count++;
        break;
      }
      case 'vn': {
        if (readNumbers('a normal') !== 3) scanner.fail('a normal has 3 numbers: x y z', keywordAt);
        for (let k = 0; k < 3; k++) normals.push(values[k]);
        normalIds.count++;
        break;
      }
      case 'f': {
        const face = faceStarts.length - 1;
        while (!scanner.atLineEnd()) {
          const at = scanner.pos;
          faceIndices.push(vertexIds.resolve(scanner.integer(true), face, scanner, at));
          let texcoord = -1;
          let normal = -1;
          if (bytes[scanner.pos] === SLASH) {
            scanner.pos++;
            const texcoordAt = scanner.pos;
            if (numberFollows()) texcoord = texcoordIds.resolve(scanner.integer(true), face, scanner, texcoordAt);
            if (bytes[scanner.pos] === SLASH) {
              scanner.pos++;
              const normalAt = scanner.pos;
              if (numberFollows()) normal = normalIds.resolve(scanner.integer(), face, scanner, normalAt);
            }
          }
          if (texcoord >= 0) cornerTexcoords ??= noneSoFar();
          if (normal >= 0) cornerNormals ??= noneSoFar();
          cornerTexcoords?.push(texcoord);
          cornerNormals?.push(normal);
        }
        if (faceIndices.length === faceStarts.data[face]) scanner.fail(`face ${face} has no corners`, keywordAt);
        faceStarts.push(faceIndices.length);
        break;
      }
      default:
        ignored.set(keyword, (ignored.get(keyword) ?? 0) + 1);
        scanner.nextLine();
        continue;
    }
    scanner.endLine(() => `the '${keyword}' statement should end here`);
  }
  vertexIds.check();
  texcoordIds.check();
  normalIds.check();

  const vertexCount = vertexIds.count;
  const faceCount = faceStarts.length - 1;
  const vertexAttributes: SoupAttribute[] = [];
  if (colors) {
    if (uncolored > 0) notes.push(`${plural(uncolored, 'vertex has', 'vertices have')} no colour (left black)`);
    vertexAttributes.push({ name: 'color', itemSize: 3, data: colors.finish() });
  }
  const cornerAttributes: SoupAttribute[] = [];
  const texcoordOfCorner = cornerTexcoords?.finish();
  const normalOfCorner = cornerNormals?.finish();
  if (texcoordOfCorner) cornerAttributes.push(gather('texcoord', 2, texcoords.finish(), texcoordOfCorner, notes));
  if (normalOfCorner) cornerAttributes.push(gather('normal', 3, normals.finish(), normalOfCorner, notes));
  if (ignored.size > 0) {
    // a file that is not really OBJ can have thousands of "statements": name the first few kinds
    const total = [...ignored.values()].reduce((a, b) => a + b, 0);
    const kinds = [...ignored].slice(0, 8).map(([name, n]) => `${n} '${name.slice(0, 24)}'`);
    if (ignored.size > 8) kinds.push(`${ignored.size - 8} other kinds`);
    notes.push(`ignored ${plural(total, 'OBJ statement')}: ${kinds.join(', ')}`);
  }
  if (vertexCount > 0 && faceCount === 0) notes.push('no faces: loaded as a point set');
  if (scanner.droppedComments > 0) {
    notes.push(`kept the first ${comments.length} comments, ${scanner.droppedComments} more not kept`);
  }
  const locate: Locate = (element, name, index, item) => {
    // a vertex's colour follows its x y z; a corner's normal or texture coordinate is the one its
    // `vn` or `vt` statement gives (only the attributes there are, of vertices and corners, are asked for)
    if (element === 'vertex') return statementPlace(bytes, 'v', index, name === 'color' ? 3 + item : item);
    if (name === 'normal') return statementPlace(bytes, 'vn', normalOfCorner![index], item);
    return statementPlace(bytes, 'vt', texcoordOfCorner![index], item);
  };
  const file: MeshFile = {
    format: 'obj',
    encoding: 'ascii',
    soup: {
      positions: positions.finish(),
      faceStarts: faceStarts.finish(),
      faceIndices: faceIndices.finish(),
      vertexAttributes,
      cornerAttributes,
    },
    counts: { vertices: vertexCount, faces: faceCount },
    comments,
    notes,
  };
  return { file, locate };
}

/**
 * Where number `item` of the `index`-th statement `keyword` (`v`, `vt`, `vn`) is. Walks the file
 * statement by statement, a line each, as `readObj` read it.
 */
function statementPlace(bytes: Uint8Array, keyword: string, index: number, item: number): FileLocation {
  const scanner = new TextScanner(bytes, 'obj', { hashComments: true });
  let seen = 0;
  while (scanner.skipBlankLines()) {
    if (scanner.word() === keyword && seen++ === index) {
      for (let k = 0; k < item; k++) scanner.number();
      scanner.skipSpaces();
      break;
    }
    scanner.nextLine();
  }
  return scanner.location();
}

/** One value per corner, looked up from the list the corners index (-1: none, left zero). */
function gather(
  name: string,
  itemSize: number,
  list: Float32Array<ArrayBuffer>,
  cornerIds: Int32Array,
  notes: string[],
): SoupAttribute {
  const data = new Float32Array(itemSize * cornerIds.length);
  let missing = 0;
  for (let c = 0; c < cornerIds.length; c++) {
    const id = cornerIds[c];
    if (id < 0) missing++;
    // item by item: a view of the list for each corner would cost more than the copy
    else for (let k = 0; k < itemSize; k++) data[itemSize * c + k] = list[itemSize * id + k];
  }
  if (missing > 0) notes.push(`${plural(missing, 'face corner names', 'face corners name')} no ${name} (set to zero)`);
  return { name, itemSize, data };
}
