import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { buildMesh, ParseError, tetrahedron, validate } from '../../src/index.js';
import { readMesh, writeSoup } from '../../src/core/io/index.js';
import {
  attribute,
  expectSameSoup,
  faceLists,
  makePly,
  parseError,
  type PlyElementSpec,
  type PlyEncoding,
  plyEncodings,
  read,
  text,
} from './helpers.js';

const xyz = [
  { name: 'x', type: 'float' },
  { name: 'y', type: 'float' },
  { name: 'z', type: 'float' },
];
const square: PlyElementSpec = {
  name: 'vertex',
  props: xyz,
  rows: [
    [0, 0, 0],
    [1, 0, 0],
    [1, 1, 0],
    [0, 1, 0],
  ],
};
/** The header of an ascii PLY file up to its vertices' x y z (before any face element). */
const xyzHeader = (vertices: number | string, encoding = 'ascii') =>
  `ply\nformat ${encoding} 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\n`;
const twoTriangles: PlyElementSpec = {
  name: 'face',
  props: [{ name: 'vertex_indices', type: 'int', count: 'uchar' }],
  rows: [[[0, 1, 2]], [[0, 2, 3]]],
};

describe('PLY scalar types', () => {
  const types: Array<[string[], number[]]> = [
    [['char', 'int8'], [-128, 127]],
    [['uchar', 'uint8'], [0, 255]],
    [['short', 'int16'], [-32768, 32767]],
    [['ushort', 'uint16'], [0, 65535]],
    [['int', 'int32'], [-2147483648, 2147483647]],
    [['uint', 'uint32'], [0, 4294967295]],
    [['float', 'float32'], [-1.5, 3.4028234663852886e38]],
    [['double', 'float64'], [-1e-300, 0.1]],
  ];
  for (const encoding of plyEncodings) {
    for (const [names, values] of types) {
      for (const type of names) {
        it(`reads ${type} in ${encoding}, extreme values included`, () => {
          const file = read(
            makePly(encoding, [
              {
                name: 'vertex',
                props: [...xyz, { name: 'value', type }],
                rows: values.map((v, i) => [i, 0, 0, v]),
              },
            ]),
          );
          const kept = attribute(file.soup.vertexAttributes, 'value');
          expect(Array.from(kept.data)).toEqual(values);
          expect(file.encoding).toBe(encoding);
        });
      }
    }
  }

  it('keeps float positions as float32 and double ones as float64', () => {
    expect(read(makePly('binary_little_endian', [square])).soup.positions).toBeInstanceOf(Float32Array);
    const doubles = { ...square, props: xyz.map((p) => ({ ...p, type: 'double' })) };
    expect(read(makePly('binary_big_endian', [doubles])).soup.positions).toBeInstanceOf(Float64Array);
  });
});

describe('PLY lists', () => {
  for (const encoding of plyEncodings) {
    for (const count of ['uchar', 'char', 'ushort', 'short', 'uint', 'int', 'uint8', 'int16', 'uint32']) {
      it(`reads faces whose count is ${count} in ${encoding}`, () => {
        const faces = { ...twoTriangles, props: [{ name: 'vertex_indices', type: 'uint', count }] };
        expect(faceLists(read(makePly(encoding, [square, faces])).soup)).toEqual([
          [0, 1, 2],
          [0, 2, 3],
        ]);
      });
    }

    it(`keeps faces of any degree as polygons in ${encoding}`, () => {
      const hexagonFan: PlyElementSpec = {
        name: 'vertex',
        props: xyz,
        rows: Array.from({ length: 6 }, (_, i) => [Math.cos(i), Math.sin(i), 0]),
      };
      const faces = { ...twoTriangles, rows: [[[0, 1, 2, 3, 4, 5]], [[0, 1]]] };
      const file = read(makePly(encoding, [hexagonFan, faces]));
      expect(faceLists(file.soup)).toEqual([[0, 1, 2, 3, 4, 5], [0, 1]]);
    });
  }

  it("takes the face list named 'vertex_index', or the only list", () => {
    for (const name of ['vertex_index', 'corners']) {
      const faces = { ...twoTriangles, props: [{ name, type: 'int', count: 'uchar' }] };
      expect(read(makePly('ascii', [square, faces])).counts).toEqual({ vertices: 4, faces: 2 });
    }
  });
});

