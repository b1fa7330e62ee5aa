/**
 * PLY, the Stanford polygon file format: a text header that declares *elements* (tables) and
 * their *properties* (typed columns), then the rows of every element in order, as text or as
 * packed binary in either byte order.
 *
 * ```
 * ply
 * format binary_little_endian 1.0        ascii | binary_little_endian | binary_big_endian
 * comment any text
 * element vertex 8                       a table of 8 rows …
 * property float x                       … whose columns are typed scalars
 * property float y
 * property float z
 * element face 6
 * property list uchar int vertex_indices … or lists: a count, then that many items
 * end_header
 * <8 vertex rows, then 6 face rows>
 * ```
 *
 * A file may declare any element and property, so a reader must step over the ones it does not
 * use; in binary that means knowing every type's size and reading every list's count. This one
 * keeps what a halfedge mesh can carry and says in `notes` what it skipped:
 *   - vertex `x y z` → positions (float32 when the file's are, else float64);
 *   - vertex `nx ny nz` → `normal` (float32 × 3); `u v`, `s t` or `texture_u texture_v` →
 *     `texcoord` (float32 × 2); `red green blue [alpha]` (or `diffuse_*`) → `color`, in the
 *     file's type (uint8 for uchar colours, float32 for float ones);
 *   - face `vertex_indices` (or `vertex_index`, or the only list) → faces, any degree;
 *     face `red green blue [alpha]` → face `color`; a face list `texcoord` (two numbers per
 *     corner) → corner `texcoord`;
 *   - any other scalar property → an attribute under its own name, in its own type;
 *   - a `tristrips` element (strips of vertex ids, -1 between strips) → triangles.
 *
 * Before anything is allocated, every element's row count is checked against the bytes left, so
 * a 40-byte file that claims two billion faces is refused at once.
 *
 * Each value of the soup remembers the properties it was read from, so that one that is NaN or
 * infinite can be found in the file again (`finite.ts`): a byte offset from the element's layout,
 * or the line of its row and the column of its token.
 */
import { attributeArrayTypes, type AttributeType } from '../attributes.js';
import { type FileLocation, ParseError } from '../errors.js';
import { plural } from '../report.js';
import type { SoupAttribute } from '../soup.js';
import { BinaryReader, type NumberTarget, type ScalarType, scalarTypes, viewOf } from './binary.js';
import { GrowableArray } from './growable.js';
import { type Encoding, type Locate, type MeshFile, type Progress, PROGRESS_ROWS, type ReaderOutput, type SoupElement } from './mesh-file.js';
import { quoted, someOf } from './names.js';
import { type PlainLines, TextScanner } from './text.js';

/**
 * Every PLY type name, old (`uchar`) and new (`uint8`), and the type of the values it holds. A Map,
 * not an object: a file's type name must not find `constructor` or `toString` on a prototype.
 */
const plyTypeNames = new Map<string, AttributeType>([
  ['char', 'int8'],
  ['int8', 'int8'],
  ['uchar', 'uint8'],
  ['uint8', 'uint8'],
  ['short', 'int16'],
  ['int16', 'int16'],
  ['ushort', 'uint16'],
  ['uint16', 'uint16'],
  ['int', 'int32'],
  ['int32', 'int32'],
  ['uint', 'uint32'],
  ['uint32', 'uint32'],
  ['float', 'float32'],
  ['float32', 'float32'],
  ['double', 'float64'],
  ['float64', 'float64'],
]);

const encodings: readonly Encoding[] = ['ascii', 'binary_little_endian', 'binary_big_endian'];

/** Property names that make up one attribute, first spelling first. */
const normalNames = [['nx', 'ny', 'nz']];
const colorNames = [
  ['red', 'green', 'blue', 'alpha'],
  ['diffuse_red', 'diffuse_green', 'diffuse_blue', 'diffuse_alpha'],
];
const texcoordNames = [
  ['u', 'v'],
  ['s', 't'],
  ['texture_u', 'texture_v'],
  ['texture_s', 'texture_t'],
];
/** Names the soup gives its own meaning; a scalar property of the same name would clash. */
const reservedNames = new Set(['position', 'normal', 'color', 'texcoord']);

interface PlyProperty {
  name: string;
  type: ScalarType;
  /** The type of a list's count; null for a scalar property. */
  countType: ScalarType | null;
}

interface PlyElement {
  name: string;
  count: number;
  properties: PlyProperty[];
  /** Header line that declares it, for messages. */
  line: number;
}

interface PlyHeader {
  encoding: Encoding;
  elements: PlyElement[];
  comments: string[];
  notes: string[];
  /** Byte offset and line number where the data begins. */
  bodyStart: number;
  bodyLine: number;
}

/**
 * Reads a PLY file (any of the three encodings) into a polygon soup.
 * @throws ParseError with the line (header, ascii data) or byte offset (binary data).
 */
export function readPly(bytes: Uint8Array, progress: Progress): ReaderOutput {
  const header = readHeader(bytes);
  checkCountsFit(header, bytes.length);
  const plan = planElements(header);
  if (header.encoding === 'ascii') readAsciiBody(bytes, header, plan, progress);
  else readBinaryBody(bytes, header, plan, progress);
  const file = assemble(header, plan);
  const locate: Locate = (element, name, index, item) => {
    const { element: source, properties } = plan.sources.get(sourceKey(element, name))!;
    const elementPlan = plan.elements.find((e) => e.element === source)!;
    if (element !== 'corner') return valuePlace(bytes, header.encoding, elementPlan, index, properties[item], null);
    // a corner's texture coordinate: two items of its face's list per corner
    const { faceStarts } = file.soup;
    let face = 0;
    while (faceStarts[face + 1] <= index) face++;
    return valuePlace(bytes, header.encoding, elementPlan, face, properties[0], 2 * (index - faceStarts[face]) + item);
  };
  return { file, locate };
}

