/**
 * Helpers for the io tests: a small PLY maker written independently of the library's writer (so
 * the reader is checked against an oracle, not against itself), and ways to look at soups.
 */
import { expect } from 'vitest';
import { type HalfedgeMesh, ParseError, type PolygonSoup, type SoupAttribute } from '../../src/index.js';
import { type MeshFile, readMesh } from '../../src/core/io/index.js';

export type PlyEncoding = 'ascii' | 'binary_little_endian' | 'binary_big_endian';
export const plyEncodings: PlyEncoding[] = ['ascii', 'binary_little_endian', 'binary_big_endian'];

export interface PlyProp {
  name: string;
  /** Any PLY type name (`uchar`, `float32`, …). */
  type: string;
  /** A list property's count type. */
  count?: string;
}

export interface PlyElementSpec {
  name: string;
  props: PlyProp[];
  /** One array per row; a list property takes an array. */
  rows: Array<Array<number | number[]>>;
}

const typeInfo: Record<string, { size: number; set: (view: DataView, at: number, x: number, le: boolean) => void }> = {};
const setters: Array<[string[], number, (view: DataView, at: number, x: number, le: boolean) => void]> = [
  [['char', 'int8'], 1, (v, at, x) => v.setInt8(at, x)],
  [['uchar', 'uint8'], 1, (v, at, x) => v.setUint8(at, x)],
  [['short', 'int16'], 2, (v, at, x, le) => v.setInt16(at, x, le)],
  [['ushort', 'uint16'], 2, (v, at, x, le) => v.setUint16(at, x, le)],
  [['int', 'int32'], 4, (v, at, x, le) => v.setInt32(at, x, le)],
  [['uint', 'uint32'], 4, (v, at, x, le) => v.setUint32(at, x, le)],
  [['float', 'float32'], 4, (v, at, x, le) => v.setFloat32(at, x, le)],
  [['double', 'float64'], 8, (v, at, x, le) => v.setFloat64(at, x, le)],
];
for (const [names, size, set] of setters) for (const name of names) typeInfo[name] = { size, set };

/** The header lines of a PLY file for `elements` (before `end_header`). */
export function plyHeader(encoding: PlyEncoding, elements: PlyElementSpec[], extra: string[] = []): string[] {
  return [
    'ply',
    `format ${encoding} 1.0`,
    ...extra,
    ...elements.flatMap((e) => [
      `element ${e.name} ${e.rows.length}`,
      ...e.props.map((p) => (p.count ? `property list ${p.count} ${p.type} ${p.name}` : `property ${p.type} ${p.name}`)),
    ]),
  ];
}

/** A complete PLY file. */
export function makePly(encoding: PlyEncoding, elements: PlyElementSpec[], extra: string[] = []): Uint8Array {
  const header = [...plyHeader(encoding, elements, extra), 'end_header'].join('\n') + '\n';
  if (encoding === 'ascii') {
    const value = (x: number | number[]) => (Array.isArray(x) ? [x.length, ...x].join(' ') : String(x));
    const lines = elements.flatMap((e) => e.rows.map((row) => row.map(value).join(' ')));
    return text(header + lines.map((l) => l + '\n').join(''));
  }
  const le = encoding === 'binary_little_endian';
  const chunks: number[] = [];
  const buffer = new DataView(new ArrayBuffer(8));
  const put = (type: string, x: number) => {
    const { size, set } = typeInfo[type];
    set(buffer, 0, x, le);
    for (let i = 0; i < size; i++) chunks.push(buffer.getUint8(i));
  };
  for (const e of elements) {
    for (const row of e.rows) {
      e.props.forEach((p, i) => {
        const value = row[i];
        if (p.count) {
          const items = value as number[];
          put(p.count, items.length);
          for (const x of items) put(p.type, x);
        } else {
          put(p.type, value as number);
        }
      });
    }
  }
  const head = text(header);
  const out = new Uint8Array(head.length + chunks.length);
  out.set(head);
  out.set(chunks, head.length);
  return out;
}

export function text(source: string): Uint8Array {
  return new TextEncoder().encode(source);
}

/** Face lists of a soup, as arrays. */
export function faceLists(soup: PolygonSoup): number[][] {
  const faces: number[][] = [];
  for (let f = 0; f + 1 < soup.faceStarts.length; f++) {
    faces.push(Array.from(soup.faceIndices.subarray(soup.faceStarts[f], soup.faceStarts[f + 1])));
  }
  return faces;
}