describe('PLY ascii rows, read a batch at a time', () => {
  /** Vertex i of a strip of quads along x, and its faces: triangles, then quads. */
  const stripVertices = (n: number): PlyElementSpec => ({
    name: 'vertex',
    props: xyz,
    rows: Array.from({ length: 2 * n }, (_, i) => [i >> 1, i & 1, i / 8]),
  });
  const stripFaces = (n: number): Array<Array<number | number[]>> =>
    Array.from({ length: n - 1 }, (_, i) => [i % 3 === 0 ? [2 * i, 2 * i + 2, 2 * i + 1] : [2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1]]);

  it('names the line and column of a bad index thousands of rows in, as row by row', () => {
    const faces = stripFaces(3000);
    faces[2500] = [[5000, 5002, 6000]];
    const error = parseError(() => read(makePly('ascii', [stripVertices(3000), { ...twoTriangles, rows: faces }])));
    // 9 header lines, 6000 vertex rows, then face 2500; the 6000 after '3 5000 5002 '
    expect(error.message).toBe(`ply: line ${9 + 6000 + 2501}, column 13: face 2500: vertex index 6000 is out of range 0..5999`);
  });

  it('reads rows the fast lane leaves (long numbers, blank lines, tabs, CRLF, no last line feed) as the rest', () => {
    const vertices = stripVertices(2500);
    const faces = stripFaces(2500);
    const expected = read(makePly('ascii', [vertices, { ...twoTriangles, rows: faces }])).soup;
    const lines = new TextDecoder().decode(makePly('ascii', [vertices, { ...twoTriangles, rows: faces }])).split('\n');
    const body = 9; // the first data line
    lines[body + 3] = '1.00000000000000000000 1 0.375'; // vertex 3, with more digits than the fast lane takes
    lines[body + 2100] = `\t${lines[body + 2100]}\r`;
    lines[body + 4000] = `\n\n${lines[body + 4000]}`;
    lines[body + 5000 + 1700] = `${lines[body + 5000 + 1700]}  \r`;
    const file = read(lines.join('\n').replace(/\n$/, ''));
    expectSameSoup(file.soup, expected);
    expect(file.soup.faceStarts.length - 1).toBe(2499);
  });

  it('reads a face element that also holds a scalar, row by row', () => {
    const faces: PlyElementSpec = {
      name: 'face',
      props: [twoTriangles.props[0], { name: 'flags', type: 'uchar' }],
      rows: [
        [[0, 1, 2], 7],
        [[0, 2, 3], 9],
      ],
    };
    const file = read(makePly('ascii', [square, faces]));
    expect(faceLists(file.soup)).toEqual([
      [0, 1, 2],
      [0, 2, 3],
    ]);
    expect(Array.from(file.soup.faceAttributes?.find((a) => a.name === 'flags')?.data ?? [])).toEqual([7, 9]);
  });
});