// -------------------------------------------------------------------------------------------------
// The header

function readHeader(bytes: Uint8Array): PlyHeader {
  const scanner = new TextScanner(bytes, 'ply');
  if (scanner.word() !== 'ply') scanner.fail("a PLY file starts with the line 'ply'", 0);
  scanner.endLine("the first line should be just 'ply'");
  if (indexOfText(bytes, 'end_header') < 0) {
    const reason = "the file ends before 'end_header': the header is cut off";
    throw new ParseError('ply', { byteOffset: bytes.length }, reason);
  }
  const elements: PlyElement[] = [];
  const comments: string[] = [];
  const notes: string[] = [];
  /** Header lines without a keyword, noted once at the end. */
  const unknownLines: number[] = [];
  let firstUnknownText = '';
  let encoding: Encoding | null = null;

  const nextType = (): ScalarType => {
    scanner.skipSpaces();
    const at = scanner.pos;
    const name = scanner.word();
    const type = plyTypeNames.get(name);
    if (type === undefined) {
      const types = 'char, uchar, short, ushort, int, uint, float, double, or int8 … float64';
      return scanner.fail(`unknown property type '${scanner.token(at)}' (PLY types: ${types})`, at);
    }
    return scalarTypes[type];
  };

  // every pass reads at least one byte of the file, so there are fewer passes than bytes
  for (let pass = 0; ; pass++) {
    if (pass > bytes.length || !scanner.skipBlankLines()) scanner.fail("the header has no 'end_header' line");
    const line = scanner.line;
    const start = scanner.pos;
    const keyword = scanner.word();
    if (keyword === 'end_header') break;
    switch (keyword) {
      case 'format': {
        const at = scanner.pos + 1;
        const name = scanner.word();
        if (!encodings.includes(name as Encoding)) {
          scanner.fail(`unknown format '${name}': PLY data is ascii, binary_little_endian or binary_big_endian`, at);
        }
        encoding = name as Encoding;
        const version = scanner.word();
        if (version !== '1.0') notes.push(`the header gives PLY version '${version}'; read as version 1.0`);
        scanner.endLine('the format line should end after the version');
        break;
      }
      case 'comment':
        comments.push(scanner.restOfLine());
        scanner.nextLine();
        break;
      case 'obj_info':
        comments.push(`obj_info ${scanner.restOfLine()}`.trim());
        scanner.nextLine();
        break;
      case 'element': {
        const name = scanner.word();
        if (!name) scanner.fail('an element needs a name and a row count');
        const at = scanner.pos + 1;
        const count = scanner.integer();
        if (count < 0) scanner.fail(`element '${name}' cannot have ${count} rows`, at);
        scanner.endLine(`the element line should end after the row count`);
        elements.push({ name, count, properties: [], line });
        break;
      }
      case 'property': {
        const element = elements[elements.length - 1];
        if (!element) scanner.fail("a 'property' line comes before any 'element' line", start);
        scanner.skipSpaces();
        const listAt = scanner.pos;
        let countType: ScalarType | null = null;
        if (scanner.word() === 'list') {
          countType = nextType();
          if (countType.type.startsWith('float')) {
            scanner.fail(`a list's count must have an integer type, not ${countType.type}`, listAt);
          }
        } else {
          scanner.pos = listAt;
        }
        const type = nextType();
        const name = scanner.word();
        if (!name) scanner.fail('the property needs a name after its type');
        scanner.endLine(`the property line should end after the name '${name}'`);
        element.properties.push({ name, type, countType });
        break;
      }
      default: {
        // a line without a keyword (Blender 2.47 wrote its banner so): keep the text, go on
        scanner.pos = start;
        const text = scanner.restOfLine();
        comments.push(text);
        if (unknownLines.length === 0) firstUnknownText = text;
        unknownLines.push(line);
        scanner.nextLine();
      }
    }
  }
  if (encoding === null) return scanner.fail("the header has no 'format' line (such as 'format ascii 1.0')");
  if (unknownLines.length === 1) {
    notes.push(`header line ${unknownLines[0]} has no PLY keyword (${quoted(firstUnknownText)}): kept as a comment`);
  } else if (unknownLines.length > 1) {
    const lines = someOf(unknownLines.map(String));
    notes.push(`header lines ${lines} have no PLY keyword (the first: ${quoted(firstUnknownText)}): kept as comments`);
  }

  // after end_header come optional spaces and exactly one line ending: a binary body may well
  // start with the byte 0x0A, which must not be taken for a second line ending
  let bodyStart = scanner.pos;
  while (bytes[bodyStart] === 0x20 || bytes[bodyStart] === 0x09) bodyStart++;
  if (bytes[bodyStart] === 0x0d) bodyStart++;
  if (bytes[bodyStart] === 0x0a) bodyStart++;
  return { encoding, elements, comments, notes, bodyStart, bodyLine: scanner.line + 1 };
}

