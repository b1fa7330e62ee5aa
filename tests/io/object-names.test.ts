/**
 * Names from a file that are also the names of `Object.prototype`'s members. A lookup in a plain
 * object finds `constructor` or `toString` there even though no table lists them, and writing
 * `__proto__` into one changes its prototype instead of adding a key: every table keyed by text
 * from a file must treat these as the ordinary names they are.
 */
import { describe, expect, it } from 'vitest';
import { AttributeSet, buildMesh, type HalfedgeMesh, InvalidInputError, ParseError, torus, validate } from '../../src/index.js';
import { meshFromHalfedgeJSON, meshToHalfedgeJSON, writeMesh } from '../../src/core/io/index.js';
import { attribute, faceLists, makePly, meshArrays, parseError, type PlyElementSpec, plyEncodings, read } from './helpers.js';

const objectNames = ['constructor', 'toString', '__proto__', 'hasOwnProperty', 'valueOf'];

const xyz = ['x', 'y', 'z'].map((name) => ({ name, type: 'float' }));
const triangle: PlyElementSpec = {
  name: 'vertex',
  props: xyz,
  rows: [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
  ],
};
const oneFace: PlyElementSpec = {
  name: 'face',
  props: [{ name: 'vertex_indices', type: 'int', count: 'uchar' }],
  rows: [[[0, 1, 2]]],
};

describe('PLY type names', () => {
  for (const name of objectNames) {
    it(`refuses '${name}' as a list's count type, a list's item type and a scalar type, naming the line`, () => {
      const headers = [
        `element face 1\nproperty list ${name} int vertex_indices\nend_header\n0\n`,
        `element face 1\nproperty list uchar ${name} vertex_indices\nend_header\n0\n`,
        `element vertex 1\nproperty ${name} x\nend_header\n0\n`,
      ];
      for (const header of headers) {
        const error = parseError(() => read(`ply\nformat ascii 1.0\n${header}`));
        expect(error.location.line).toBe(4);
        expect(error.reason).toMatch(new RegExp(`^unknown property type '${name}'`));
      }
    });
  }
});

describe('PLY element and property names', () => {
  for (const encoding of plyEncodings) {
    it(`skips elements named like object members, with a note, in ${encoding}`, () => {
      const extras = objectNames.map((name): PlyElementSpec => ({ name, props: [{ name: 'n', type: 'int' }], rows: [[7]] }));
      const file = read(makePly(encoding, [triangle, ...extras, oneFace]));
      expect(faceLists(file.soup)).toEqual([[0, 1, 2]]);
      expect(file.notes.join('\n')).toMatch(/skipped elements 'constructor' \(1 row\), 'toString' \(1 row\), '__proto__'/);
    });

    it(`keeps scalar properties named like object members as attributes, in ${encoding}`, () => {
      const props = [...xyz, ...objectNames.map((name) => ({ name, type: 'short' }))];
      const vertex = { name: 'vertex', props, rows: triangle.rows.map((row, i) => [...row, 1 + i, 2, 3, 4, 5 + i]) };
      const faceProps = [oneFace.props[0], ...objectNames.map((name) => ({ name, type: 'uchar' }))];
      const face = { name: 'face', props: faceProps, rows: [[[0, 1, 2], 10, 20, 30, 40, 50]] };
      const { soup } = read(makePly(encoding, [vertex, face]));
      expect(objectNames.map((name) => Array.from(attribute(soup.vertexAttributes, name).data))).toEqual([
        [1, 2, 3],
        [2, 2, 2],
        [3, 3, 3],
        [4, 4, 4],
        [5, 6, 7],
      ]);
      const faceValues = objectNames.map((name) => Array.from(attribute(soup.faceAttributes, name).data));
      expect(faceValues).toEqual([[10], [20], [30], [40], [50]]);
    });

    it(`takes a face list named like an object member as the only list, in ${encoding}`, () => {
      for (const name of objectNames) {
        const face = { ...oneFace, props: [{ name, type: 'int', count: 'uchar' }] };
        expect(faceLists(read(makePly(encoding, [triangle, face])).soup)).toEqual([[0, 1, 2]]);
      }
    });
  }
});