describe('PLY text, the fast lane against token by token', () => {
  const SEED = 20261125;
  const wellFormed = fc.oneof(
    fc.integer({ min: -9, max: 9 }).map(String),
    fc.double({ noNaN: true, noDefaultInfinity: true, min: -10, max: 10 }).map((x) => x.toPrecision(6)),
  );
  const number = fc.oneof({ weight: 8, arbitrary: wellFormed }, { weight: 1, arbitrary: fc.constantFrom('1e2', '0.30000000000000004', '+3', '.5', 'x', '1e999') });
  const index = fc.oneof({ weight: 8, arbitrary: fc.integer({ min: 0, max: 5 }).map(String) }, { weight: 1, arbitrary: fc.constantFrom('-1', '6', '2.0', '1e0') });
  const vertexRow = fc.oneof({ weight: 8, arbitrary: fc.array(number, { minLength: 3, maxLength: 3 }) }, { weight: 1, arbitrary: fc.array(number, { minLength: 2, maxLength: 4 }) });
  // the count: now and then one off, or not written as a whole number
  const faceRow = fc
    .tuple(fc.array(index, { minLength: 1, maxLength: 5 }), fc.integer({ min: -1, max: 1 }), fc.constantFrom('', '', '', '', '.0'))
    .map(([ids, off, decimals]) => [`${Math.max(0, ids.length + off)}${decimals}`, ...ids]);
  const space = fc.constantFrom(' ', '  ', '\t', ' \r');
  const file = fc.tuple(
    fc.array(vertexRow, { minLength: 6, maxLength: 6 }),
    fc.array(faceRow, { maxLength: 6 }),
    fc.array(space, { minLength: 12, maxLength: 12 }),
    fc.integer({ min: -1, max: 11 }),
  );

  /**
   * An ascii PLY of these rows. `padded` puts a property first in each element (an empty list
   * before a vertex's x y z, a scalar before a face's list), which sends every row token by token.
   */
  const ply = ([vertices, faces, spaces, blank]: [string[][], string[][], string[], number], padded: boolean) => {
    const pad = (rows: string[][]) => (padded ? rows.map((r) => ['0', ...r]) : rows);
    const rows = [...pad(vertices), ...pad(faces)].map((r, i) => r.join(spaces[i % 12]));
    if (blank >= 0 && blank < rows.length) rows.splice(blank, 0, '');
    const header = [
      'ply',
      'format ascii 1.0',
      'element vertex 6',
      ...(padded ? ['property list uchar int pad'] : []),
      ...['x', 'y', 'z'].map((name) => `property float ${name}`),
      `element face ${faces.length}`,
      ...(padded ? ['property uchar pad'] : []),
      'property list uchar int vertex_indices',
      'end_header',
    ];
    return `${[...header, ...rows].join('\n')}\n`;
  };

  /** What a read gives (positions and faces), or which line of the data its error is on. */
  const outcome = (source: string) => {
    try {
      const { soup } = read(source);
      return { positions: Array.from(soup.positions), faces: faceLists(soup) };
    } catch (error) {
      if (!(error instanceof ParseError)) throw error;
      return { dataLine: error.location.line! - source.split('\n').indexOf('end_header') - 1 };
    }
  };

  it(`reads every row as token by token reading does (seed ${SEED})`, () => {
    fc.assert(
      fc.property(file, (rows) => {
        expect(outcome(ply(rows, false))).toEqual(outcome(ply(rows, true)));
      }),
      { seed: SEED, numRuns: 3000 },
    );
  });
});

describe('PLY binary faces, runs of triangles and quads against row by row', () => {
  const SEED = 20261126;
  const VERTICES = 6;
  const index = fc.oneof(
    { weight: 12, arbitrary: fc.integer({ min: 0, max: VERTICES - 1 }) },
    { weight: 1, arbitrary: fc.constantFrom(-1, VERTICES, 0x7fffffff, -0x80000000) },
  );
  // mostly triangles and quads, in runs, with now and then another length in between
  const face = fc.oneof(
    { weight: 6, arbitrary: fc.array(index, { minLength: 3, maxLength: 3 }) },
    { weight: 6, arbitrary: fc.array(index, { minLength: 4, maxLength: 4 }) },
    { weight: 1, arbitrary: fc.array(index, { minLength: 0, maxLength: 7 }) },
  );
  const file = fc.record({
    faces: fc.array(face, { maxLength: 40 }),
    encoding: fc.constantFrom('binary_little_endian', 'binary_big_endian' as const),
    type: fc.constantFrom('int', 'uint'),
  });

  /** Cells of six vertices; `padded` puts a scalar after each face's list, which sends every row through the general loop. */
  const ply = ({ faces, encoding, type }: { faces: number[][]; encoding: PlyEncoding; type: string }, padded: boolean) =>
    makePly(encoding, [
      { ...square, rows: Array.from({ length: VERTICES }, (_, i) => [i, i % 2, 0]) },
      {
        name: 'face',
        props: [{ name: 'vertex_indices', type, count: 'uchar' }, ...(padded ? [{ name: 'flag', type: 'uchar' }] : [])],
        // a uint column holds what an int one does, bit for bit (-1 as 0xffffffff)
        rows: faces.map((ids) => [type === 'uint' ? ids.map((i) => i >>> 0) : ids, ...(padded ? [7] : [])]),
      },
    ]);

  /** The faces read, or the error's reason. */
  const outcome = (bytes: Uint8Array) => {
    try {
      return { faces: faceLists(read(bytes).soup) };
    } catch (error) {
      if (!(error instanceof ParseError)) throw error;
      return { reason: error.reason };
    }
  };

  it(`reads every face, or fails at the same face for the same reason, as the row by row loop (seed ${SEED})`, () => {
    fc.assert(
      fc.property(file, (spec) => {
        expect(outcome(ply(spec, false))).toEqual(outcome(ply(spec, true)));
      }),
      { seed: SEED, numRuns: 2000 },
    );
  });

  it('reads 70,000 faces, triangles then quads then both by turns, as row by row (progress and growth)', () => {
    const faces = Array.from({ length: 70000 }, (_, f) => {
      const quad = f >= 30000 && (f < 50000 || f % 3 === 0);
      return quad ? [f % 6, (f + 1) % 6, (f + 2) % 6, (f + 3) % 6] : [f % 6, (f + 2) % 6, (f + 4) % 6];
    });
    for (const encoding of ['binary_little_endian', 'binary_big_endian'] as const) {
      const fractions: number[] = [];
      const soup = readMesh(ply({ faces, encoding, type: 'int' }, false), { onProgress: (x) => fractions.push(x) }).soup;
      expect(faceLists(soup)).toEqual(faceLists(read(ply({ faces, encoding, type: 'int' }, true)).soup));
      expect(soup.faceStarts[70000]).toBe(30000 * 3 + 20000 * 4 + 6667 * 4 + 13333 * 3);
      expect(fractions.length).toBeGreaterThan(3);
    }
    // the file cut inside a run of quads: the row it ends in, and where that row starts
    const bytes = ply({ faces, encoding: 'binary_little_endian', type: 'int' }, false);
    const rowStart = new TextDecoder().decode(bytes.subarray(0, 400)).indexOf('end_header\n') + 11 + 12 * 6 + 13 * 30000 + 17 * 10000;
    const cut = parseError(() => read(bytes.subarray(0, rowStart + 5)));
    expect(cut.reason).toBe("the file ends inside row 40000 of 70000 of element 'face', whose list 'vertex_indices' announces 4 items");
    expect(cut.location).toEqual({ byteOffset: rowStart });
  });
});