function indexOfText(bytes: Uint8Array, text: string): number {
  const first = text.charCodeAt(0);
  search: for (let i = bytes.indexOf(first); i >= 0; i = bytes.indexOf(first, i + 1)) {
    for (let k = 1; k < text.length; k++) if (bytes[i + k] !== text.charCodeAt(k)) continue search;
    return i;
  }
  return -1;
}

/**
 * Refuses row counts the file cannot hold, before anything is allocated: a binary row needs at
 * least its scalars and list counts, an ascii value at least one digit and one separator.
 */
function checkCountsFit(header: PlyHeader, fileBytes: number): void {
  const available = fileBytes - header.bodyStart;
  const ascii = header.encoding === 'ascii';
  let needed = 0;
  for (const element of header.elements) {
    let rowBytes = 0;
    for (const { type, countType } of element.properties) {
      if (ascii) rowBytes += 2;
      else rowBytes += countType ? countType.size : type.size;
    }
    const before = needed;
    needed += element.count * rowBytes;
    if (needed > available + 1) {
      const row = ascii ? plural(element.properties.length, 'value') : `at least ${plural(rowBytes, 'byte')}`;
      const most = Math.max(0, Math.floor((available + 1 - before) / rowBytes));
      throw new ParseError(
        'ply',
        { line: element.line },
        `element '${element.name}' announces ${element.count} rows of ${row}, but the ${plural(available, 'byte')} ` +
          `of data hold at most ${most} of them`,
      );
    }
  }
}

// -------------------------------------------------------------------------------------------------
// Where each property's values go

type ListItems = Uint32Array<ArrayBuffer> | Int32Array<ArrayBuffer> | Float32Array<ArrayBuffer>;

/** The items of one list property, row after row (CSR, like the soup's faces). */
class ListCollector<T extends ListItems = ListItems> {
  readonly starts: Uint32Array;
  readonly items: GrowableArray<T>;
  /** Items outside `min … max` are an error (vertex ids must exist; -1 separates strips). */
  readonly min: number;
  readonly max: number;
  /** Vertex indices (faces, strips) rather than values (texture coordinates). */
  readonly holdsIndices: boolean;

  constructor(rows: number, make: (n: number) => T, min: number, max: number) {
    this.starts = new Uint32Array(rows + 1);
    this.items = new GrowableArray(make, 3 * rows);
    this.min = min;
    this.max = max;
    this.holdsIndices = Number.isFinite(min);
  }

  /**
   * Room for `count` more items in row `row`, the rest of the file holding at most `more`; returns
   * the items' array (see `GrowableArray.reserveRow`).
   */
  reserve(count: number, row: number, more: number): T {
    return this.items.reserveRow(count, row, this.starts.length - 1, this.items.length + more);
  }
}

interface PropertyPlan {
  property: PlyProperty;
  /** A list whose count is a uchar (almost all of them). */
  countIsByte: boolean;
  /** A scalar's destination: value of row r at `target[r × stride + offset]`; null to skip it. */
  target: NumberTarget | null;
  stride: number;
  offset: number;
  /** A list's destination; null to skip it. */
  list: ListCollector | null;
}

interface ElementPlan {
  element: PlyElement;
  properties: PropertyPlan[];
  /** Bytes per binary row when every property is a scalar; -1 when rows hold lists. */
  rowBytes: number;
  /** Where its rows begin: a byte offset, and (ascii) the number of that line. */
  start: number;
  startLine: number;
}

/** The properties a soup value was read from: one per item, or the one list whose items they are. */
interface ValueSource {
  element: PlyElement;
  properties: PlyProperty[];
}

/** The key of a soup value in `Plan.sources`. */
const sourceKey = (element: SoupElement, name: string) => `${element}:${name}`;

interface Plan {
  elements: ElementPlan[];
  positions: Float32Array | Float64Array;
  vertexAttributes: SoupAttribute[];
  faceAttributes: SoupAttribute[];
  faces: ListCollector<Uint32Array<ArrayBuffer>> | null;
  /** Per-face texture coordinates, two per corner. */
  faceTexcoords: ListCollector<Float32Array<ArrayBuffer>> | null;
  strips: ListCollector<Int32Array<ArrayBuffer>> | null;
  /** The source of each value of the soup (positions and attributes), by `sourceKey`. */
  sources: Map<string, ValueSource>;
  notes: string[];
}

