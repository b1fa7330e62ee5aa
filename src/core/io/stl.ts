/**
 * STL (stereolithography): a bare list of triangles, each with a facet normal and its corners
 * written out in full. No vertex is shared: a cube's 12 triangles carry 36 corners for its 8
 * vertices.
 *
 * ```
 * ascii:   solid name
 *            facet normal nx ny nz
 *              outer loop
 *                vertex x y z      (three times)
 *              endloop
 *            endfacet
 *          endsolid name
 * binary:  an 80-byte header, a uint32 triangle count n, then 50 bytes per triangle (normal and
 *          3 corners as 12 little-endian float32, then a 2-byte attribute): 84 + 50·n bytes.
 * ```
 *
 * A binary header may itself begin with "solid", so the size rule decides first. A halfedge mesh
 * needs shared vertices: corners at exactly the same position are welded into one vertex, found
 * in linear time by hashing the bits of the three coordinates. Facet normals are kept as the face
 * attribute `normal`; one that is NaN (a facet of no area has no normal, and some exporters write
 * NaN for it) is computed again from the facet's corners (see `finite.ts`).
 */
import { plural } from '../report.js';
import { BinaryReader, viewOf } from './binary.js';
import { GrowableArray } from './growable.js';
import type { FileLocation } from '../errors.js';
import { type Locate, type MeshFile, type Progress, PROGRESS_ROWS, type ReaderOutput } from './mesh-file.js';
import { TextScanner, decodeText } from './text.js';
import { weldPositions } from './weld.js';

const HEADER_BYTES = 80;
const TRIANGLE_BYTES = 50;

/** True when the size is exactly what the triangle count after the 80-byte header makes. */
export function isBinaryStl(bytes: Uint8Array): boolean {
  if (bytes.length < HEADER_BYTES + 4) return false;
  const triangles = viewOf(bytes).getUint32(HEADER_BYTES, true);
  return HEADER_BYTES + 4 + TRIANGLE_BYTES * triangles === bytes.length;
}

/** Starts with "solid" and has no control bytes early on (binary floats are full of zero bytes). */
function looksLikeAsciiStl(bytes: Uint8Array): boolean {
  const start = bytes.subarray(0, 512);
  return /^\s*solid\b/.test(decodeText(start, 0, 64)) && start.every((b) => b >= 9);
}

/**
 * Reads an STL file (ascii or binary) and welds its corners into shared vertices: those at equal
 * positions, or within `weldTolerance` of each other.
 * @throws ParseError with the line (ascii) or byte offset (binary).
 */
export function readStl(bytes: Uint8Array, progress: Progress, weldTolerance = 0): ReaderOutput {
  const ascii = !isBinaryStl(bytes) && looksLikeAsciiStl(bytes);
  const comments: string[] = [];
  const notes: string[] = [];
  const triangles = ascii ? readAscii(bytes, comments, progress) : readBinary(bytes, comments, notes);
  const { corners, faceStarts, normals } = triangles;
  const cornerCount = corners.length / 3;
  // STL repeats each position at every corner: welded, the triangles share their vertices
  const weld = weldPositions(corners, weldTolerance);
  const indices = weld.remap;
  // the values are float32 in the file, and kept so (the finite check names the type they are stored in)
  const positions = Float32Array.from(weld.positions);
  const vertexCount = positions.length / 3;
  const welded = `${plural(cornerCount, 'STL corner')} into ${plural(vertexCount, 'vertex', 'vertices')}`;
  const how = weldTolerance > 0 ? `, within ${weldTolerance} of each other` : '';
  notes.push(`welded ${welded} (${cornerCount - vertexCount} merged${how})`);
  const faceCount = faceStarts.length - 1;
  const file: MeshFile = {
    format: 'stl',
    encoding: ascii ? 'ascii' : 'binary_little_endian',
    soup: {
      positions,
      faceStarts,
      faceIndices: indices,
      faceAttributes: [{ name: 'normal', itemSize: 3, data: normals }],
    },
    counts: { vertices: vertexCount, faces: faceCount },
    comments,
    notes,
  };
  const locate: Locate = (element, _name, index, item) => {
    // a vertex is where the first corner welded into it was read; the only face value is its normal
    const corner = element === 'vertex' ? indices.indexOf(index) : -1;
    if (ascii) return element === 'vertex' ? asciiPlace(bytes, 'vertex', corner, item) : asciiPlace(bytes, 'facet', index, item);
    const triangle = HEADER_BYTES + 4 + TRIANGLE_BYTES * (element === 'vertex' ? Math.floor(corner / 3) : index);
    return { byteOffset: element === 'vertex' ? triangle + 12 + 12 * (corner % 3) + 4 * item : triangle + 4 * item };
  };
  return { file, locate };
}

/**
 * Where number `item` of the `index`-th `keyword` of an ascii STL is: of a corner (`vertex`), or
 * of a facet's normal (`facet`, then `normal`). Walks the file word by word as `readAscii` read it.
 */
function asciiPlace(bytes: Uint8Array, keyword: 'facet' | 'vertex', index: number, item: number): FileLocation {
  const scanner = new TextScanner(bytes, 'stl');
  let seen = 0;
  while (scanner.skipBlankLines()) {
    // a solid's name is any text, keywords included
    if (scanner.isWord('solid') || scanner.isWord('endsolid')) {
      scanner.nextLine();
    } else if (!scanner.isWord(keyword)) {
      scanner.word();
    } else if (seen++ === index) {
      if (keyword === 'facet') {
        scanner.skipBlankLines();
        scanner.isWord('normal');
      }
      // a point's three numbers are on one line
      for (let k = 0; k < item; k++) scanner.number();
      scanner.skipSpaces();
      break;
    }
  }
  return scanner.location();
}