describe('PLY elements and properties the reader does not use', () => {
  const edge: PlyElementSpec = {
    name: 'edge',
    props: [
      { name: 'vertex1', type: 'int' },
      { name: 'vertex2', type: 'int' },
      { name: 'path', type: 'double', count: 'ushort' },
    ],
    rows: [
      [0, 1, [0.5, 0.25, 0.125]],
      [1, 2, []],
    ],
  };
  const facesWithExtras: PlyElementSpec = {
    name: 'face',
    props: [
      { name: 'flags', type: 'short', count: 'uint' },
      { name: 'vertex_indices', type: 'int', count: 'uchar' },
      { name: 'quality', type: 'double' },
    ],
    rows: [
      [[7, 8], [0, 1, 2], 0.5],
      [[], [0, 2, 3], 0.75],
    ],
  };
  const verticesWithList: PlyElementSpec = {
    name: 'vertex',
    props: [{ name: 'neighbours', type: 'int', count: 'uchar' }, ...xyz],
    rows: square.rows.map((row, i) => [[i, i + 1], ...row]),
  };
  for (const encoding of plyEncodings) {
    it(`steps over unknown elements and list properties in ${encoding}`, () => {
      const file = read(makePly(encoding, [verticesWithList, edge, facesWithExtras]));
      expect(Array.from(file.soup.positions)).toEqual(square.rows.flat());
      expect(faceLists(file.soup)).toEqual([
        [0, 1, 2],
        [0, 2, 3],
      ]);
      expect(Array.from(attribute(file.soup.faceAttributes, 'quality').data)).toEqual([0.5, 0.75]);
      expect(file.notes).toContain("skipped element 'edge' (2 rows)");
      expect(file.notes).toContain("skipped vertex list property 'neighbours'");
      expect(file.notes).toContain("skipped face list property 'flags'");
    });
  }
});