describe('OBJ statements', () => {
  it('counts statements named like object members among the ignored ones', () => {
    const statements = objectNames.map((name) => `${name} 1 2\n${name}\n`).join('');
    const file = read(`v 0 0 0\nv 1 0 0\nv 0 1 0\n${statements}f 1 2 3\n`);
    expect(faceLists(file.soup)).toEqual([[0, 1, 2]]);
    const counted = objectNames.map((name) => `2 '${name}'`).join(', ');
    expect(file.notes).toContain(`ignored 10 OBJ statements: ${counted}`);
  });
});

/** A torus with one attribute per kind of element under each of the names. */
function namedLikeObjectMembers(): HalfedgeMesh {
  const { mesh } = buildMesh(torus(4, 3));
  objectNames.forEach((name, k) => {
    mesh.vertexAttributes.add(name, 'int16', 1).data.forEach((_, i, data) => (data[i] = 3 * i + k));
    mesh.faceAttributes.add(name, 'float32', 1).data.forEach((_, i, data) => (data[i] = i / 4 + k));
    mesh.halfedgeAttributes.add(name, 'uint8', 2).data.forEach((_, i, data) => (data[i] = (i + k) % 256));
    mesh.edgeAttributes.add(name, 'float64', 1).data.forEach((_, i, data) => (data[i] = -1 - i - k));
  });
  return mesh;
}

describe('attribute names through a write and a read', () => {
  for (const format of ['ply', 'ply-binary'] as const) {
    it(`keeps vertex and face attributes named like object members in ${format}`, () => {
      const mesh = namedLikeObjectMembers();
      const { mesh: back } = buildMesh(read(writeMesh(mesh, format)).soup);
      const values = (set: AttributeSet, name: string) => Array.from(set.get(name)?.data ?? []);
      for (const name of objectNames) {
        expect(values(back.vertexAttributes, name), name).toEqual(values(mesh.vertexAttributes, name));
        expect(values(back.faceAttributes, name), name).toEqual(values(mesh.faceAttributes, name));
      }
    });
  }

  it('keeps attributes of every element named like object members in halfedge JSON, as an object and as text', () => {
    const mesh = namedLikeObjectMembers();
    const doc = meshToHalfedgeJSON(mesh);
    expect(Object.keys(doc.vertices[0].attributes ?? {})).toEqual(objectNames);
    expect(meshArrays(meshFromHalfedgeJSON(doc))).toEqual(meshArrays(mesh));
    const back = meshFromHalfedgeJSON(JSON.stringify(doc));
    expect(meshArrays(back)).toEqual(meshArrays(mesh));
    expect(validate(back)).toEqual([]);
  });

  it('refuses a record that lacks a described attribute named like an object member', () => {
    for (const name of objectNames) {
      const mesh = buildMesh(torus(4, 3)).mesh;
      mesh.vertexAttributes.add(name, 'uint8', 1);
      const doc = meshToHalfedgeJSON(mesh);
      delete doc.vertices[2].attributes;
      const error = parseError(() => meshFromHalfedgeJSON(JSON.stringify(doc)));
      expect(error).toBeInstanceOf(ParseError);
      expect(error.reason).toBe(`vertex 2: attribute '${name}' is missing`);
    }
  });
});

describe('attribute types', () => {
  it('refuses a type that is an object member rather than a typed array name', () => {
    for (const name of objectNames) {
      expect(() => new AttributeSet(4).add('value', name as 'uint8', 1)).toThrow(InvalidInputError);
      expect(() => new AttributeSet(4).add('value', name as 'uint8', 1)).toThrow(/unknown attribute type/);
    }
  });
});