export function attribute(list: SoupAttribute[] | undefined, name: string): SoupAttribute {
  const found = list?.find((a) => a.name === name);
  if (!found) throw new Error(`no attribute '${name}' among ${list?.map((a) => a.name).join(', ') || 'none'}`);
  return found;
}

/** The ParseError that `read` throws (fails the test when it throws nothing or something else). */
export function parseError(read: () => unknown): ParseError {
  try {
    read();
  } catch (error) {
    if (error instanceof ParseError) return error;
    throw error;
  }
  throw new Error('expected a ParseError, but the file was read');
}

export function read(source: string | Uint8Array, fileName?: string): MeshFile {
  return readMesh(typeof source === 'string' ? text(source) : source, { fileName });
}

/** Two soups hold the same positions (by value), faces and attributes (by name, type and value). */
export function expectSameSoup(actual: PolygonSoup, expected: PolygonSoup): void {
  expect(Array.from(actual.positions)).toEqual(Array.from(expected.positions));
  expect(faceLists(actual)).toEqual(faceLists(expected));
  for (const kind of ['vertexAttributes', 'faceAttributes', 'cornerAttributes'] as const) {
    const describe = (list: SoupAttribute[] | undefined) =>
      (list ?? [])
        .map((a) => ({ name: a.name, itemSize: a.itemSize, type: a.data.constructor.name, values: Array.from(a.data) }))
        .sort((a, b) => a.name.localeCompare(b.name));
    expect(describe(actual[kind]), kind).toEqual(describe(expected[kind]));
  }
}

/** Every array of the mesh up to its slots, and (unless told not to) its attributes, for an exact comparison. */
export function meshArrays(mesh: HalfedgeMesh, withAttributes = true) {
  const h = mesh.halfedgeSlots;
  const attributes = (set: HalfedgeMesh['vertexAttributes'], n: number) =>
    [...set].map(({ name, type, itemSize, interpolation, data }) => ({
      name,
      type,
      itemSize,
      interpolation,
      data: Array.from(data.subarray(0, n * itemSize)),
    }));
  return {
    slots: [mesh.vertexSlots, mesh.edgeSlots, mesh.faceSlots],
    counts: [mesh.nVertices, mesh.nEdges, mesh.nFaces],
    heNext: Array.from(mesh.heNext.subarray(0, h)),
    hePrev: Array.from(mesh.hePrev.subarray(0, h)),
    heVertex: Array.from(mesh.heVertex.subarray(0, h)),
    heFace: Array.from(mesh.heFace.subarray(0, h)),
    vHalfedge: Array.from(mesh.vHalfedge.subarray(0, mesh.vertexSlots)),
    fHalfedge: Array.from(mesh.fHalfedge.subarray(0, mesh.faceSlots)),
    vDeleted: Array.from(mesh.vDeleted.subarray(0, mesh.vertexSlots)),
    eDeleted: Array.from(mesh.eDeleted.subarray(0, mesh.edgeSlots)),
    fDeleted: Array.from(mesh.fDeleted.subarray(0, mesh.faceSlots)),
    positions: Array.from(mesh.positions.subarray(0, 3 * mesh.vertexSlots)),
    ...(withAttributes && {
      vertexAttributes: attributes(mesh.vertexAttributes, mesh.vertexSlots),
      halfedgeAttributes: attributes(mesh.halfedgeAttributes, h),
      edgeAttributes: attributes(mesh.edgeAttributes, mesh.edgeSlots),
      faceAttributes: attributes(mesh.faceAttributes, mesh.faceSlots),
    }),
  };
}

/**
 * Reads `head` and `lines` as written, and again with a comment at the end of every line, which
 * sends each line of a format with `#` comments (OFF, OBJ) token by token: both must give the same
 * soup, notes and counts, or an error on the same line for the same reason (its column moves with
 * the comments).
 */
export function expectSameReadWithComments(head: string, lines: string[], fileName?: string): void {
  const outcome = (source: string) => {
    try {
      const { soup, notes, counts } = read(source, fileName);
      return { soup, notes, counts };
    } catch (error) {
      if (!(error instanceof ParseError)) throw error;
      return { line: error.location.line, reason: error.reason };
    }
  };
  expect(outcome(head + lines.map((l) => `${l}\n`).join(''))).toEqual(outcome(head + lines.map((l) => `${l} # c\n`).join('')));
}