describe('PLY attributes', () => {
  it('reads normals, uchar colours with alpha and texture coordinates under the soup names', () => {
    const vertex: PlyElementSpec = {
      name: 'vertex',
      props: [
        ...xyz,
        ...['nx', 'ny', 'nz'].map((name) => ({ name, type: 'float' })),
        ...['red', 'green', 'blue', 'alpha'].map((name) => ({ name, type: 'uchar' })),
        ...['texture_u', 'texture_v'].map((name) => ({ name, type: 'float' })),
      ],
      rows: square.rows.map((p, i) => [...p, 0, 0, 1, 10 * i, 20, 30, 255, i / 4, 0.5]),
    };
    const { soup } = read(makePly('binary_little_endian', [vertex, twoTriangles]));
    const normal = attribute(soup.vertexAttributes, 'normal');
    expect([normal.itemSize, normal.data.constructor]).toEqual([3, Float32Array]);
    const color = attribute(soup.vertexAttributes, 'color');
    expect([color.itemSize, color.data.constructor]).toEqual([4, Uint8Array]);
    expect(Array.from(color.data.subarray(4, 8))).toEqual([10, 20, 30, 255]);
    expect(Array.from(attribute(soup.vertexAttributes, 'texcoord').data)).toEqual([0, 0.5, 0.25, 0.5, 0.5, 0.5, 0.75, 0.5]);
  });

  it('keeps float colours as float32, on faces too', () => {
    const faces: PlyElementSpec = {
      name: 'face',
      props: [twoTriangles.props[0], ...['red', 'green', 'blue'].map((name) => ({ name, type: 'float' }))],
      rows: [
        [[0, 1, 2], 1, 0.5, 0],
        [[0, 2, 3], 0, 0, 1],
      ],
    };
    const color = attribute(read(makePly('ascii', [square, faces])).soup.faceAttributes, 'color');
    expect([color.itemSize, color.data.constructor, Array.from(color.data)]).toEqual([3, Float32Array, [1, 0.5, 0, 0, 0, 1]]);
  });

  it('turns a per-face texcoord list into corner texture coordinates', () => {
    const faces: PlyElementSpec = {
      name: 'face',
      props: [twoTriangles.props[0], { name: 'texcoord', type: 'float', count: 'uchar' }],
      rows: [
        [[0, 1, 2], [0, 0, 1, 0, 1, 1]],
        [[0, 2, 3], [0, 0, 1, 1, 0, 1]],
      ],
    };
    for (const encoding of plyEncodings) {
      const { soup } = read(makePly(encoding, [square, faces]));
      expect(Array.from(attribute(soup.cornerAttributes, 'texcoord').data)).toEqual([0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1]);
      // the builder makes them halfedge attributes
      expect(buildMesh(soup).mesh.halfedgeAttributes.has('texcoord')).toBe(true);
    }
  });

  it('skips texture coordinates that are not two per corner, saying which face is off', () => {
    const faces: PlyElementSpec = {
      name: 'face',
      props: [twoTriangles.props[0], { name: 'texcoord', type: 'float', count: 'uchar' }],
      rows: [
        [[0, 1, 2], [0, 0, 1, 0, 1, 1]],
        [[0, 2, 3], [0, 0]],
      ],
    };
    const file = read(makePly('ascii', [square, faces]));
    expect(file.soup.cornerAttributes).toEqual([]);
    expect(file.notes.join('\n')).toMatch(/face 1 has 3 corners but 2 texture coordinates/);
  });
});

describe('PLY headers as real files write them', () => {
  it('reads CRLF line endings and header lines with trailing spaces', () => {
    const source =
      'ply\r\nformat ascii 1.0   \r\ncomment made on Windows \r\nelement vertex 3  \r\nproperty float x\r\nproperty float y\r\n' +
      'property float z \r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nend_header  \r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n';
    const file = read(source);
    expect(faceLists(file.soup)).toEqual([[0, 1, 2]]);
    expect(file.comments).toEqual(['made on Windows']);
  });

  it('does not take a binary body that starts with byte 0x0A for a second line ending', () => {
    // x of vertex 0 is a float whose first little-endian byte is 0x0A
    const x = new DataView(new Uint8Array([0x0a, 0, 0x80, 0x3f]).buffer).getFloat32(0, true);
    const bytes = makePly('binary_little_endian', [{ ...square, rows: [[x, 0, 0], ...square.rows.slice(1)] }, twoTriangles]);
    const file = read(bytes);
    expect(file.soup.positions[0]).toBe(x);
    expect(file.notes).toEqual([]);
  });

  it('keeps comment and obj_info lines, and a line without a keyword as a comment with a note', () => {
    const extra = ['comment first', 'obj_info scanned 2024', 'Created by Blender3D 247 - www.blender.org'];
    const bytes = makePly('ascii', [square, twoTriangles], extra);
    const file = read(bytes);
    expect(file.comments).toEqual(['first', 'obj_info scanned 2024', 'Created by Blender3D 247 - www.blender.org']);
    expect(file.notes[0]).toMatch(/header line 5 has no PLY keyword/);
  });

  it('loads vertices without faces as a point set, with a note', () => {
    for (const encoding of plyEncodings) {
      const file = read(makePly(encoding, [square]));
      expect(file.counts).toEqual({ vertices: 4, faces: 0 });
      expect(file.notes).toContain('no faces: loaded as a point set');
    }
  });
});

