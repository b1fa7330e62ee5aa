import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { buildMesh, type HalfedgeMesh, type PolygonSoup, torus, uvSphere, validate } from '../../src/index.js';
import { meshToSoup, readMesh, type WriteFormat, writeMesh, writeSoup } from '../../src/core/io/index.js';
import { writePly } from '../../src/core/io/write-ply.js';
import { expectSameSoup, faceLists, meshArrays } from './helpers.js';

type Writer = [name: string, write: (soup: PolygonSoup) => Uint8Array, carries: Carries];
/** The attributes a format carries, by kind. */
interface Carries {
  vertex: string[];
  face: string[];
  corner: string[];
}

const plyCarries: Carries = {
  vertex: ['normal', 'color', 'texcoord', 'quality', 'label'],
  face: ['color', 'region'],
  corner: ['texcoord'],
};
const writers: Writer[] = [
  ['ascii PLY', (soup) => writeSoup(soup, 'ply'), plyCarries],
  ['little-endian PLY', (soup) => writeSoup(soup, 'ply-binary'), plyCarries],
  ['big-endian PLY', (soup) => writePly(soup, 'binary_big_endian'), plyCarries],
  ['OFF', (soup) => writeSoup(soup, 'off'), { vertex: ['normal', 'color', 'texcoord'], face: ['color'], corner: [] }],
  ['OBJ', (soup) => writeSoup(soup, 'obj'), { vertex: [], face: [], corner: ['texcoord', 'normal'] }],
];

/** A torus of quads carrying every kind of attribute, in several types. */
function decoratedMesh(colorType: 'uint8' | 'float32'): HalfedgeMesh {
  const { mesh } = buildMesh(torus(6, 5));
  const v = mesh.nVertices;
  const fill = (data: { length: number; [i: number]: number }, f: (i: number) => number) => {
    for (let i = 0; i < data.length; i++) data[i] = f(i);
  };
  fill(mesh.vertexAttributes.add('normal', 'float32', 3).data, (i) => Math.fround(Math.sin(i)));
  const color = (i: number, period: number) => (colorType === 'uint8' ? (37 * i) % 256 : Math.fround((i % period) / period));
  fill(mesh.vertexAttributes.add('color', colorType, 4).data, (i) => color(i, 7));
  fill(mesh.vertexAttributes.add('texcoord', 'float32', 2).data, (i) => Math.fround(i / (2 * v)));
  fill(mesh.vertexAttributes.add('quality', 'float64', 1).data, (i) => Math.sqrt(i));
  fill(mesh.vertexAttributes.add('label', 'int16', 1).data, (i) => i - 10);
  fill(mesh.faceAttributes.add('color', colorType, 3).data, (i) => color(i, 5));
  fill(mesh.faceAttributes.add('region', 'uint32', 1).data, (i) => i % 3);
  fill(mesh.halfedgeAttributes.add('texcoord', 'float32', 2).data, (i) => Math.fround(i / 100));
  fill(mesh.halfedgeAttributes.add('normal', 'float32', 3).data, (i) => Math.fround(Math.cos(i)));
  return mesh;
}

/** `soup` with only the attributes `carries` names. */
function only(soup: PolygonSoup, carries: Carries): PolygonSoup {
  const keep = (list: PolygonSoup['vertexAttributes'], names: string[]) => (list ?? []).filter((a) => names.includes(a.name));
  return {
    ...soup,
    vertexAttributes: keep(soup.vertexAttributes, carries.vertex),
    faceAttributes: keep(soup.faceAttributes, carries.face),
    cornerAttributes: keep(soup.cornerAttributes, carries.corner),
  };
}

describe('write, then read back', () => {
  for (const [name, write, carries] of writers) {
    for (const colorType of ['uint8', 'float32'] as const) {
      it(`${name} gives back positions, faces and the attributes it carries (${colorType} colours)`, () => {
        const soup = meshToSoup(decoratedMesh(colorType));
        expectSameSoup(only(readMesh(write(soup), { fileName: 'x' }).soup, carries), only(soup, carries));
      });
    }

    it(`${name} keeps float64 positions exactly, and faces of every degree`, () => {
      const soup: PolygonSoup = {
        positions: Float64Array.from([0.1, 1 / 3, Math.PI, -1e-300, 2 ** 60, 123456789.123456789, 1e21, -0, 5e-324, 0, 0, 0]),
        faceStarts: Uint32Array.from([0, 4, 6, 9]),
        faceIndices: Uint32Array.from([0, 1, 2, 3, 3, 1, 0, 2, 1]),
      };
      const back = readMesh(write(soup)).soup;
      expect(Array.from(back.positions)).toEqual(Array.from(soup.positions));
      expect(faceLists(back)).toEqual(faceLists(soup));
    });
  }

  it('OBJ carries vertex colours as r g b reals, uint8 ones scaled to 0…1', () => {
    const soup = meshToSoup(decoratedMesh('uint8'));
    const back = readMesh(writeSoup(soup, 'obj')).soup;
    const written = soup.vertexAttributes!.find((a) => a.name === 'color')!.data;
    const read = back.vertexAttributes!.find((a) => a.name === 'color')!.data;
    expect(read.length).toBe((written.length / 4) * 3);
    for (let v = 0; v < read.length / 3; v++) {
      for (let k = 0; k < 3; k++) expect(read[3 * v + k]).toBe(Math.fround(written[4 * v + k] / 255));
    }
  });

  it('leaves deleted elements out and numbers the vertices that remain densely', () => {
    const { mesh } = buildMesh(uvSphere(4, 5));
    const extra = mesh.addVertex(9, 9, 9);
    mesh.addVertex(7, 7, 7);
    mesh.deleteVertex(extra);
    mesh.deleteFace(0);
    const soup = readMesh(writeMesh(mesh, 'ply')).soup;
    expect(soup.positions.length / 3).toBe(mesh.nVertices);
    expect(Array.from(soup.positions.subarray(-3))).toEqual([7, 7, 7]);
    expect(soup.faceStarts.length - 1).toBe(mesh.nFaces);
  });
});

const corpus = path.resolve(import.meta.dirname, '../../../shared/corpus');
const samples = [
  'trimesh__fuze_binary_face_texcoord.ply',
  'cgal__colored_tetra_double_edges.ply',
  'meshlab__screwdriver_binary_be.ply',
  'geomview__vertcube.coff',
  'geomview__mushroom.off',
  'cgal__nm_edges_simple_noff.off',
  'trimesh__negative_indices.obj',
  'geometrycentral__moebius.obj',
  'assimp__wuson.ply',
  'pmp__beetle_off_binary.off',
];

describe.skipIf(!existsSync(corpus))('read, write, read again: real files', () => {
  const formats: WriteFormat[] = ['ply', 'ply-binary', 'off', 'obj'];
  for (const file of samples) {
    for (const format of formats) {
      it(`${file} as ${format} gives back the same mesh, ids and attributes included`, () => {
        const first = buildMesh(readMesh(readFileSync(path.join(corpus, file)), { fileName: file }).soup).mesh;
        const second = buildMesh(readMesh(writeMesh(first, format), { fileName: `x.${format}` }).soup).mesh;
        const third = readMesh(writeMesh(second, format), { fileName: `x.${format}` });
        expect(validate(second)).toEqual([]);
        // the first write keeps what the format carries; from then on nothing changes at all
        expectSameSoup(third.soup, meshToSoup(second));
        expect(meshArrays(buildMesh(third.soup).mesh)).toEqual(meshArrays(second));
        // and every pointer and position is the first mesh's
        expect(meshArrays(second, false)).toEqual(meshArrays(first, false));
      });
    }
  }
});
