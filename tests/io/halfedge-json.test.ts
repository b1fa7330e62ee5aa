import { describe, expect, it } from 'vitest';
import {
  buildMesh,
  type HalfedgeMesh,
  InvalidInputError,
  ParseError,
  strip,
  tetrahedron,
  torus,
  validate,
} from '../../src/index.js';
import { type HalfedgeDocument, meshFromHalfedgeJSON, meshToHalfedgeJSON } from '../../src/core/io/index.js';
import { meshArrays, parseError } from './helpers.js';

function decorated(): HalfedgeMesh {
  const { mesh } = buildMesh(torus(5, 4));
  mesh.vertexAttributes.add('color', 'uint8', 3).data.fill(200);
  mesh.halfedgeAttributes.add('texcoord', 'float32', 2).data.forEach((_, i, data) => (data[i] = Math.fround(i / 7)));
  mesh.edgeAttributes.add('sharp', 'uint8', 1).data[3] = 1;
  mesh.faceAttributes.add('area', 'float64', 1, 'copy').data.fill(0.25);
  // deleted slots keep their ids
  const lonely = mesh.addVertex(5, 5, 5);
  mesh.addVertex(6, 6, 6);
  mesh.deleteVertex(lonely);
  return mesh;
}

describe('halfedge JSON', () => {
  it('spells out every pointer of every halfedge, as in the textbook tables', () => {
    const doc = meshToHalfedgeJSON(buildMesh(tetrahedron()).mesh);
    expect(doc.halfedges[0]).toEqual({ id: 0, origin: 0, twin: 1, next: 2, prev: 4, face: 0, edge: 0 });
    expect(doc.edges[0]).toEqual({ id: 0, halfedges: [0, 1] });
    expect(doc.vertices[0]).toEqual({ id: 0, halfedge: doc.vertices[0].halfedge, position: [1, 1, 1] });
    expect(doc.halfedges.length).toBe(12);
  });

  it('reads back into the identical mesh: same ids, pointers, deleted slots and attributes', () => {
    const mesh = decorated();
    const back = meshFromHalfedgeJSON(meshToHalfedgeJSON(mesh));
    expect(meshArrays(back)).toEqual(meshArrays(mesh));
  });

  it('reads its own JSON text', () => {
    const mesh = decorated();
    const back = meshFromHalfedgeJSON(JSON.stringify(meshToHalfedgeJSON(mesh)));
    expect(meshArrays(back)).toEqual(meshArrays(mesh));
    expect(validate(back)).toEqual([]);
  });

  it('refuses to write NaN or infinity, which JSON cannot hold, naming the element and the field', () => {
    const { mesh } = buildMesh(strip(3));
    mesh.setPosition(2, 0, Number.NaN, 0);
    expect(() => meshToHalfedgeJSON(mesh)).toThrow(InvalidInputError);
    expect(() => meshToHalfedgeJSON(mesh)).toThrow(/^vertex 2: item 1 of 'position' is NaN; JSON has no NaN or infinity/);
    const attributed = decorated();
    attributed.halfedgeAttributes.get('texcoord')!.data[2 * 7 + 1] = -Infinity;
    expect(() => meshToHalfedgeJSON(attributed)).toThrow(/^halfedge 7: item 1 of attribute 'texcoord' is -Infinity;/);
  });

  it('reads a broken mesh as it is, so a bug report shows the bug', () => {
    const doc = meshToHalfedgeJSON(buildMesh(tetrahedron()).mesh);
    doc.halfedges[0].next = 0;
    const back = meshFromHalfedgeJSON(doc);
    expect(back.heNext[0]).toBe(0);
    expect(validate(back).length).toBeGreaterThan(0);
  });

  const malformed: Array<[string, (doc: HalfedgeDocument) => unknown, RegExp]> = [
    [
      'a pointer out of range',
      (doc) => ((doc.halfedges[5].next = 99), doc),
      /halfedge 5: 'next' is 99, but halfedge ids run from 0 to 11/,
    ],
    ['a twin that is not id ^ 1', (doc) => ((doc.halfedges[3].twin = 4), doc), /halfedge 3: 'twin' must be 2/],
    ['an edge that is not id >> 1', (doc) => ((doc.halfedges[3].edge = 0), doc), /halfedge 3: 'edge' must be 1/],
    ['records out of order', (doc) => ((doc.vertices[2].id = 3), doc), /vertex record 2 has id 3/],
    ['a position of two numbers', (doc) => ((doc.vertices[1].position = [0, 0]), doc), /vertex 1: 'position' must be 3 numbers/],
    [
      'a pointer that is not an integer',
      (doc) => (((doc.faces[2] as { halfedge: unknown }).halfedge = '4'), doc),
      /face 2: 'halfedge' must be an integer, not "4"/,
    ],
    ['halfedges that do not pair up into edges', (doc) => (doc.halfedges.pop(), doc), /11 halfedges for 6 edges/],
    [
      'an undescribed attribute',
      (doc) => ((doc.faces[1].attributes = { area: [1] }), doc),
      /face 1: attribute 'area' is not described/,
    ],
    ['a wrong format', (doc) => ({ ...doc, format: 'obj' }), /'format' must be 'halfedge-json'/],
    [
      'a null coordinate (what JSON makes of NaN)',
      (doc) => JSON.stringify(doc).replace('"position":[-1,-1,1]', '"position":[-1,-1,null]'),
      /vertex 3: item 2 of 'position' is null, not a number \(JSON writes NaN and infinity as null\)/,
    ],
    [
      'a coordinate too large for a double',
      (doc) => JSON.stringify(doc).replace('"position":[-1,-1,1]', '"position":[-1,1e999,1]'),
      /vertex 3: item 1 of 'position' is Infinity, which float64 cannot hold/,
    ],
    [
      'a coordinate that is text',
      (doc) => ((doc.vertices[3].position[0] = '1' as unknown as number), doc),
      /vertex 3: item 0 of 'position' is "1", not a number$/,
    ],
    ['not JSON at all', () => '{ "format": ', /not valid JSON/],
    ['not an object', () => 42, /must be an object/],
  ];
  /** A tetrahedron with a vertex attribute `color` (uint8 × 3), each of its records spoiled by `spoil`. */
  const coloured = (spoil: (doc: HalfedgeDocument) => void) => {
    const { mesh } = buildMesh(tetrahedron());
    mesh.vertexAttributes.add('color', 'uint8', 3).data.fill(9);
    const doc = meshToHalfedgeJSON(mesh);
    spoil(doc);
    return doc;
  };
  const malformedAttributes: Array<[string, HalfedgeDocument, RegExp]> = [
    [
      'an itemSize of 1e300 before allocating it',
      coloured((doc) => (doc.attributes[0].itemSize = 1e300)),
      /^attributes\[0\]\.itemSize is 1e\+300; the document holds 12 values of vertex attribute 'color' for 4 vertices$/,
    ],
    [
      'an itemSize of 2^31 before allocating it',
      coloured((doc) => (doc.attributes[0].itemSize = 2 ** 31)),
      /^attributes\[0\]\.itemSize is 2147483648; the document holds 12 values/,
    ],
    [
      'an itemSize only one record agrees with, naming the first record that does not',
      coloured((doc) => {
        doc.attributes[0].itemSize = 1000;
        doc.vertices[0].attributes!.color = Array.from({ length: 1000 }, () => 1);
      }),
      /^vertex 1: attribute 'color' must be 1000 numbers$/,
    ],
    [
      'a record with too few values',
      coloured((doc) => doc.vertices[2].attributes!.color.pop()),
      /^vertex 2: attribute 'color' must be 3 numbers$/,
    ],
    [
      'a value an integer attribute would wrap',
      coloured((doc) => (doc.vertices[1].attributes!.color[2] = 256)),
      /^vertex 1: item 2 of attribute 'color' is 256, which uint8 cannot hold$/,
    ],
    [
      'a fraction in an integer attribute',
      coloured((doc) => (doc.vertices[3].attributes!.color[0] = 1.5)),
      /^vertex 3: item 0 of attribute 'color' is 1.5, which uint8 cannot hold$/,
    ],
    [
      'a null attribute value',
      coloured((doc) => ((doc.vertices[0].attributes!.color[1] as number | null) = null)),
      /^vertex 0: item 1 of attribute 'color' is null, not a number/,
    ],
  ];
  for (const [what, doc, reason] of malformedAttributes) {
    it(`refuses ${what}, naming the field`, () => {
      const error = parseError(() => meshFromHalfedgeJSON(JSON.stringify(doc)));
      expect(error.format).toBe('halfedge-json');
      expect(error.reason).toMatch(reason);
    });
  }

  it('names the place of what it refuses: the path to the value, with its line and column when the document is text', () => {
    const doc = meshToHalfedgeJSON(buildMesh(tetrahedron()).mesh);
    (doc.vertices[3].position as unknown[])[2] = null;
    expect(parseError(() => meshFromHalfedgeJSON(doc)).location).toEqual({ path: 'vertices[3].position[2]' });
    const source = JSON.stringify(doc, null, 2);
    const lines = source.split('\n');
    const line = lines.findIndex((l) => l.includes('null')) + 1;
    const column = lines[line - 1].indexOf('null') + 1;
    expect(parseError(() => meshFromHalfedgeJSON(source)).message).toBe(
      `halfedge-json: line ${line}, column ${column} (vertices[3].position[2]): vertex 3: item 2 of 'position' is null, not a number (JSON writes NaN and infinity as null)`,
    );
    // text that is not JSON: where it breaks
    expect(parseError(() => meshFromHalfedgeJSON('{\n  "format": "halfedge-json",\n  "version": 1,,\n}')).location).toEqual({ line: 3, column: 16 });
  });

  it('reads a float32 attribute value written as a double that float32 holds exactly, and refuses one beyond its range', () => {
    const { mesh } = buildMesh(tetrahedron());
    mesh.faceAttributes.add('weight', 'float32', 1).data.set([0.1, 0.2, 0.3, 3e38]);
    const doc = meshToHalfedgeJSON(mesh);
    expect(meshArrays(meshFromHalfedgeJSON(JSON.stringify(doc)))).toEqual(meshArrays(mesh));
    doc.faces[3].attributes!.weight[0] = 1e39;
    expect(parseError(() => meshFromHalfedgeJSON(doc)).reason).toBe(
      "face 3: item 0 of attribute 'weight' is 1e+39, which float32 cannot hold",
    );
  });

  for (const [what, spoil, message] of malformed) {
    it(`refuses ${what} with a ParseError that names the record`, () => {
      const doc = meshToHalfedgeJSON(buildMesh(tetrahedron()).mesh);
      const input = spoil(doc);
      const error = parseError(() => meshFromHalfedgeJSON(input));
      expect(error).toBeInstanceOf(ParseError);
      expect(error.format).toBe('halfedge-json');
      expect(error.message).toMatch(message);
    });
  }
});