describe('PLY headers with many elements and properties', () => {
  it(
    'plans a header of 100000 properties in one pass, keeping each and naming only the first few in its note',
    () => {
      const n = 100_000;
      const props = [...xyz, ...Array.from({ length: n }, (_, i) => ({ name: `p${i}`, type: 'uchar' }))];
      const row = [1, 2, 3, ...Array.from({ length: n }, (_, i) => i % 251)];
      const file = read(makePly('binary_little_endian', [{ name: 'vertex', props, rows: [row] }]));
      expect(Array.from(file.soup.positions)).toEqual([1, 2, 3]);
      const kept = file.soup.vertexAttributes ?? [];
      expect(kept.length).toBe(n);
      expect([kept[0].name, kept[0].data[0], kept[n - 1].name, kept[n - 1].data[0]]).toEqual(['p0', 0, `p${n - 1}`, (n - 1) % 251]);
      expect(file.notes).toContain("kept vertex properties 'p0', 'p1', 'p2', 'p3', 'p4' and 99995 more as attributes");
    },
    20_000,
  );

  it(
    'writes and reads back 100000 scalar attributes, each under its own name',
    () => {
      const n = 100_000;
      const soup = tetrahedron();
      soup.vertexAttributes = Array.from({ length: n }, (_, i) => ({ name: `a${i}`, itemSize: 1, data: new Uint8Array([i % 7, 1, 2, 3]) }));
      for (const format of ['ply', 'ply-binary'] as const) {
        const back = read(writeSoup(soup, format)).soup;
        expectSameSoup(back, soup);
      }
    },
    30_000,
  );

  it('notes skipped elements, skipped lists, taken names and keywordless lines once each, naming the first few', () => {
    const many = Array.from({ length: 9 }, (_, i): PlyElementSpec => ({ name: `extra${i}`, props: [{ name: 'n', type: 'int' }], rows: [[i]] }));
    const lists = Array.from({ length: 7 }, (_, i) => ({ name: `list${i}`, type: 'int', count: 'uchar' }));
    const vertex = {
      name: 'vertex',
      props: [...xyz, ...lists, { name: 'q', type: 'int' }, { name: 'q', type: 'int' }, { name: 'color', type: 'int' }],
      rows: square.rows.map((row) => [...row, ...lists.map(() => [1, 2]), 5, 6, 7]),
    };
    const banner = Array.from({ length: 8 }, (_, i) => `Banner line ${i}`);
    const file = read(makePly('ascii', [vertex, ...many, twoTriangles], banner));
    expect(file.notes).toEqual([
      "header lines 3, 4, 5, 6, 7 and 3 more have no PLY keyword (the first: 'Banner line 0'): kept as comments",
      "skipped vertex properties 'q', 'color': the names are taken",
      "kept vertex property 'q' as an attribute",
      "skipped vertex list properties 'list0', 'list1', 'list2', 'list3', 'list4' and 2 more",
      "skipped elements 'extra0' (1 row), 'extra1' (1 row), 'extra2' (1 row), 'extra3' (1 row), 'extra4' (1 row) and 4 more",
    ]);
    expect(faceLists(file.soup)).toEqual(faceLists(read(makePly('ascii', [square, twoTriangles])).soup));
  });

  it('cuts a long element name short in its note', () => {
    const long = 'e'.repeat(100_000);
    const file = read(makePly('ascii', [square, { name: long, props: [{ name: 'n', type: 'int' }], rows: [[1]] }]));
    expect(file.notes).toContain(`skipped element '${'e'.repeat(40)}…' (1 row)`);
  });

  it('reads the first vertex and face elements and skips a repeat, whose rows do not count as vertices', () => {
    const moreVertices = { ...square, rows: [...square.rows, [5, 5, 5], [6, 6, 6]] };
    const otherFaces = { ...twoTriangles, rows: [[[4, 5, 0]]] };
    for (const encoding of plyEncodings) {
      const file = read(makePly(encoding, [square, moreVertices, twoTriangles, otherFaces]));
      expect(Array.from(file.soup.positions)).toEqual(square.rows.flat());
      expect(faceLists(file.soup)).toEqual([
        [0, 1, 2],
        [0, 2, 3],
      ]);
      expect(file.notes).toContain("skipped elements 'vertex' (6 rows), 'face' (1 row)");
      // a face of the first face element must index the first vertex element's rows
      const outside = { ...twoTriangles, rows: [[[0, 1, 4]]] };
      expect(parseError(() => read(makePly(encoding, [square, moreVertices, outside]))).reason).toMatch(
        /face 0: vertex index 4 is out of range 0..3/,
      );
    }
  });
});

