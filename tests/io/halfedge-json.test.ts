import { describe, expect, it } from 'vitest';
import { buildMesh, type HalfedgeMesh, ParseError, strip, tetrahedron, torus, validate } from '../../src/index.js';
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

  it('reads its own JSON text, with NaN positions written as null', () => {
    const { mesh } = buildMesh(strip(3));
    mesh.setPosition(2, Number.NaN, 0, 0);
    const textDoc = JSON.stringify(meshToHalfedgeJSON(mesh));
    const back = meshFromHalfedgeJSON(textDoc);
    expect(meshArrays(back)).toEqual(meshArrays(mesh));
    expect(validate(back)).toEqual([]);
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
    ['not JSON at all', () => '{ "format": ', /not valid JSON/],
    ['not an object', () => 42, /must be an object/],
  ];
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
