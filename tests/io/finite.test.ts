/**
 * NaN and infinity. A position that is one refuses the file, naming where it was read: line and
 * column in text, byte offset in binary. Any other value that is one (a facet normal of no area, a
 * normal or texture coordinate written as `nan`, a PLY `quality`) is dropped with a note naming
 * the first and the count, and the mesh opens, and writes and reads back the same. The writers
 * refuse a mesh holding one, so whatever the library reads it writes.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, cube, InvalidInputError, meshToSoup, writeMesh, writeSoup } from '../../src/index.js';
import { type MeshFile, readMesh, type WriteFormat } from '../../src/core/io/index.js';
import { expectSurvivesReload } from '../core/reload.js';
import { attribute, makePly, meshArrays, parseError, read, text } from './helpers.js';

/** A binary STL of `facets`, each its normal then its three corners (12 numbers). */
function binaryStl(facets: number[][]): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * facets.length);
  const view = new DataView(bytes.buffer);
  view.setUint32(80, facets.length, true);
  facets.forEach((numbers, t) => numbers.forEach((x, k) => view.setFloat32(84 + 50 * t + 4 * k, x, true)));
  return bytes;
}

/** An `OFF BINARY` file as Geomview writes it (big-endian, a colour count after each face) of `vertices` and one triangle. */
function binaryOff(vertices: number[][]): Uint8Array {
  const head = text('OFF BINARY\n');
  const words = [vertices.length, 1, 0, ...vertices.flat(), 3, 0, 1, 2, 0];
  const bytes = new Uint8Array(head.length + 4 * words.length);
  bytes.set(head);
  const view = new DataView(bytes.buffer);
  words.forEach((x, i) => {
    const at = head.length + 4 * i;
    if (i >= 3 && i < 3 + 3 * vertices.length) view.setFloat32(at, x);
    else view.setInt32(at, x);
  });
  return bytes;
}

/** The file builds into a valid mesh that saves and reads back the same; written as `format`, it keeps its attributes too. */
function expectWritesBack(file: MeshFile, format?: WriteFormat): void {
  const { mesh } = buildMesh(file.soup);
  expectSurvivesReload(mesh);
  if (!format) return;
  const again = buildMesh(readMesh(writeMesh(mesh, format), { fileName: `again.${format === 'ply-binary' ? 'ply' : format}` }).soup).mesh;
  expect(meshArrays(again)).toEqual(meshArrays(mesh));
}

const triangle = [0, 0, 0, 1, 0, 0, 0, 1, 0];