function planElements(header: PlyHeader): Plan {
  const notes = header.notes;
  // the first element of each of these names is the one read; a repeat is skipped like any other
  const vertexElement = header.elements.find((e) => e.name === 'vertex');
  const faceElement = header.elements.find((e) => e.name === 'face');
  const stripsElement = faceElement ? undefined : header.elements.find((e) => e.name === 'tristrips');
  const vertexCount = vertexElement?.count ?? 0;
  const plan: Plan = {
    elements: [],
    positions: new Float64Array(0),
    vertexAttributes: [],
    faceAttributes: [],
    faces: null,
    faceTexcoords: null,
    strips: null,
    sources: new Map(),
    notes,
  };
  /** Elements skipped whole, as `'name' (n rows)`, noted once at the end. */
  const skipped: string[] = [];

  for (const element of header.elements) {
    const properties = element.properties.map(
      (property): PropertyPlan => ({
        property,
        countIsByte: property.countType?.type === 'uint8',
        target: null,
        stride: 1,
        offset: 0,
        list: null,
      }),
    );
    const scalars = scalarsByName(properties);
    const rows = element.count;
    const lists = properties.filter((p) => p.property.countType !== null);
    if (element === vertexElement) {
      const xyz = findGroup(scalars, [['x', 'y', 'z']], 3);
      if (!xyz) {
        const missing = ['x', 'y', 'z'].find((name) => !scalars.has(name));
        throw new ParseError('ply', { line: element.line }, `element 'vertex' has no scalar property '${missing}'`);
      }
      const float32 = xyz.every((p) => p.property.type.type === 'float32');
      plan.positions = float32 ? new Float32Array(3 * rows) : new Float64Array(3 * rows);
      route(xyz, plan.positions, 3);
      plan.sources.set(sourceKey('vertex', 'position'), { element, properties: xyz.map((p) => p.property) });
      planAttributes(element, properties, scalars, plan.vertexAttributes, plan.sources, notes, true);
      noteSkippedLists(element, lists, notes);
    } else if (element === faceElement) {
      const faceList =
        lists.find((p) => p.property.name === 'vertex_indices' || p.property.name === 'vertex_index') ??
        (lists.length === 1 ? lists[0] : undefined);
      if (faceList) {
        requireIntegers(element, faceList);
        faceList.list = plan.faces = new ListCollector(rows, (n) => new Uint32Array(n), 0, vertexCount - 1);
      } else {
        notes.push(`element 'face' has no list of vertex indices: no faces read`);
      }
      const texcoords = lists.find((p) => p.property.name === 'texcoord' || p.property.name === 'texcoords');
      if (texcoords && texcoords !== faceList) {
        texcoords.list = plan.faceTexcoords = new ListCollector(rows, (n) => new Float32Array(n), -Infinity, Infinity);
        plan.sources.set(sourceKey('corner', 'texcoord'), { element, properties: [texcoords.property] });
      }
      noteSkippedLists(element, lists.filter((p) => p !== faceList && p !== texcoords), notes);
      planAttributes(element, properties, scalars, plan.faceAttributes, plan.sources, notes, false);
    } else if (element === stripsElement && lists.length > 0) {
      const stripList = lists.find((p) => p.property.name === 'vertex_indices') ?? lists[0];
      requireIntegers(element, stripList);
      stripList.list = plan.strips = new ListCollector(rows, (n) => new Int32Array(n), -1, vertexCount - 1);
    } else {
      skipped.push(`${quoted(element.name)} (${plural(rows, 'row')})`);
    }
    const rowBytes = lists.length > 0 ? -1 : properties.reduce((sum, p) => sum + p.property.type.size, 0);
    plan.elements.push({ element, properties, rowBytes, start: 0, startLine: 0 });
  }
  if (skipped.length > 0) notes.push(`skipped ${skipped.length === 1 ? 'element' : 'elements'} ${someOf(skipped)}`);
  if (!vertexElement) {
    const names = someOf(header.elements.map((e) => `${quoted(e.name)} (${plural(e.count, 'row')})`)) || 'none';
    notes.push(`no 'vertex' element (elements: ${names}): nothing to show`);
  }
  return plan;
}

function requireIntegers(element: PlyElement, p: PropertyPlan): void {
  const { name, type } = p.property;
  if (type.type.startsWith('float')) {
    const reason = `the vertex indices ${quoted(name)} of element ${quoted(element.name)} are ${type.type}, not integers`;
    throw new ParseError('ply', { line: element.line }, reason);
  }
}

/** Sends each property of `group` to `target`, interleaved `stride` per row. */
function route(group: PropertyPlan[], target: NumberTarget, stride: number): void {
  group.forEach((p, k) => {
    p.target = target;
    p.stride = stride;
    p.offset = k;
  });
}

/**
 * An element's scalar properties by name (the first, when a name repeats), looked up once each
 * instead of searched for: a header may declare a hundred thousand properties.
 */
function scalarsByName(properties: PropertyPlan[]): Map<string, PropertyPlan> {
  const scalars = new Map<string, PropertyPlan>();
  for (const p of properties) {
    if (p.property.countType === null && !scalars.has(p.property.name)) scalars.set(p.property.name, p);
  }
  return scalars;
}

/**
 * The scalar properties named by one of `spellings` (the first `required` names must all be
 * there; the rest are optional and kept only in order), or null.
 */
function findGroup(scalars: Map<string, PropertyPlan>, spellings: string[][], required: number): PropertyPlan[] | null {
  for (const names of spellings) {
    const group: PropertyPlan[] = [];
    for (const name of names) {
      const p = scalars.get(name);
      if (!p) break;
      group.push(p);
    }
    if (group.length >= required) return group;
  }
  return null;
}

/** "property 'a'", or "properties 'a', 'b', 'c', 'd', 'e' and 3 more" (names already quoted). */
function propertyList(names: string[]): string {
  return `${names.length === 1 ? 'property' : 'properties'} ${someOf(names)}`;
}

/** One note for the list properties of a vertex or face element that the soup has no place for. */
function noteSkippedLists(element: PlyElement, lists: PropertyPlan[], notes: string[]): void {
  if (lists.length > 0) notes.push(`skipped ${element.name} list ${propertyList(lists.map((p) => quoted(p.property.name)))}`);
}