describe('PLY triangle strips', () => {
  it('decodes strips with -1 restarts, alternating the winding and leaving out degenerate triangles', () => {
    const vertices: PlyElementSpec = { name: 'vertex', props: xyz, rows: Array.from({ length: 8 }, (_, i) => [i, i % 2, 0]) };
    const strips: PlyElementSpec = {
      name: 'tristrips',
      props: [{ name: 'vertex_indices', type: 'int', count: 'int' }],
      // strip 0 1 2 3 4; then 5 6 6 7 (two degenerate triangles from the repeated 6)
      rows: [[[0, 1, 2, 3, 4, -1, 5, 6, 6, 7]]],
    };
    for (const encoding of plyEncodings) {
      const file = read(makePly(encoding, [vertices, strips]));
      expect(faceLists(file.soup)).toEqual([
        [0, 1, 2],
        [2, 1, 3],
        [2, 3, 4],
      ]);
      expect(file.counts).toEqual({ vertices: 8, faces: 3 });
      expect(file.notes).toContain('decoded 2 triangle strips into 3 triangles (2 degenerate left out)');
    }
  });

  it('keeps the strip orientation consistent, so a strip builds without repairs', () => {
    const vertices: PlyElementSpec = { name: 'vertex', props: xyz, rows: Array.from({ length: 10 }, (_, i) => [i >> 1, i % 2, 0]) };
    const strips: PlyElementSpec = {
      name: 'tristrips',
      props: [{ name: 'vertex_indices', type: 'int', count: 'int' }],
      rows: [[[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]]],
    };
    const { report, mesh } = buildMesh(read(makePly('binary_big_endian', [vertices, strips])).soup);
    expect(report.repairs).toEqual([]);
    expect(validate(mesh)).toEqual([]);
  });
});