interface Triangles {
  /** x y z of every corner, face after face. */
  corners: Float32Array<ArrayBuffer>;
  faceStarts: Uint32Array;
  normals: Float32Array<ArrayBuffer>;
}

function readBinary(bytes: Uint8Array, comments: string[], notes: string[]): Triangles {
  const reader = new BinaryReader(bytes, 'stl', true, HEADER_BYTES);
  reader.need(4, 'the 80-byte header and the triangle count of a binary STL');
  const header = bytes.subarray(0, HEADER_BYTES);
  if (header.every((b) => b === 0 || (b >= 32 && b < 127))) {
    const text = decodeText(header).replace(/\0/g, '').trim();
    if (text) comments.push(text);
  }
  const count = reader.uint32();
  const fullTriangles = Math.floor(reader.remaining / TRIANGLE_BYTES);
  if (fullTriangles < count) {
    const at = reader.offset + fullTriangles * TRIANGLE_BYTES;
    reader.fail(`the file ends after ${fullTriangles} of ${plural(count, 'triangle')}`, at);
  }
  if (reader.remaining > count * TRIANGLE_BYTES) {
    notes.push(`ignored ${plural(reader.remaining - count * TRIANGLE_BYTES, 'byte')} after the last triangle`);
  }
  const corners = new Float32Array(9 * count);
  const normals = new Float32Array(3 * count);
  const view = reader.view;
  for (let t = 0; t < count; t++) {
    const offset = reader.offset + t * TRIANGLE_BYTES;
    for (let k = 0; k < 3; k++) normals[3 * t + k] = view.getFloat32(offset + 4 * k, true);
    for (let k = 0; k < 9; k++) corners[9 * t + k] = view.getFloat32(offset + 12 + 4 * k, true);
  }
  const faceStarts = new Uint32Array(count + 1);
  for (let t = 1; t <= count; t++) faceStarts[t] = 3 * t;
  return { corners, faceStarts, normals };
}

function readAscii(bytes: Uint8Array, comments: string[], progress: Progress): Triangles {
  const scanner = new TextScanner(bytes, 'stl');
  const corners = new GrowableArray((n) => new Float32Array(n), bytes.length >> 5);
  const normals = new GrowableArray((n) => new Float32Array(n), bytes.length >> 7);
  const faceStarts = new GrowableArray((n) => new Uint32Array(n), bytes.length >> 8);
  faceStarts.push(0);
  /** Reads the next word, which must be `expected`. */
  const expect = (expected: string): void => {
    if (!scanner.skipBlankLines()) scanner.fail(`the file ends where '${expected}' should come`);
    const at = scanner.pos;
    if (!scanner.isWord(expected)) scanner.fail(`expected '${expected}', found '${scanner.token(at)}'`, at);
  };
  /** Reads three numbers; `what` names them in an error (a function: built only when one comes). */
  const readPoint = (target: GrowableArray<Float32Array<ArrayBuffer>>, what: () => string): void => {
    for (let k = 0; k < 3; k++) {
      if (scanner.atLineEnd()) scanner.fail(`${what()} needs 3 numbers`);
      target.push(scanner.number());
    }
    scanner.endLine(() => `${what()} should end after 3 numbers`);
  };

  expect('solid');
  comments.push(`solid ${scanner.restOfLine()}`.trim());
  // every pass reads at least one word, so there are fewer passes than bytes
  for (let pass = 0; ; pass++) {
    if (pass > bytes.length || !scanner.skipBlankLines()) scanner.fail("the file ends before 'endsolid'");
    const at = scanner.pos;
    if (scanner.isWord('endsolid')) {
      scanner.nextLine();
      // some files hold several solids one after the other
      if (!scanner.skipBlankLines()) break;
      expect('solid');
      comments.push(`solid ${scanner.restOfLine()}`.trim());
      continue;
    }
    if (!scanner.isWord('facet')) scanner.fail(`expected 'facet' or 'endsolid', found '${scanner.token(at)}'`, at);
    const facet = faceStarts.length - 1;
    if ((facet & PROGRESS_ROWS) === PROGRESS_ROWS) progress(scanner.pos / bytes.length);
    expect('normal');
    readPoint(normals, () => `the normal of facet ${facet}`);
    expect('outer');
    expect('loop');
    let cornerCount = 0;
    // every pass reads at least one word, so there are fewer passes than bytes
    for (let pass = 0; ; pass++) {
      if (pass > bytes.length || !scanner.skipBlankLines()) scanner.fail(`the file ends inside facet ${facet}`);
      const wordAt = scanner.pos;
      if (scanner.isWord('endloop')) break;
      if (!scanner.isWord('vertex')) {
        scanner.fail(`expected 'vertex' or 'endloop' in facet ${facet}, found '${scanner.token(wordAt)}'`, wordAt);
      }
      readPoint(corners, () => `vertex ${cornerCount} of facet ${facet}`);
      cornerCount++;
    }
    if (cornerCount === 0) scanner.fail(`facet ${facet} has no vertices`);
    expect('endfacet');
    faceStarts.push(corners.length / 3);
  }
  return { corners: corners.finish(), faceStarts: faceStarts.finish(), normals: normals.finish() };
}