/** Plans a vertex or face element's attributes: normal, colour, texcoord, then any other scalar. */
function planAttributes(
  element: PlyElement,
  properties: PropertyPlan[],
  scalars: Map<string, PropertyPlan>,
  attributes: SoupAttribute[],
  sources: Map<string, ValueSource>,
  notes: string[],
  isVertex: boolean,
): void {
  const rows = element.count;
  const taken = new Set(reservedNames);
  const add = (name: string, group: PropertyPlan[], type: AttributeType) => {
    const data = new attributeArrayTypes[type](rows * group.length);
    route(group, data, group.length);
    attributes.push({ name, itemSize: group.length, data });
    sources.set(sourceKey(isVertex ? 'vertex' : 'face', name), { element, properties: group.map((p) => p.property) });
    taken.add(name);
  };
  if (isVertex) {
    const normal = findGroup(scalars, normalNames, 3);
    if (normal) add('normal', normal, 'float32');
    const texcoord = findGroup(scalars, texcoordNames, 2);
    if (texcoord) add('texcoord', texcoord, 'float32');
  }
  const color = findGroup(scalars, colorNames, 3);
  if (color) add('color', color, color[0].property.type.type);

  const kept: string[] = [];
  const clashing: string[] = [];
  for (const p of properties) {
    const { name, type, countType } = p.property;
    if (p.target || countType !== null) continue;
    if (taken.has(name)) {
      clashing.push(quoted(name));
      continue;
    }
    add(name, [p], type.type);
    kept.push(quoted(name));
  }
  if (clashing.length > 0) {
    const why = clashing.length === 1 ? 'the name is taken' : 'the names are taken';
    notes.push(`skipped ${element.name} ${propertyList(clashing)}: ${why}`);
  }
  if (kept.length > 0) {
    notes.push(`kept ${element.name} ${propertyList(kept)} as ${kept.length === 1 ? 'an attribute' : 'attributes'}`);
  }
}

// -------------------------------------------------------------------------------------------------
// The data

function readAsciiBody(bytes: Uint8Array, header: PlyHeader, plan: Plan, progress: Progress): void {
  const scanner = new TextScanner(bytes, 'ply', { start: header.bodyStart, line: header.bodyLine });
  for (const elementPlan of plan.elements) {
    const { element, properties } = elementPlan;
    const { name, count: rows } = element;
    elementPlan.start = scanner.pos;
    elementPlan.startLine = scanner.line;
    if (properties.length === 0) continue;
    // the fast lane takes rows of plain numbers whole when they fit their properties; any other
    // row, and every row of another layout, is read token by token
    const layout = fastLayout(properties);
    scanner.readRows(
      rows,
      layout && ((batch, lines, row, bytesLeft) => storeRows(layout, properties, batch, lines, row, bytesLeft)),
      (row) => readRowByTokens(scanner, element, properties, row),
      (row) => `the file ends after ${row} of ${rows} rows of element '${name}'`,
      progress,
    );
  }
  if (scanner.skipBlankLines()) plan.notes.push(`ignored the text after the last element (from line ${scanner.line})`);
}

/** The two layouts of nearly every file, which the fast lane takes (see `storeRows`); null for any other. */
function fastLayout(properties: PropertyPlan[]): 'scalars' | 'list' | null {
  if (properties.every((p) => p.property.countType === null)) return 'scalars';
  return properties.length === 1 && properties[0].list !== null ? 'list' : null;
}

/**
 * The fast lane's part (a `StoreRows` for `layout`): stores the rows of a batch for as long as each
 * is what its properties say. Rows of scalars alone (vertices) are stored a column at a time; rows
 * of one list (faces) are a count, then that many items (vertex indices: whole numbers in range).
 */
function storeRows(
  layout: 'scalars' | 'list',
  properties: PropertyPlan[],
  batch: PlainLines,
  lines: number,
  firstRow: number,
  bytesLeft: number,
): number {
  const { values, integral, ends } = batch;
  if (layout === 'scalars') {
    const width = properties.length;
    let rows = 0;
    while (rows < lines && ends[rows] === (rows + 1) * width) rows++;
    for (let i = 0; i < width; i++) {
      const { target, stride, offset } = properties[i];
      if (target === null) continue;
      for (let r = 0, at = firstRow * stride + offset; r < rows; r++, at += stride) target[at] = values[r * width + i];
    }
    return rows;
  }
  const list = properties[0].list!;
  const { min, max, holdsIndices, starts } = list;
  // each line is a count, then its items; after the batch, an item takes at least two bytes
  const items = list.reserve(ends[lines - 1] - lines, firstRow + lines - 1, ends[lines - 1] - lines + bytesLeft / 2);
  let n = list.items.length;
  let r = 0;
  for (let from = 0; r < lines; r++) {
    const to = ends[r];
    if (!integral[from] || values[from] !== to - from - 1) break;
    let k = from + 1;
    for (; k < to; k++) {
      const value = values[k];
      if ((holdsIndices && !integral[k]) || value < min || value > max) break;
      items[n + k - from - 1] = value;
    }
    if (k < to) break;
    n += to - from - 1;
    starts[firstRow + r + 1] = n;
    from = to;
  }
  list.items.length = n;
  return r;
}

