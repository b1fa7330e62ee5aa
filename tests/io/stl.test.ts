import { describe, expect, it } from 'vitest';
import { buildMesh, cube, meshStats, readMesh, validate } from '../../src/index.js';
import { attribute, faceLists, parseError, read, text } from './helpers.js';

/** The 12 triangles of the unit cube, corner by corner. */
function cubeTriangles(): number[][][] {
  const soup = cube();
  const p = (v: number) => Array.from(soup.positions.subarray(3 * v, 3 * v + 3));
  return faceLists(soup).flatMap(([a, b, c, d]) => [
    [p(a), p(b), p(c)],
    [p(a), p(c), p(d)],
  ]);
}

function asciiStl(triangles: number[][][], name = 'cube'): string {
  const facets = triangles.map((corners) => {
    const vertices = corners.map((c) => `      vertex ${c.join(' ')}\n`).join('');
    return `  facet normal 0 0 0\n    outer loop\n${vertices}    endloop\n  endfacet\n`;
  });
  return `solid ${name}\n${facets.join('')}endsolid ${name}\n`;
}

function binaryStl(triangles: number[][][], header = 'binary cube'): Uint8Array {
  const bytes = new Uint8Array(84 + 50 * triangles.length);
  bytes.set(text(header).subarray(0, 80));
  const view = new DataView(bytes.buffer);
  view.setUint32(80, triangles.length, true);
  triangles.forEach((corners, t) => {
    view.setFloat32(84 + 50 * t + 8, 1, true); // normal (0, 0, 1)
    corners.flat().forEach((x, k) => view.setFloat32(84 + 50 * t + 12 + 4 * k, x, true));
  });
  return bytes;
}

describe('STL', () => {
  it('welds corners within a tolerance when asked, and only exactly equal ones otherwise', () => {
    // the cube with every corner of the odd triangles moved by 1e-5: exactly, only the even triangles' corners meet
    const triangles = cubeTriangles().map((corners, t) => corners.map((c) => c.map((x) => (t % 2 ? x + 1e-5 : x))));
    const bytes = binaryStl(triangles);
    const exact = readMesh(bytes);
    expect(exact.counts.vertices).toBeGreaterThan(8);
    const near = readMesh(bytes, { weldTolerance: 1e-4 });
    expect(near.counts).toEqual({ vertices: 8, faces: 12 });
    expect(near.notes.at(-1)).toMatch(/28 merged, within 0\.0001 of each other/);
    const { mesh } = buildMesh(near.soup);
    expect(validate(mesh)).toEqual([]);
    expect(meshStats(mesh)).toMatchObject({ vertices: 8, edges: 18, faces: 12, boundaryLoops: 0 });
  });

  it('welds the 36 corners of an ascii cube into its 8 vertices, giving a closed mesh', () => {
    const file = read(asciiStl(cubeTriangles()));
    expect(file.format).toBe('stl');
    expect(file.encoding).toBe('ascii');
    expect(file.counts).toEqual({ vertices: 8, faces: 12 });
    expect(file.notes).toContain('welded 36 STL corners into 8 vertices (28 merged)');
    expect(file.comments).toEqual(['solid cube']);
    const { mesh } = buildMesh(file.soup);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces, meshStats(mesh).boundaryLoops]).toEqual([8, 18, 12, 0]);
    expect(validate(mesh)).toEqual([]);
  });

  it('reads binary STL, facet normals included, even when its header starts with "solid"', () => {
    for (const header of ['binary cube', 'solid cube, but binary']) {
      const file = read(binaryStl(cubeTriangles(), header));
      expect(file.encoding).toBe('binary_little_endian');
      expect(file.counts).toEqual({ vertices: 8, faces: 12 });
      expect(Array.from(attribute(file.soup.faceAttributes, 'normal').data.subarray(0, 3))).toEqual([0, 0, 1]);
    }
  });

  it('welds -0 with 0 and keeps distinct positions apart, in first-seen order', () => {
    const file = read(asciiStl([
      [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
      [[-0, 1, 0], [1, 0, -0], [1, 1, 1e-30]],
    ]));
    expect(faceLists(file.soup)).toEqual([
      [0, 1, 2],
      [2, 1, 3],
    ]);
    expect(Array.from(file.soup.positions.subarray(9))).toEqual([1, 1, Math.fround(1e-30)]);
  });

  it('reads several solids in one ascii file, and facets with more than three vertices as polygons', () => {
    const quad = asciiStl([[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]], 'a');
    const file = read(quad + asciiStl([[[0, 0, 1], [1, 0, 1], [1, 1, 1]]], 'b'));
    expect(faceLists(file.soup)).toEqual([[0, 1, 2, 3], [4, 5, 6]]);
  });

  it('takes ascii keywords in any case, and only whole', () => {
    // (the first word stays 'solid': it is what tells an ascii file from a binary one)
    const shouting = asciiStl(cubeTriangles())
      .replace(/[a-z]+/g, (word) => (word.length % 2 === 0 ? word.toUpperCase() : word[0].toUpperCase() + word.slice(1)))
      .replace('Solid', 'solid');
    expect(shouting).toContain('Facet NORMAL 0 0 0\n    Outer LOOP\n      VERTEX');
    expect(faceLists(read(shouting, 'cube.stl').soup)).toEqual(faceLists(read(asciiStl(cubeTriangles())).soup));
    const longer = asciiStl(cubeTriangles()).replace('vertex', 'vertexes');
    expect(parseError(() => read(longer)).message).toBe(
      "stl: line 4, column 7: expected 'vertex' or 'endloop' in facet 0, found 'vertexes'",
    );
  });

  it('says where a binary STL ends early and an ascii one goes wrong', () => {
    const bytes = binaryStl(cubeTriangles());
    const cut = parseError(() => read(bytes.subarray(0, bytes.length - 30), 'cube.stl'));
    expect(cut.message).toBe('stl: byte 634: the file ends after 11 of 12 triangles');
    const broken = asciiStl(cubeTriangles()).replace('endloop', 'endlop');
    expect(parseError(() => read(broken)).message).toBe(
      "stl: line 7, column 5: expected 'vertex' or 'endloop' in facet 0, found 'endlop'",
    );
  });
});