describe('malformed PLY', () => {
  it('names the header line of an unknown type', () => {
    const error = parseError(() => read('ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\nend_header\n1\n'));
    expect(error.location).toEqual({ line: 4, column: 10 });
    expect(error.message).toMatch(/unknown property type 'flaot'/);
  });

  it('refuses a property before any element, and a header without format or end_header', () => {
    expect(parseError(() => read('ply\nformat ascii 1.0\nproperty float x\nend_header\n')).location.line).toBe(3);
    expect(parseError(() => read('ply\nelement vertex 0\nend_header\n')).message).toMatch(/no 'format' line/);
    expect(parseError(() => read(xyzHeader(8))).message).toMatch(/ends before 'end_header'/);
  });

  it('says where ascii rows end early and which property is missing', () => {
    const error = parseError(() =>
      read(`${xyzHeader(3)}end_header\n0 0 0\n1 1\n2.0 2.0 2.0\n`),
    );
    expect(error.message).toBe("ply: line 9, column 4: row 1 of element 'vertex' ends before its property 'z'");
  });

  it('says how many rows an ascii file holds when it ends early', () => {
    const header = `${xyzHeader(3)}end_header\n`;
    // padded with spaces, so the rows that are there could hold the third one
    expect(parseError(() => read(`${header}1.000 2.000 3.000\n1.000 2.000 3.000\n`)).message).toBe(
      "ply: line 10, column 1: the file ends after 2 of 3 rows of element 'vertex'",
    );
    // without room for the missing rows, the header's count is refused at once
    expect(parseError(() => read(`${header}1 2 3\n`)).message).toBe(
      "ply: line 3: element 'vertex' announces 3 rows of 3 values, but the 6 bytes of data hold at most 1 of them",
    );
  });

  it('refuses a value that is not a number, naming it', () => {
    const error = parseError(() =>
      read(`${xyzHeader(1)}end_header\n0 abc 0\n`),
    );
    expect(error.message).toBe("ply: line 8, column 3: expected a number, found 'abc'");
  });

  it('refuses a position that is NaN or infinite where it stands: line and column in text, byte offset in binary', () => {
    const header = `${xyzHeader(2)}end_header\n`;
    expect(parseError(() => read(`${header}0 0 0\n1 nan 0\n`)).message).toBe(
      "ply: line 9, column 3: vertex 1's position (item 1) is NaN, not a number",
    );
    expect(parseError(() => read(`${header}0 0 0\n1 1e999 0\n`)).message).toMatch(
      /^ply: line 9, column 3: vertex 1's position \(item 1\) is infinity: a value written as infinite, or beyond the range of float32/,
    );
    const rows = [...square.rows.slice(0, 2), [0, Number.NaN, 0], [Infinity, 0, 0]];
    const bytes = makePly('binary_little_endian', [{ ...square, rows }]);
    // after the header: two rows of three float32, then the third row's x
    const y = bytes.length - 4 * 12 + 2 * 12 + 4;
    expect(parseError(() => read(bytes)).message).toBe(`ply: byte ${y}: vertex 2's position (item 1) is NaN, not a number`);
  });

  it('refuses NaN or infinity written for an integer property, which cannot hold it', () => {
    const header = `${xyzHeader(1)}property uchar red\nend_header\n`;
    expect(parseError(() => read(`${header}0 0 0 inf\n`)).message).toBe(
      "ply: line 9, column 7: row 0 of element 'vertex': property 'red' is uint8, which holds no NaN or infinity",
    );
  });

  it('names the face, the index and the place of an out-of-range vertex index', () => {
    const faces = { ...twoTriangles, rows: [[[0, 1, 2]], [[0, 2, 4]]] };
    const ascii = parseError(() => read(makePly('ascii', [square, faces])));
    expect(ascii.message).toBe('ply: line 15, column 7: face 1: vertex index 4 is out of range 0..3');
    const negative = { ...twoTriangles, rows: [[[0, 1, 2]], [[0, -1, 3]]] };
    for (const encoding of ['binary_little_endian', 'binary_big_endian'] as const) {
      const bytes = makePly(encoding, [square, negative]);
      const error = parseError(() => read(bytes));
      // header, 4 vertices of 12 bytes, face 0 (13 bytes), face 1's count and first index
      const headerBytes = new TextDecoder().decode(bytes).indexOf('end_header\n') + 11;
      expect(error.location).toEqual({ byteOffset: headerBytes + 48 + 13 + 1 + 4 });
      expect(error.reason).toBe('face 1: vertex index -1 is out of range 0..3');
    }
  });

  it('says where binary data ends early', () => {
    const bytes = makePly('binary_little_endian', [square, twoTriangles]);
    const cut = parseError(() => read(bytes.subarray(0, bytes.length - 5)));
    expect(cut.location.byteOffset).toBe(bytes.length - 13);
    expect(cut.reason).toMatch(/the file ends inside row 1 of 2 of element 'face', whose list 'vertex_indices' announces 3 items/);
    const vertices = parseError(() => read(bytes.subarray(0, bytes.length - 40)));
    expect(vertices.message).toBe(
      "ply: line 3: element 'vertex' announces 4 rows of at least 12 bytes, but the 34 bytes of data hold at most 2 of them",
    );
  });

  it('rejects a tiny file that claims 2^31 faces before allocating anything', () => {
    for (const encoding of plyEncodings) {
      const header = `${xyzHeader(3, encoding)}element face 2147483648\nproperty list uchar int vertex_indices\nend_header\n`;
      const bytes = text(header + '0 0 0 1 0 0 0 1 0 3 0 1 2 '.repeat(3));
      const start = performance.now();
      const error = parseError(() => read(bytes));
      expect(performance.now() - start).toBeLessThan(50);
      expect(error.location).toEqual({ line: 7 });
      expect(error.reason).toMatch(/element 'face' announces 2147483648 rows/);
    }
  });

  it('rejects an ascii list that claims more items than the file holds', () => {
    const source = `${xyzHeader(1)}element face 1\nproperty list uint int vertex_indices\nend_header\n0 0 0\n4000000000 0 0 0\n`;
    expect(parseError(() => read(source)).message).toMatch(
      /line 11, column 1: row 0 of element 'face': the list announces 4000000000 items/,
    );
  });

  it('refuses text where a row should have ended', () => {
    const error = parseError(() => read(`${xyzHeader(1)}end_header\n0 0 0 7\n`));
    expect(error.message).toBe(
      "ply: line 8, column 7: row 0 of element 'vertex' should end after its 3 properties, then found '7'",
    );
  });

  it('reads a big binary file through an ArrayBuffer as well as a Uint8Array view into a larger buffer', () => {
    const bytes = makePly('binary_big_endian', [square, twoTriangles]);
    const padded = new Uint8Array(bytes.length + 10);
    padded.set(bytes, 5);
    const view = padded.subarray(5, 5 + bytes.length);
    expect(faceLists(readMesh(view).soup)).toEqual(faceLists(readMesh(bytes.slice().buffer).soup));
  });
});