/** Reads a row the fast lane did not take, property by property from its first token: stores it, or says what is wrong with it. */
function readRowByTokens(scanner: TextScanner, element: PlyElement, properties: PropertyPlan[], row: number): void {
  const { name } = element;
  const bytes = scanner.bytes;
  for (let i = 0; i < properties.length; i++) {
    const p = properties[i];
    if (scanner.atLineEnd()) {
      scanner.fail(`row ${row} of element '${name}' ends before its property '${p.property.name}'`);
    }
    if (p.property.countType === null) {
      const at = scanner.pos;
      const value = scanner.number();
      // x − x is 0 for every finite number, NaN for NaN and both infinities
      if (value - value !== 0 && !p.property.type.type.startsWith('float')) {
        scanner.fail(`row ${row} of element '${name}': property '${p.property.name}' is ${p.property.type.type}, which holds no NaN or infinity`, at);
      }
      if (p.target) p.target[row * p.stride + p.offset] = value;
      continue;
    }
    const countAt = scanner.pos;
    const count = scanner.integer();
    if (count < 0) scanner.fail(`row ${row} of element '${name}': a list cannot have ${count} items`, countAt);
    if (count > (bytes.length - scanner.pos + 1) / 2) {
      const reason = `the list announces ${count} items, more than the rest of the file holds`;
      scanner.fail(`row ${row} of element '${name}': ${reason}`, countAt);
    }
    const list = p.list;
    if (list === null) {
      for (let k = 0; k < count; k++) {
        if (scanner.atLineEnd()) scanner.fail(listEndsEarly(element, row, p, count, k));
        scanner.number();
      }
      continue;
    }
    const items = list.reserve(count, row, (bytes.length - scanner.pos + 1) / 2);
    let n = list.items.length;
    for (let k = 0; k < count; k++) {
      if (scanner.atLineEnd()) scanner.fail(listEndsEarly(element, row, p, count, k));
      const at = scanner.pos;
      const value = list.holdsIndices ? scanner.integer() : scanner.number();
      if (value < list.min || value > list.max) scanner.fail(outOfRange(element, row, value, list), at);
      items[n++] = value;
    }
    list.items.length = n;
    list.starts[row + 1] = n;
  }
  scanner.endLine(`row ${row} of element '${name}' should end after its ${plural(properties.length, 'property', 'properties')}`);
}

function readBinaryBody(bytes: Uint8Array, header: PlyHeader, plan: Plan, progress: Progress): void {
  const littleEndian = header.encoding === 'binary_little_endian';
  const reader = new BinaryReader(bytes, 'ply', littleEndian);
  const { view } = reader;
  const fail = (reason: string, at: number) => reader.fail(reason, at);
  const end = bytes.length;
  // the cursor lives in a local for speed: every read below is checked against `end` first
  let offset = header.bodyStart;
  for (const elementPlan of plan.elements) {
    const { element, properties, rowBytes } = elementPlan;
    const { name, count: rows } = element;
    progress(offset / end);
    elementPlan.start = offset;
    if (properties.length === 0) continue;
    if (rowBytes >= 0) {
      // rows of scalars only: a table with fixed columns, read column by column
      const fullRows = Math.floor((end - offset) / rowBytes);
      if (fullRows < rows) {
        fail(`the file ends after ${fullRows} of ${rows} rows of element '${name}'`, offset + fullRows * rowBytes);
      }
      let column = offset;
      for (const p of properties) {
        const { type } = p.property;
        if (p.target) type.readRun(view, column, rowBytes, rows, littleEndian, p.target, p.offset, p.stride);
        column += type.size;
      }
      offset += rows * rowBytes;
      continue;
    }
    offset = isIndexList(properties)
      ? readIndexListRows(bytes, reader, offset, element, properties, progress)
      : readRowsWithLists(bytes, reader, offset, element, properties, progress);
  }
  if (offset < end) plan.notes.push(`ignored ${plural(end - offset, 'byte')} after the last element`);
}

/**
 * Reads rows `first` … `last` − 1 (all of them by default) of an element that holds lists, row by
 * row from byte `offset`; returns where they end. On its own, so that the engine optimises this
 * loop for itself.
 */
function readRowsWithLists(
  bytes: Uint8Array,
  reader: BinaryReader,
  offset: number,
  element: PlyElement,
  properties: PropertyPlan[],
  progress: Progress,
  first = 0,
  last = element.count,
): number {
  const { view, littleEndian } = reader;
  const fail = (reason: string, at: number) => reader.fail(reason, at);
  const end = bytes.length;
  const { name, count: rows } = element;
  for (let row = first; row < last; row++) {
    if ((row & PROGRESS_ROWS) === PROGRESS_ROWS) progress(offset / end);
    for (let i = 0; i < properties.length; i++) {
      const p = properties[i];
      const { type, countType } = p.property;
      const size = type.size;
      if (countType === null) {
        if (offset + size > end) fail(`the file ends inside row ${row} of ${rows} of element '${name}'`, offset);
        if (p.target) p.target[row * p.stride + p.offset] = type.read(view, offset, littleEndian);
        offset += size;
        continue;
      }
      if (offset + countType.size > end) {
        fail(`the file ends inside row ${row} of ${rows} of element '${name}'`, offset);
      }
      // most lists count in a uchar: read it straight from the bytes, sparing a call per row
      const count = p.countIsByte ? bytes[offset] : countType.read(view, offset, littleEndian);
      if (count < 0) fail(`row ${row} of element '${name}': a list cannot have ${count} items`, offset);
      offset += countType.size;
      if (offset + count * size > end) {
        fail(
          `the file ends inside row ${row} of ${rows} of element '${name}', whose list '${p.property.name}' ` +
            `announces ${count} items`,
          offset - countType.size,
        );
      }
      const list = p.list;
      if (list === null) {
        offset += count * size;
        continue;
      }
      const items = list.reserve(count, row, (end - offset) / size);
      const first = list.items.length;
      type.readRun(view, offset, size, count, littleEndian, items, first, 1);
      for (let k = first; k < first + count; k++) {
        if (items[k] < list.min || items[k] > list.max) {
          // the list's array may have wrapped the value (-1 in a Uint32Array): report what the file says
          const at = offset + (k - first) * size;
          fail(outOfRange(element, row, type.read(view, at, littleEndian), list), at);
        }
      }
      offset += count * size;
      list.items.length = first + count;
      list.starts[row + 1] = first + count;
    }
  }
  return offset;
}

