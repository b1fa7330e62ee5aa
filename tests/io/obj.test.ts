import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { buildMesh, validate } from '../../src/index.js';
import { attribute, expectSameReadWithComments, faceLists, parseError, read } from './helpers.js';

const square = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n';

describe('OBJ faces', () => {
  it('reads every corner form: v, v/vt, v//vn, v/vt/vn, and empty fields', () => {
    const faces = 'f 1 2 3\nf 1/1 3/3 4/2\nf 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/3/1 4/3/1\nf 2/2/ 3// 4\n';
    const source = `${square}vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n${faces}`;
    const file = read(source);
    expect(faceLists(file.soup)).toEqual([
      [0, 1, 2],
      [0, 2, 3],
      [0, 1, 2],
      [0, 1, 2, 3],
      [1, 2, 3],
    ]);
    expect(file.counts).toEqual({ vertices: 4, faces: 5 });
  });

  it('resolves negative indices relative to the latest vertex, texture coordinate and normal', () => {
    const source = `v 9 9 9\n${square}vt 0.5 0.5\nvn 0 1 0\nf -4/-1/-1 -3/-1/-1 -2/-1/-1 -1/-1/-1\nv 2 2 2\nf -1 -2 -3\n`;
    const file = read(source);
    expect(faceLists(file.soup)).toEqual([
      [1, 2, 3, 4],
      [5, 4, 3],
    ]);
  });

  it('keeps per-corner texture coordinates and normals as corner attributes, zero where a corner names none', () => {
    const source = `${square}vt 0.25 0.75\nvt 1 1\nvn 0 0 1\nvn 0 0 -1\nf 1/1/1 2/2/1 3/1/2\nf 1 3 4\n`;
    const file = read(source);
    const texcoord = attribute(file.soup.cornerAttributes, 'texcoord').data;
    expect(Array.from(texcoord)).toEqual([0.25, 0.75, 1, 1, 0.25, 0.75, 0, 0, 0, 0, 0, 0]);
    const normal = attribute(file.soup.cornerAttributes, 'normal').data;
    expect(Array.from(normal)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    expect(file.notes).toContain('3 face corners name no texcoord (set to zero)');
    const { mesh } = buildMesh(file.soup);
    expect(mesh.halfedgeAttributes.has('texcoord') && mesh.halfedgeAttributes.has('normal')).toBe(true);
    expect(validate(mesh)).toEqual([]);
  });

  it('reads a vertex w (ignored) and vertex colours given as r g b after x y z', () => {
    const file = read('v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n');
    expect(Array.from(file.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const colored = read('v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n');
    const color = attribute(colored.soup.vertexAttributes, 'color');
    expect([color.itemSize, color.data.constructor]).toEqual([3, Float32Array]);
    expect(Array.from(color.data)).toEqual([1, 0, 0, 0, 1, 0, 0, 0, 1]);
  });

  it('counts the statements a halfedge mesh has no use for', () => {
    const source = `mtllib a.mtl\no thing\ng one\n${square}usemtl red\ns 1\ng two\nf 1 2 3 4\nl 1 3\np 2\n`;
    const file = read(source);
    expect(file.notes).toContain("ignored 8 OBJ statements: 1 'mtllib', 1 'o', 2 'g', 1 'usemtl', 1 's', 1 'l', 1 'p'");
    expect(file.counts.faces).toBe(1);
  });

  it('accepts faces that name vertices defined further down', () => {
    expect(faceLists(read(`f 1 2 3\n${square}`).soup)).toEqual([[0, 1, 2]]);
  });

  it('keeps comments, and loads vertices without faces as a point set', () => {
    const file = read(`# scanned\n${square}`);
    expect(file.comments).toEqual(['scanned']);
    expect(file.notes).toContain('no faces: loaded as a point set');
  });
});

describe('malformed OBJ', () => {
  it('names the line and column of a bad index thousands of lines in, read a batch at a time', () => {
    const vertices = Array.from({ length: 6000 }, (_, i) => `v ${i >> 1} ${i & 1} ${i / 8}`);
    const faces = Array.from({ length: 2999 }, (_, i) => `f ${2 * i + 1} ${2 * i + 3} ${2 * i + 2}`);
    faces[2500] = 'f 5001 5003 0';
    // 6000 vertex lines, then face 2500; the 0 after 'f 5001 5003 '
    expect(parseError(() => read([...vertices, ...faces, ''].join('\n'), 'strip.obj')).message).toBe(
      `obj: line ${6000 + 2501}, column 13: face 2500: OBJ vertex indices count from 1; 0 names nothing`,
    );
  });

  it('names the line, column and face of an out-of-range index', () => {
    const error = parseError(() => read(`${square}f 1 2 3\nf 1 3 17\n`));
    expect(error.message).toBe('obj: line 6, column 7: face 1: vertex index 17 names nothing: it is out of range 1..4');
    expect(parseError(() => read(`${square}vt 0 0\nf 1/2 2/1 3/1\n`)).message).toBe(
      'obj: line 6, column 5: face 0: texture coordinate index 2 names nothing: it is out of range 1..1',
    );
  });

  it('refuses index 0 and negative indices that reach before the first vertex', () => {
    expect(parseError(() => read(`${square}f 0 1 2\n`)).message).toBe(
      'obj: line 5, column 3: face 0: OBJ vertex indices count from 1; 0 names nothing',
    );
    expect(parseError(() => read(`${square}f -5 1 2\n`)).message).toMatch(
      /line 5, column 3: face 0: vertex index -5 reaches back before the first vertex/,
    );
  });

  it('refuses malformed statements, with the line', () => {
    expect(parseError(() => read('v 1 2\n')).message).toBe(
      'obj: line 1, column 1: a vertex has x y z (then an optional w, or a colour r g b), not 2 numbers',
    );
    expect(parseError(() => read('v 1 2 x\n')).message).toBe("obj: line 1, column 7: expected a number, found 'x'");
    expect(parseError(() => read(`${square}f\n`)).message).toBe('obj: line 5, column 1: face 0 has no corners');
    expect(parseError(() => read(`${square}f 1 2 3a\n`)).message).toBe(
      "obj: line 5, column 7: expected a whole number, found '3a'",
    );
    expect(parseError(() => read('vn 0 0\n')).message).toMatch(/line 1, column 1: a normal has 3 numbers/);
  });
});

describe('OBJ, the fast lane against token by token', () => {
  const SEED = 20261125;
  const coordinate = fc.oneof(
    { weight: 8, arbitrary: fc.double({ noNaN: true, noDefaultInfinity: true, min: -10, max: 10 }).map((x) => x.toFixed(6)) },
    { weight: 1, arbitrary: fc.constantFrom('1e2', '0.30000000000000004', '+3', 'x', '1e999') },
  );
  const corner = fc.oneof(
    { weight: 8, arbitrary: fc.integer({ min: -6, max: 8 }).map(String) },
    { weight: 1, arbitrary: fc.constantFrom('1.0', '1/1', '2//1', '3/2/1') },
  );
  const statement = fc.oneof(
    { weight: 4, arbitrary: fc.array(coordinate, { minLength: 2, maxLength: 7 }).map((xs) => `v ${xs.join(' ')}`) },
    { weight: 3, arbitrary: fc.array(corner, { minLength: 0, maxLength: 5 }).map((cs) => `f ${cs.join(' ')}`) },
    { weight: 1, arbitrary: fc.constantFrom('vt 0.5 0.5', 'vn 0 0 1', 'g part', 'v\t1 2 3', 'f\t1 2 3', '') },
  );
  const file = fc.array(statement, { maxLength: 30 });

  // a comment at the end of every line sends each one token by token
  it(`reads every statement as token by token reading does (seed ${SEED})`, () => {
    fc.assert(
      fc.property(file, (lines) => expectSameReadWithComments('', lines, 'test.obj')),
      { seed: SEED, numRuns: 3000 },
    );
  });
});
