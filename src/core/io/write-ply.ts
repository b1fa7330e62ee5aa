/**
 * Writing PLY, ascii or binary: positions, faces as `vertex_indices` lists, and every attribute
 * PLY can carry under the names its readers know: vertex `nx ny nz`, `red green blue [alpha]`,
 * `s t`; face `red green blue [alpha]`; per-corner texture coordinates as the face list
 * `texcoord`; any other attribute of one number per element under its own name and type.
 */
import { type AttributeType, attributeTypeOf } from '../attributes.js';
import type { PolygonSoup, SoupAttribute } from '../soup.js';
import { type ScalarType, scalarTypes, viewOf } from './binary.js';
import type { Encoding } from './mesh-file.js';
import { allFloat32, concatBytes, numberFormat, TextOutput } from './output.js';
import { encodeText } from './text.js';

const plyTypeNames: Record<AttributeType, string> = {
  int8: 'char',
  uint8: 'uchar',
  int16: 'short',
  uint16: 'ushort',
  int32: 'int',
  uint32: 'uint',
  float32: 'float',
  float64: 'double',
};

/** The property names of attributes with several numbers per element (Maps: a name is any text). */
const vertexNames = new Map([
  ['normal', ['nx', 'ny', 'nz']],
  ['color', ['red', 'green', 'blue', 'alpha']],
  ['texcoord', ['s', 't']],
]);
const faceNames = new Map([['color', ['red', 'green', 'blue', 'alpha']]]);

/** One scalar property: row r's value is `data[r × stride + offset]`. */
interface Column {
  name: string;
  type: AttributeType;
  data: ArrayLike<number>;
  stride: number;
  offset: number;
}

/**
 * Writes a soup as PLY in the given encoding.
 * @example
 *   const bytes = writePly(soup, 'binary_little_endian');
 */
export function writePly(soup: PolygonSoup, encoding: Encoding): Uint8Array {
  const { positions, faceStarts, faceIndices } = soup;
  const vertexCount = positions.length / 3;
  const faceCount = faceStarts.length - 1;
  const positionType = allFloat32(positions) ? 'float32' : 'float64';
  const vertexColumns: Column[] = ['x', 'y', 'z'].map((name, k) => ({
    name,
    type: positionType,
    data: positions,
    stride: 3,
    offset: k,
  }));
  vertexColumns.push(...attributeColumns(soup.vertexAttributes ?? [], vertexNames, vertexColumns));
  const faceColumns = attributeColumns(soup.faceAttributes ?? [], faceNames, []);
  const texcoords = soup.cornerAttributes?.find((a) => a.name === 'texcoord' && a.itemSize === 2);

  let maxDegree = 0;
  for (let f = 0; f < faceCount; f++) maxDegree = Math.max(maxDegree, faceStarts[f + 1] - faceStarts[f]);
  const degreeType = countTypeFor(maxDegree);
  const texcoordCountType = countTypeFor(2 * maxDegree);

  const header = [
    'ply',
    `format ${encoding} 1.0`,
    `element vertex ${vertexCount}`,
    ...vertexColumns.map((c) => `property ${plyTypeNames[c.type]} ${c.name}`),
    `element face ${faceCount}`,
    `property list ${plyTypeNames[degreeType.type]} int vertex_indices`,
    ...(texcoords ? [`property list ${plyTypeNames[texcoordCountType.type]} float texcoord`] : []),
    ...faceColumns.map((c) => `property ${plyTypeNames[c.type]} ${c.name}`),
    'end_header',
  ];

  if (encoding === 'ascii') {
    const out = new TextOutput();
    for (const line of header) out.line(line);
    const vertexFormats = vertexColumns.map((c) => numberFormat(c.type));
    const faceFormats = faceColumns.map((c) => numberFormat(c.type));
    const formatTexcoord = numberFormat('float32');
    for (let v = 0; v < vertexCount; v++) out.line(rowText(vertexColumns, vertexFormats, v));
    for (let f = 0; f < faceCount; f++) {
      const start = faceStarts[f];
      const end = faceStarts[f + 1];
      const parts = [String(end - start)];
      for (let c = start; c < end; c++) parts.push(String(faceIndices[c]));
      if (texcoords) {
        parts.push(String(2 * (end - start)));
        for (let i = 2 * start; i < 2 * end; i++) parts.push(formatTexcoord(texcoords.data[i]));
      }
      if (faceColumns.length > 0) parts.push(rowText(faceColumns, faceFormats, f));
      out.line(parts.join(' '));
    }
    return out.bytes();
  }

  // binary: the size is known up front, so one buffer is written straight through
  const littleEndian = encoding === 'binary_little_endian';
  const headerBytes = encodeText(header.join('\n') + '\n');
  const rowBytes = (columns: Column[]) => columns.reduce((n, c) => n + scalarTypes[c.type].size, 0);
  const texcoordBytes = texcoords ? faceCount * texcoordCountType.size + 8 * faceIndices.length : 0;
  const size =
    vertexCount * rowBytes(vertexColumns) +
    faceCount * (degreeType.size + rowBytes(faceColumns)) +
    4 * faceIndices.length +
    texcoordBytes;
  const body = new Uint8Array(size);
  const view = viewOf(body);
  let offset = 0;
  const put = (type: ScalarType, value: number) => {
    type.write(view, offset, value, littleEndian);
    offset += type.size;
  };
  const putRow = (columns: Column[], row: number) => {
    for (const c of columns) put(scalarTypes[c.type], c.data[row * c.stride + c.offset]);
  };
  for (let v = 0; v < vertexCount; v++) putRow(vertexColumns, v);
  for (let f = 0; f < faceCount; f++) {
    const start = faceStarts[f];
    const end = faceStarts[f + 1];
    put(degreeType, end - start);
    for (let c = start; c < end; c++) put(scalarTypes.int32, faceIndices[c]);
    if (texcoords) {
      put(texcoordCountType, 2 * (end - start));
      for (let i = 2 * start; i < 2 * end; i++) put(scalarTypes.float32, texcoords.data[i]);
    }
    putRow(faceColumns, f);
  }
  return concatBytes([headerBytes, body]);
}

/**
 * The columns of the attributes PLY can hold: known ones under their property names, others of
 * one number per element under their own name. Attributes of other shapes are left out.
 */
function attributeColumns(attributes: SoupAttribute[], known: Map<string, string[]>, taken: Column[]): Column[] {
  const columns: Column[] = [];
  const used = new Set(taken.map((c) => c.name));
  const isFree = (name: string) => /^\S+$/.test(name) && !used.has(name);
  for (const { name, itemSize, data } of attributes) {
    const type = attributeTypeOf(data);
    const names = known.get(name)?.slice(0, itemSize) ?? (itemSize === 1 ? [name] : []);
    if (names.length !== itemSize || !names.every(isFree)) continue;
    names.forEach((property, k) => {
      columns.push({ name: property, type, data, stride: itemSize, offset: k });
      used.add(property);
    });
  }
  return columns;
}

function countTypeFor(maxCount: number): ScalarType {
  return maxCount <= 0xff ? scalarTypes.uint8 : maxCount <= 0xffff ? scalarTypes.uint16 : scalarTypes.uint32;
}

function rowText(columns: Column[], formats: Array<(x: number) => string>, row: number): string {
  let text = '';
  for (let i = 0; i < columns.length; i++) {
    const c = columns[i];
    text += (i > 0 ? ' ' : '') + formats[i](c.data[row * c.stride + c.offset]);
  }
  return text;
}