/** Rows that are one list of 32-bit vertex indices counted in a uchar: the faces of almost every binary PLY. */
function isIndexList(properties: PropertyPlan[]): boolean {
  if (properties.length !== 1) return false;
  const { property, countIsByte, list } = properties[0];
  return countIsByte && list !== null && list.holdsIndices && (property.type.type === 'int32' || property.type.type === 'uint32');
}

/**
 * `readRowsWithLists` for an element that `isIndexList` accepts. Runs of triangles or quads are
 * read at fixed offsets (`readPolygonRun`); any other row, and the row a run stops at, goes to
 * `readRowsWithLists` on its own, which also says what is wrong with it. A 1.31M-triangle file
 * parses in about half the time it took with the general loop (28–30 ms against 54–67).
 */
function readIndexListRows(
  bytes: Uint8Array,
  reader: BinaryReader,
  offset: number,
  element: PlyElement,
  properties: PropertyPlan[],
  progress: Progress,
): number {
  const { view, littleEndian } = reader;
  const rows = element.count;
  const p = properties[0];
  const list = p.list!;
  // runs read int32s, the same numbers as uint32s where they are not negative; a list that may
  // hold -1 (strips) is read in runs only when it is signed, so that 0xffffffff is never taken for it
  const inRuns = p.property.type.type === 'int32' || list.min >= 0;
  for (let row = 0; row < rows; ) {
    const k = bytes[offset];
    const ranTo =
      inRuns && (k === 3 || k === 4)
        ? readPolygonRun(bytes, view, littleEndian, offset, row, Math.min(rows, (row | PROGRESS_ROWS) + 1), k, list)
        : row;
    if (ranTo > row) {
      offset += (ranTo - row) * (1 + 4 * k);
      row = ranTo;
      list.items.length = list.starts[row];
    } else {
      offset = readRowsWithLists(bytes, reader, offset, element, properties, progress, row, row + 1);
      row++;
    }
    if ((row & PROGRESS_ROWS) === 0) progress(offset / bytes.length);
  }
  return offset;
}

/**
 * Reads the rows from `row` on that hold `k` = 3 or 4 indices (triangles, quads), at fixed offsets
 * from byte `offset`, writing after the list's items; stops before `stop`, a row of another length,
 * an index out of range, the end of the file or of the items' array. Returns the row it stopped
 * at, which the caller reads on its own (growing the array, or reporting what is wrong); the
 * list's `starts` say how many items there are now.
 */
function readPolygonRun(
  bytes: Uint8Array,
  view: DataView,
  littleEndian: boolean,
  offset: number,
  row: number,
  stop: number,
  k: number,
  list: ListCollector,
): number {
  const { starts, min, max } = list;
  const items = list.items.data;
  let n = list.items.length;
  const quad = k === 4;
  const stride = 1 + 4 * k;
  const end = bytes.length;
  for (; row < stop; row++, offset += stride) {
    if (bytes[offset] !== k || offset + stride > end || n + k > items.length) break;
    const a = view.getInt32(offset + 1, littleEndian);
    const b = view.getInt32(offset + 5, littleEndian);
    const c = view.getInt32(offset + 9, littleEndian);
    const d = quad ? view.getInt32(offset + 13, littleEndian) : min;
    if (a < min || a > max || b < min || b > max || c < min || c > max || d < min || d > max) break;
    items[n] = a;
    items[n + 1] = b;
    items[n + 2] = c;
    if (quad) items[n + 3] = d;
    n += k;
    starts[row + 1] = n;
  }
  return row;
}

/**
 * Where `property` of row `row` of an element is (with `listItem`, that item of its list): walks
 * the rows before it as they were read, a byte offset from the layout (binary), or a line per row
 * and a token per value (ascii).
 */
function valuePlace(bytes: Uint8Array, encoding: Encoding, elementPlan: ElementPlan, row: number, property: PlyProperty, listItem: number | null): FileLocation {
  const { element, rowBytes, start, startLine } = elementPlan;
  if (encoding === 'ascii') {
    const scanner = new TextScanner(bytes, 'ply', { start, line: startLine });
    for (let r = 0; r < row; r++) {
      scanner.skipBlankLines();
      scanner.nextLine();
    }
    scanner.skipBlankLines();
    for (const p of element.properties) {
      if (p === property) break;
      if (p.countType === null) scanner.word();
      else for (let k = scanner.integer(); k > 0; k--) scanner.word();
    }
    if (listItem !== null) {
      scanner.integer();
      for (let k = 0; k < listItem; k++) scanner.word();
    }
    scanner.skipSpaces();
    return scanner.location();
  }
  const view = viewOf(bytes);
  const littleEndian = encoding === 'binary_little_endian';
  /** Bytes of `p` at `offset`: a scalar, or a list's count and items. */
  const size = (p: PlyProperty, offset: number) => (p.countType ? p.countType.size + p.countType.read(view, offset, littleEndian) * p.type.size : p.type.size);
  let offset = start;
  if (rowBytes >= 0) offset += row * rowBytes;
  else for (let r = 0; r < row; r++) for (const p of element.properties) offset += size(p, offset);
  for (const p of element.properties) {
    if (p === property) break;
    offset += size(p, offset);
  }
  if (listItem !== null) offset += property.countType!.size + listItem * property.type.size;
  return { byteOffset: offset };
}

