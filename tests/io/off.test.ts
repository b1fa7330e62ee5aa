import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { attribute, expectSameReadWithComments, faceLists, parseError, read } from './helpers.js';

const quadAndTriangle = [
  [0, 1, 2, 3],
  [0, 3, 4],
];
const fivePoints = '0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 0.5 0\n';

describe('OFF variants', () => {
  it('reads plain OFF, faces of any degree kept as polygons', () => {
    const file = read(`OFF\n5 2 0\n${fivePoints}4 0 1 2 3\n3 0 3 4\n`);
    expect(file.format).toBe('off');
    expect(file.counts).toEqual({ vertices: 5, faces: 2 });
    expect(faceLists(file.soup)).toEqual(quadAndTriangle);
    expect(Array.from(file.soup.positions.subarray(12))).toEqual([-1, 0.5, 0]);
  });

  it('reads counts on the keyword line, glued to the keyword, and without the edge count', () => {
    for (const head of ['OFF 5 2 0\n', 'OFF5 2 0\n', 'OFF\n5 2\n']) {
      expect(faceLists(read(`${head}${fivePoints}4 0 1 2 3\n3 0 3 4\n`).soup)).toEqual(quadAndTriangle);
    }
  });

  // as real files have them: each face's indices on lines of their own, blank lines between faces
  it('reads OFF as a stream of numbers: faces, vertices and counts over several lines', () => {
    const faces = '4\n0\n1\n2\n3\n\n3\n0\n3\n4\n\n';
    expect(faceLists(read(`OFF\n5 2 0\n${fivePoints}${faces}`).soup)).toEqual(quadAndTriangle);
    const file = read(`OFF\n5\n2\n0 0\n0\n1 0 0\n1 1\n0\n0 1 0\n-1\n0.5\n0\n4 0 1\n2 3\n3 0 3 4 0.5 0.5 0.5\n`);
    expect(faceLists(file.soup)).toEqual(quadAndTriangle);
    expect(Array.from(file.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0.5, 0]);
    // a face on a line of its own keeps its colour; the face over two lines has none
    expect(Array.from(attribute(file.soup.faceAttributes, 'color').data)).toEqual([0, 0, 0, 0.5, 0.5, 0.5]);
  });

  it('reads a COFF whose faces go on over several lines, each ending at its last index', () => {
    // vertex 2 goes on onto the next line too: it takes the numbers COFF needs (x y z r g b)
    const source = 'COFF\n3 2 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0\n0 0 255\n3\n0 1 2\n3 2 1\n0\n';
    const file = read(source);
    expect(faceLists(file.soup)).toEqual([
      [0, 1, 2],
      [2, 1, 0],
    ]);
    expect(Array.from(attribute(file.soup.vertexAttributes, 'color').data)).toEqual([255, 0, 0, 0, 255, 0, 0, 0, 255]);
  });

  it('skips # comments anywhere: before the keyword, between keyword and counts, after values, and blank lines', () => {
    const source =
      '# made by hand\n\nOFF # keyword\n# counts next\n\n5 2 7 # edges ignored\n' +
      '0 0 0 # 0\n1 0 0\n\n1 1 0\t# two\n0 1 0\n-1 0.5 0\n# faces\n4 0 1 2 3 # quad\n3 0 3 4\n';
    const file = read(source);
    expect(faceLists(file.soup)).toEqual(quadAndTriangle);
    expect(file.comments).toEqual(['made by hand', 'keyword', 'counts next', 'edges ignored', '0', 'two', 'faces', 'quad']);
  });

  it('reads COFF vertex colours, as uint8 when written as integers and float32 otherwise', () => {
    const ints = read('COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 128\n3 0 1 2\n');
    const intColor = attribute(ints.soup.vertexAttributes, 'color');
    expect([intColor.itemSize, intColor.data.constructor, Array.from(intColor.data)]).toEqual([
      4,
      Uint8Array,
      [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128],
    ]);
    const floats = read('COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1.0 0\n0 1 0 0 0 0.5\n3 0 1 2\n');
    const floatColor = attribute(floats.soup.vertexAttributes, 'color');
    expect([floatColor.itemSize, floatColor.data.constructor, Array.from(floatColor.data)]).toEqual([
      3,
      Float32Array,
      [1, 0, 0, 0, 1, 0, 0, 0, 0.5],
    ]);
  });

  it('reads NOFF normals, STOFF texture coordinates and all of STCNOFF in Geomview order', () => {
    const noff = read('NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n3 0 1 2\n');
    expect(Array.from(attribute(noff.soup.vertexAttributes, 'normal').data)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, -1]);
    const vertices = '0 0 0  0 0 1  1 0 0 1  0.5 1\n1 0 0  0 0 1  0 1 0 1  0 0\n0 1 0  0 0 1  0 0 1 1  1 0\n';
    const all = read(`STCNOFF\n3 1 0\n${vertices}3 0 1 2\n`);
    const names = all.soup.vertexAttributes!.map((a) => a.name);
    expect(names).toEqual(['normal', 'color', 'texcoord']);
    expect(Array.from(attribute(all.soup.vertexAttributes, 'texcoord').data)).toEqual([0.5, 1, 0, 0, 1, 0]);
    expect(Array.from(attribute(all.soup.vertexAttributes, 'color').data)).toEqual([1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1]);
  });

  it('reads 4OFF homogeneous coordinates and nOFF with 2 or 3 dimensions', () => {
    const four = read('4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 4 0 4\n3 0 1 2\n');
    expect(Array.from(four.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const flat = read('nOFF\n2\n3 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n');
    expect(Array.from(flat.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const three = read('nOFF 3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
    expect(three.counts).toEqual({ vertices: 3, faces: 1 });
  });

  it('reads nOFF of any dimension: beyond 3, x, y and z are kept; 4nOFF divides by the last', () => {
    const five = read('nOFF\n5\n3 1 0\n1 2 3 4 5\n6 7 8 9 10\n0 1 0 0 0\n3 0 1 2\n');
    expect(Array.from(five.soup.positions)).toEqual([1, 2, 3, 6, 7, 8, 0, 1, 0]);
    expect(five.notes).toContain('nOFF vertices have 5 coordinates: kept x, y and z, dropped the other 2');
    const homogeneous = read('4nOFF 4\n3 1 0\n2 4 6 8 2\n1 1 1 1 1\n0 2 0 0 2\n3 0 1 2\n');
    expect(Array.from(homogeneous.soup.positions)).toEqual([1, 2, 3, 1, 1, 1, 0, 1, 0]);
    expect(parseError(() => read('nOFF\n0\n3 1 0\n')).message).toBe('off: line 2, column 1: the dimension must be at least 1, not 0');
    expect(parseError(() => read('nOFF 999999\n1 0 0\n0\n')).message).toMatch(/the dimension 999999 is more numbers than the whole file holds/);
  });

  it('refuses a point at infinity', () => {
    expect(parseError(() => read('4OFF\n2 0 0\n0 0 0 1\n1 1 1 0\n')).message).toBe(
      'off: line 4, column 8: vertex 1 has w = 0: a point at infinity has no place in a mesh',
    );
  });

  it('keeps face colours after the indices: RGB, RGBA, integers or reals; colour-map indices are noted', () => {
    const rgb = read(`OFF\n5 2 0\n${fivePoints}4 0 1 2 3 1.0 0.5 0.0\n3 0 3 4 0 0 1.0\n`);
    const color = attribute(rgb.soup.faceAttributes, 'color');
    expect([color.itemSize, color.data.constructor, Array.from(color.data)]).toEqual([3, Float32Array, [1, 0.5, 0, 0, 0, 1]]);
    const rgba = read(`OFF\n5 2 0\n${fivePoints}4 0 1 2 3 255 128 0 255\n3 0 3 4\n`);
    const intColor = attribute(rgba.soup.faceAttributes, 'color');
    expect([intColor.itemSize, intColor.data.constructor]).toEqual([4, Uint8Array]);
    expect(Array.from(intColor.data)).toEqual([255, 128, 0, 255, 0, 0, 0, 255]);
    expect(rgba.notes).toContain('1 face has no colour (left black)');
    const indexed = read(`OFF\n5 2 0\n${fivePoints}4 0 1 2 3 7\n3 0 3 4 2\n`);
    expect(indexed.soup.faceAttributes).toEqual([]);
    expect(indexed.notes).toContain('ignored the colour-map indices of 2 faces (no colour map is loaded)');
  });

  it("skips a Geomview 'appearance { … }' block before the keyword", () => {
    const file = read('appearance {\n  +texturing\n  texture { file grid.pgm }\n}\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
    expect(file.counts).toEqual({ vertices: 3, faces: 1 });
    expect(file.notes[0]).toMatch(/skipped a Geomview 'appearance/);
  });

  it('reads CRLF line endings and files without the keyword (by the .off name)', () => {
    expect(faceLists(read('OFF\r\n3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n').soup)).toEqual([[0, 1, 2]]);
    const bare = read('3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n', 'triangle.off');
    expect(bare.notes).toContain('no OFF keyword: read as plain OFF');
  });
});

describe('OFF text, read a batch of lines at a time', () => {
  /** A strip of quads along x, with a triangle every third face, as the lines of an OFF file. */
  const strip = (n: number) => ({
    vertices: Array.from({ length: 2 * n }, (_, i) => `${i >> 1} ${i & 1} ${i / 8}`),
    faces: Array.from({ length: n - 1 }, (_, i) => (i % 3 === 0 ? `3 ${2 * i} ${2 * i + 2} ${2 * i + 1}` : `4 ${2 * i} ${2 * i + 2} ${2 * i + 3} ${2 * i + 1}`)),
  });
  const off = ({ vertices, faces }: ReturnType<typeof strip>) => `OFF\n${vertices.length} ${faces.length} 0\n${[...vertices, ...faces].join('\n')}\n`;

  it('names the line and column of a bad index thousands of lines in, as line by line', () => {
    const lines = strip(3000);
    lines.faces[2500] = '3 5000 5002 6000';
    // 2 lines before the vertices, 6000 vertex lines, then face 2500; the 6000 after '3 5000 5002 '
    expect(parseError(() => read(off(lines))).message).toBe(`off: line ${2 + 6000 + 2501}, column 13: face 2500: vertex index 6000 is out of range 0..5999`);
  });

  it('reads lines the fast lane leaves (comments, a vertex over two lines, long numbers, CRLF) as the rest', () => {
    const lines = strip(2500);
    const expected = read(off(lines)).soup;
    lines.vertices[3] = '1.00000000000000000000 1 0.375 # vertex 3';
    lines.vertices[2100] = `\t${lines.vertices[2100]}\r`;
    lines.vertices[4000] = lines.vertices[4000].replace(' ', '\n');
    lines.faces[1700] = `# a comment line\n${lines.faces[1700]}`;
    const file = read(off(lines));
    expect(Array.from(file.soup.positions)).toEqual(Array.from(expected.positions));
    expect(faceLists(file.soup)).toEqual(faceLists(expected));
    expect(file.notes).toEqual([]);
  });
});

describe('OFF text, the fast lane against token by token', () => {
  const SEED = 20261125;
  const wellFormed = fc.oneof(
    fc.integer({ min: -9, max: 9 }).map(String),
    fc.double({ noNaN: true, noDefaultInfinity: true, min: -10, max: 10 }).map((x) => x.toPrecision(6)),
  );
  const number = fc.oneof(wellFormed, fc.constantFrom('1e2', '-2.5E-1', '0.30000000000000004', '1.0', '+3', '.5', 'x', '1e999'));
  const index = fc.oneof({ weight: 6, arbitrary: fc.integer({ min: 0, max: 5 }).map(String) }, { weight: 1, arbitrary: fc.constantFrom('-1', '9', '2.0', '1e0') });
  // now and then more numbers than any OFF vertex holds (45 in 3D)
  const vertexLine = fc.oneof({ weight: 9, arbitrary: fc.array(number, { minLength: 2, maxLength: 7 }) }, { weight: 1, arbitrary: fc.array(wellFormed, { minLength: 44, maxLength: 47 }) });
  // the corner count: now and then one off, or not written as a whole number; then a colour or not
  const faceLine = fc
    .tuple(fc.array(index, { minLength: 1, maxLength: 5 }), fc.integer({ min: -1, max: 1 }), fc.constantFrom('', '', '', '', '.0'), fc.array(number, { maxLength: 4 }))
    .map(([ids, off, decimals, colour]) => [`${ids.length + off}${decimals}`, ...ids, ...colour]);
  const space = fc.constantFrom(' ', '  ', '\t', ' \r');
  const file = fc
    .tuple(fc.array(vertexLine, { minLength: 6, maxLength: 6 }), fc.array(faceLine, { maxLength: 6 }), fc.array(space, { minLength: 12, maxLength: 12 }), fc.integer({ min: -1, max: 11 }))
    .map(([vertices, faces, spaces, blank]) => {
      const lines = [...vertices, ...faces].map((tokens, i) => tokens.join(spaces[i % 12]));
      if (blank >= 0 && blank < lines.length) lines.splice(blank, 0, '');
      return { head: `OFF\n6 ${faces.length} 0\n`, lines };
    });

  // a comment at the end of every line sends each one token by token
  it(`reads every line as token by token reading does (seed ${SEED})`, () => {
    fc.assert(
      fc.property(file, ({ head, lines }) => expectSameReadWithComments(head, lines)),
      { seed: SEED, numRuns: 3000 },
    );
  });
});

describe('OFF BINARY', () => {
  /** A binary OFF of a quad and a triangle over five points. */
  function binaryOff(littleEndian: boolean, faceColorCount: boolean, colors: number[][] = [[], []]): Uint8Array {
    const words: Array<['i' | 'f', number]> = [
      ['i', 5],
      ['i', 2],
      ['i', 0],
    ];
    for (const x of [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0.5, 0]) words.push(['f', x]);
    quadAndTriangle.forEach((face, f) => {
      words.push(['i', face.length], ...face.map((v): ['i', number] => ['i', v]));
      if (faceColorCount) words.push(['i', colors[f].length], ...colors[f].map((c): ['f', number] => ['f', c]));
    });
    const head = new TextEncoder().encode('OFF BINARY\n');
    const bytes = new Uint8Array(head.length + 4 * words.length);
    bytes.set(head);
    const view = new DataView(bytes.buffer);
    words.forEach(([kind, x], i) => {
      if (kind === 'i') view.setInt32(head.length + 4 * i, x, littleEndian);
      else view.setFloat32(head.length + 4 * i, x, littleEndian);
    });
    return bytes;
  }

  /** A Geomview binary OFF, big-endian: the header line, then int32 ('i') and float32 ('f') words. */
  function geomviewBinary(header: string, words: Array<['i' | 'f', number]>): Uint8Array {
    const head = new TextEncoder().encode(`${header}\n`);
    const bytes = new Uint8Array(head.length + 4 * words.length);
    bytes.set(head);
    const view = new DataView(bytes.buffer);
    words.forEach(([kind, x], i) => (kind === 'i' ? view.setInt32(head.length + 4 * i, x) : view.setFloat32(head.length + 4 * i, x)));
    return bytes;
  }
  const i = (x: number): ['i', number] => ['i', x];
  const f = (x: number): ['f', number] => ['f', x];
  const triangle = [i(3), i(0), i(1), i(2), i(0)];

  it('reads nOFF BINARY (the dimension an int32 before the counts), 4OFF BINARY and COFF BINARY (RGBA floats)', () => {
    const flat = read(geomviewBinary('nOFF BINARY', [i(2), i(3), i(1), i(0), f(0), f(0), f(1), f(0), f(0), f(1), ...triangle]));
    expect(Array.from(flat.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const homogeneous = read(geomviewBinary('4OFF BINARY', [i(3), i(1), i(0), ...[0, 0, 0, 1, 2, 0, 0, 2, 0, 4, 0, 4].map(f), ...triangle]));
    expect(Array.from(homogeneous.soup.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    const colours = [1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 0.5];
    const rows = [0, 1, 2].flatMap((v) => [...[v === 1 ? 1 : 0, v === 2 ? 1 : 0, 0].map(f), ...colours.slice(4 * v, 4 * v + 4).map(f)]);
    const coloured = read(geomviewBinary('COFF BINARY', [i(3), i(1), i(0), ...rows, ...triangle]));
    expect(Array.from(attribute(coloured.soup.vertexAttributes, 'color').data)).toEqual(colours);
  });

  it('reads the big-endian layout of the Geomview spec, with face colour counts', () => {
    const file = read(binaryOff(false, true, [[1, 0, 0], []]));
    expect(file.encoding).toBe('binary_big_endian');
    expect(faceLists(file.soup)).toEqual(quadAndTriangle);
    expect(Array.from(file.soup.positions.subarray(12))).toEqual([-1, 0.5, 0]);
    expect(Array.from(attribute(file.soup.faceAttributes, 'color').data)).toEqual([1, 0, 0, 0, 0, 0]);
  });

  it("reads pmp-library's little-endian layout without colour counts, and says so", () => {
    const file = read(binaryOff(true, false));
    expect(file.encoding).toBe('binary_little_endian');
    expect(faceLists(file.soup)).toEqual(quadAndTriangle);
    expect(file.notes[0]).toMatch(/read as little-endian without face colour counts/);
  });

  it('reports where a cut-off binary file ends', () => {
    const bytes = binaryOff(false, true);
    const error = parseError(() => read(bytes.subarray(0, bytes.length - 6)));
    expect(error.location.byteOffset).toBeGreaterThan(11);
    expect(error.format).toBe('off');
  });
});

describe('malformed OFF', () => {
  // OFF is a stream of numbers, so a face short of an index takes the next face's count for it:
  // the error shows further on, and names the face that went on over lines
  it('says when a face lists fewer indices than it announces', () => {
    const error = parseError(() => read(`OFF\n5 2 0\n${fivePoints}5 0 1 2 3\n3 0 3 4\n`));
    // face 0 takes 3 from line 9 as its fifth index, and 0 3 4 as its colour
    expect(error.message).toBe(
      'off: line 10, column 1: the file ends after 1 of 2 faces ' +
        '(note: face 0 went on from line 8 onto line 9; if it should not, it lists too few numbers)',
    );
    expect(parseError(() => read(`OFF\n5 1 0\n${fivePoints}5 0 1 2 3\n`)).message).toBe(
      'off: line 9, column 1: the file ends inside face 0, which announces 5 corners but lists 4 vertex ids',
    );
  });

  it('names an out-of-range vertex index with its line, column and face', () => {
    const error = parseError(() => read(`OFF\n5 2 0\n${fivePoints}4 0 1 2 3\n3 0 3 17\n`));
    expect(error.message).toBe('off: line 9, column 7: face 1: vertex index 17 is out of range 0..4');
  });

  it('says how many vertices and faces came before the file ended', () => {
    expect(parseError(() => read(`OFF\n6 0 0\n${fivePoints}          \n`)).message).toBe(
      'off: line 9, column 1: the file ends after 5 of 6 vertices',
    );
    const twoFaces = `OFF\n5 3 0\n${fivePoints}4 0 1 2 3\n3 0 3 4\n      `;
    expect(parseError(() => read(twoFaces)).message).toMatch(/the file ends after 2 of 3 faces/);
  });

  it('refuses counts the file cannot hold before allocating, and negative counts', () => {
    const start = performance.now();
    expect(parseError(() => read('OFF\n2147483647 2147483647 0\n0 0 0\n')).message).toMatch(
      /line 2, column 1: the counts announce 2147483647 vertices and 2147483647 faces, but only 6 bytes follow/,
    );
    expect(performance.now() - start).toBeLessThan(50);
    expect(parseError(() => read('OFF\n-3 1 0\n')).message).toMatch(/negative counts/);
  });

  it('refuses a vertex with too few coordinates, and junk where a number belongs', () => {
    expect(parseError(() => read('OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n')).message).toBe(
      'off: line 6, column 3: face 0 has 0 corners; a face needs at least one ' +
        '(note: vertex 1 went on from line 4 onto line 5; if it should not, it lists too few numbers)',
    );
    expect(parseError(() => read('OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n')).message).toBe(
      "off: line 4, column 5: expected a number, found 'zero'",
    );
  });

  it('names the vertex or face whose line holds more numbers than any OFF element can', () => {
    const many = Array.from({ length: 200 }, () => '0').join(' ');
    expect(parseError(() => read(`OFF\n3 1 0\n0 0 0\n${many}\n0 1 0\n3 0 1 2\n`)).message).toMatch(/^off: line 4, column \d+: vertex 1 has more than \d+ numbers$/);
    expect(parseError(() => read(`OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 ${many}\n`)).message).toMatch(/^off: line 6, column \d+: face 0 has more than \d+ numbers$/);
  });

  it('refuses two numbers after a face: no colour has two components', () => {
    const error = parseError(() => read(`OFF\n5 1 0\n${fivePoints}3 0 1 2 3 4\n`));
    expect(error.message).toMatch(/face 0 has 2 numbers after its vertex ids/);
  });

  it('refuses an unknown keyword and an empty file', () => {
    expect(parseError(() => read('OFFX\n3 1 0\n', 'x.off')).message).toMatch(/unknown keyword 'OFFX'/);
    expect(parseError(() => read('', 'empty.off')).message).toBe('off: byte 0: the file is empty (0 bytes)');
    expect(parseError(() => read('# nothing but a comment\n', 'x.off')).message).toMatch(/holds no OFF data/);
  });
});