describe('values that are not finite', () => {
  it('refuse the file when they are a position, naming the line and column, or the byte, where it was read', () => {
    const xyz = ['x', 'y', 'z'].map((name) => ({ name, type: 'float' }));
    // a list before x: the row's place is found by reading the lists of the rows before it
    const listed = {
      name: 'vertex',
      props: [{ name: 'tags', type: 'int', count: 'uchar' }, ...xyz],
      rows: [[[7], 0, 0, 0], [[], 1, 0, 0], [[1, 2], 0, Number.NaN, 0]],
    };
    const stlBytes = binaryStl([[0, 0, 1, ...triangle], [0, 0, 1, 0, 0, 0, 1, 0, 0, 1, -Infinity, 0]]);
    const offBytes = binaryOff([[0, 0, 0], [1, 0, 0], [0, Number.NaN, 0]]);
    const cases: Array<[string, () => unknown, string]> = [
      ['OBJ', () => read('v 0 0 0\nv 1 0 0\n# a comment\nv 0 nan 0\nf 1 2 3\n', 'a.obj'), "obj: line 4, column 5: vertex 2's position (item 1) is NaN, not a number"],
      // vertex 1 goes on over two lines, as OFF allows
      ['OFF', () => read('OFF\n3 1 0\n0 0 0\n1 0\n  0\n0 1 -inf\n3 0 1 2\n', 'a.off'), "off: line 6, column 5: vertex 2's position (item 2) is minus infinity: a value written as infinite, or beyond the range of float64, where it is kept"],
      ['OFF BINARY', () => read(offBytes, 'a.off'), `off: byte ${11 + 12 + 2 * 12 + 4}: vertex 2's position (item 1) is NaN, not a number`],
      ['ascii PLY', () => read(makePly('ascii', [listed])), "ply: line 11, column 9: vertex 2's position (item 1) is NaN, not a number"],
      ['binary PLY', () => read(makePly('binary_big_endian', [listed])), `ply: byte ${makePly('binary_big_endian', [listed]).length - 8}: vertex 2's position (item 1) is NaN, not a number`],
      ['ascii STL', () => read('solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n  vertex 0 1 NaN\nendloop\nendfacet\nendsolid s\n', 'a.stl'), "stl: line 6, column 14: vertex 2's position (item 2) is NaN, not a number"],
      // the welded vertex is named where its first corner was read: facet 1's third
      ['binary STL', () => read(stlBytes, 'a.stl'), `stl: byte ${84 + 50 + 12 + 24 + 4}: vertex 3's position (item 1) is minus infinity: a value written as infinite, or beyond the range of float32, where it is kept`],
    ];
    for (const [name, readIt, message] of cases) expect(parseError(readIt).message, name).toBe(message);
  });

  it('drop a binary STL facet normal, computing it again from the facet (zero for a facet of no area), with a note naming the first and the count', () => {
    const file = read(
      binaryStl([
        [0, 0, 1, ...triangle],
        // a facet of no area (its corners on a line) has no normal: an exporter wrote NaN
        [Number.NaN, Number.NaN, Number.NaN, 0, 0, 0, 1, 0, 0, 2, 0, 0],
        [Number.NaN, 0, Infinity, 0, 0, 0, 0, 1, 0, 0, 0, 1],
      ]),
      'a.stl',
    );
    expect(file.notes).toContain(
      "dropped 2 face normals that were NaN or infinite, computed again from the corners of its face (zero for a face without area); the first is face 1's (item 0), at byte 134",
    );
    expect(Array.from(attribute(file.soup.faceAttributes, 'normal').data)).toEqual([0, 0, 1, 0, 0, 0, 1, 0, 0]);
    expectWritesBack(file);
  });

  it('drop an ascii STL facet normal written as nan, computing it again from the facet', () => {
    const file = read('solid s\n  facet normal nan nan nan\n    outer loop\n      vertex 0 0 0\n      vertex 0 1 0\n      vertex 1 0 0\n    endloop\n  endfacet\nendsolid s\n', 'a.stl');
    expect(file.notes).toContain(
      "dropped 1 face normal that was NaN or infinite, computed again from the corners of its face (zero for a face without area); the first is face 0's (item 0), at line 2, column 16",
    );
    expect(Array.from(attribute(file.soup.faceAttributes, 'normal').data)).toEqual([0, 0, -1]);
    expectWritesBack(file);
  });

  it('drop an OBJ normal written as nan that a face uses, naming its line and column, and the mesh writes back as OBJ', () => {
    const file = read('v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn nan nan nan\nf 1//1 2//1 3//1\nf 2//2 4//2 3//1\n', 'a.obj');
    expect(file.notes).toContain(
      "dropped 2 face corner normals that were NaN or infinite, set to zero; the first is face corner 3's (item 0), at line 6, column 4",
    );
    expect(Array.from(attribute(file.soup.cornerAttributes, 'normal').data)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1]);
    expectWritesBack(file, 'obj');
  });

  it('drop a PLY quality or float colour that is NaN, naming its place, in every encoding, and the mesh writes back as PLY', () => {
    const vertex = {
      name: 'vertex',
      props: ['x', 'y', 'z', 'quality', 'red', 'green', 'blue'].map((name) => ({ name, type: 'float' })),
      rows: [
        [0, 0, 0, 1, 0.5, 0.5, 0.5],
        [1, 0, 0, Number.NaN, 0.5, 0.5, 0.5],
        [0, 1, 0, 2, 0.5, Number.NaN, 0.5],
      ],
    };
    const face = { name: 'face', props: [{ name: 'vertex_indices', type: 'int', count: 'uchar' }], rows: [[[0, 1, 2]]] };
    for (const encoding of ['ascii', 'binary_little_endian'] as const) {
      const bytes = makePly(encoding, [vertex, face]);
      const file = read(bytes);
      // the header, then whole rows of seven float32 before the value
      const body = bytes.length - 3 * 28 - 13;
      const [quality, color] = encoding === 'ascii' ? ['line 15, column 7', 'line 16, column 13'] : [`byte ${body + 28 + 12}`, `byte ${body + 56 + 20}`];
      expect(file.notes, encoding).toEqual(
        expect.arrayContaining([
          `dropped 1 vertex 'quality' value that was NaN or infinite, set to zero; the first is vertex 1's, at ${quality}`,
          `dropped 1 vertex colour that was NaN or infinite, set to black; the first is vertex 2's (item 1), at ${color}`,
        ]),
      );
      expect(Array.from(attribute(file.soup.vertexAttributes, 'quality').data)).toEqual([1, 0, 2]);
      expect(Array.from(attribute(file.soup.vertexAttributes, 'color').data)).toEqual([0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0, 0, 0]);
      expectWritesBack(file, 'ply-binary');
    }
  });

  it('name where the first dropped value was read for a few attributes, and tell of the rest in one note', () => {
    const names = Array.from({ length: 12 }, (_, k) => `w${k}`);
    const vertex = {
      name: 'vertex',
      props: ['x', 'y', 'z', ...names].map((name) => ({ name, type: 'float' })),
      rows: [[0, 0, 0, ...names.map(() => Number.NaN)]],
    };
    const notes = read(makePly('binary_little_endian', [vertex])).notes.filter((note) => note.startsWith('dropped'));
    expect(notes.length).toBe(9);
    expect(notes[7]).toMatch(/^dropped 1 vertex 'w7' value that was NaN or infinite, set to zero; the first is vertex 0's, at byte \d+$/);
    expect(notes[8]).toBe("dropped NaN or infinite values of 4 more attributes ('w8', 'w9', 'w10', 'w11'): 4 items, replaced as above");
  });

  it('drop an OFF colour written as nan, and the mesh writes back as OFF', () => {
    const file = read('COFF\n3 1 0\n0 0 0 1 1 1\n1 0 0 0.5 nan 1\n0 1 0 1 1 1\n3 0 1 2\n', 'a.off');
    expect(file.notes).toContain("dropped 1 vertex colour that was NaN or infinite, set to black; the first is vertex 1's (item 1), at line 4, column 11");
    expect(Array.from(attribute(file.soup.vertexAttributes, 'color').data)).toEqual([1, 1, 1, 0, 0, 0, 1, 1, 1]);
    expectWritesBack(file, 'off');
  });

  it('are never written: the writers refuse the mesh, naming the value', () => {
    const { mesh } = buildMesh(cube());
    mesh.positions[3 * 5 + 1] = Number.NaN;
    for (const format of ['ply', 'ply-binary', 'off', 'obj'] as const) {
      expect(() => writeMesh(mesh, format)).toThrow(new InvalidInputError("cannot write the mesh: vertex 5's position (item 1) is NaN, not a number; no reader would take it back"));
    }
    mesh.positions[3 * 5 + 1] = 1;
    mesh.faceAttributes.add('weight', 'float32', 1).data[4] = Infinity;
    expect(() => writeSoup(meshToSoup(mesh), 'ply')).toThrow(/^cannot write the mesh: face 4's weight is infinity/);
  });
});