function listEndsEarly(element: PlyElement, row: number, p: PropertyPlan, count: number, found: number): string {
  const list = `the list '${p.property.name}' announces ${count} items, but the line ends after ${found}`;
  return `row ${row} of element '${element.name}': ${list}`;
}

/** Only lists of vertex indices have a range (faces, strips). */
function outOfRange(element: PlyElement, row: number, value: number, list: ListCollector): string {
  const what = element.name === 'face' ? `face ${row}` : `row ${row} of element '${element.name}'`;
  if (list.max < 0) return `${what}: vertex index ${value} refers to a vertex, but the file has none`;
  return `${what}: vertex index ${value} is out of range ${list.min === -1 ? '-1 (strip end), 0' : '0'}..${list.max}`;
}

// -------------------------------------------------------------------------------------------------
// The soup

function assemble(header: PlyHeader, plan: Plan): MeshFile {
  const { notes } = plan;
  const positions = plan.positions;
  const vertexCount = positions.length / 3;
  let faceStarts: Uint32Array;
  let faceIndices: Uint32Array;
  const cornerAttributes: SoupAttribute[] = [];
  if (plan.faces) {
    faceStarts = plan.faces.starts;
    faceIndices = plan.faces.items.finish();
    const texcoords = plan.faceTexcoords;
    if (texcoords) {
      const mismatch = firstTexcoordMismatch(faceStarts, texcoords.starts);
      if (mismatch < 0) {
        cornerAttributes.push({ name: 'texcoord', itemSize: 2, data: texcoords.items.finish() });
      } else {
        const corners = faceStarts[mismatch + 1] - faceStarts[mismatch];
        const values = texcoords.starts[mismatch + 1] - texcoords.starts[mismatch];
        notes.push(
          `face ${mismatch} has ${corners} corners but ${values} texture coordinates (${2 * corners} expected): ` +
            'per-face texture coordinates skipped',
        );
      }
    }
  } else if (plan.strips) {
    ({ faceStarts, faceIndices } = decodeStrips(plan.strips, notes));
  } else {
    faceStarts = new Uint32Array(1);
    faceIndices = new Uint32Array(0);
  }
  const faceCount = faceStarts.length - 1;
  if (vertexCount > 0 && faceCount === 0) notes.push('no faces: loaded as a point set');
  return {
    format: 'ply',
    encoding: header.encoding,
    soup: {
      positions,
      faceStarts,
      faceIndices,
      vertexAttributes: plan.vertexAttributes,
      faceAttributes: plan.faces ? plan.faceAttributes : [],
      cornerAttributes,
    },
    counts: { vertices: vertexCount, faces: faceCount },
    comments: header.comments,
    notes,
  };
}

/** The first face whose texture coordinates are not two per corner, or -1. */
function firstTexcoordMismatch(faceStarts: Uint32Array, texcoordStarts: Uint32Array): number {
  for (let f = 0; f + 1 < faceStarts.length; f++) {
    if (texcoordStarts[f + 1] - texcoordStarts[f] !== 2 * (faceStarts[f + 1] - faceStarts[f])) return f;
  }
  return -1;
}

/**
 * A triangle strip a b c d e … makes the triangles (a b c), (c b d), (c d e), …: every second one
 * is turned round so all keep the strip's orientation. -1 ends a strip; triangles with a repeated
 * vertex (used in strips to turn corners) are left out.
 */
function decodeStrips(
  strips: ListCollector<Int32Array<ArrayBuffer>>,
  notes: string[],
): { faceStarts: Uint32Array; faceIndices: Uint32Array } {
  const items = strips.items.finish();
  const corners = new GrowableArray((n) => new Uint32Array(n), items.length * 3);
  let stripCount = 0;
  let skipped = 0;
  let runStart = 0;
  for (let i = 0; i <= items.length; i++) {
    if (i < items.length && items[i] !== -1) continue;
    // items[runStart … i) is one strip
    if (i > runStart) stripCount++;
    for (let k = runStart + 2; k < i; k++) {
      const a = items[k - 2];
      const b = items[k - 1];
      const c = items[k];
      if (a === b || b === c || a === c) {
        skipped++;
        continue;
      }
      const odd = (k - runStart) % 2 === 1;
      corners.push(odd ? b : a);
      corners.push(odd ? a : b);
      corners.push(c);
    }
    runStart = i + 1;
  }
  const faceIndices = corners.finish();
  const triangles = faceIndices.length / 3;
  const faceStarts = new Uint32Array(triangles + 1);
  for (let f = 1; f <= triangles; f++) faceStarts[f] = 3 * f;
  notes.push(
    `decoded ${plural(stripCount, 'triangle strip')} into ${plural(triangles, 'triangle')}` +
      (skipped > 0 ? ` (${skipped} degenerate left out)` : ''),
  );
  return { faceStarts, faceIndices };
}
