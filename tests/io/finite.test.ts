/**
 * NaN and infinity: refused in every format when read (naming the element and the attribute), and
 * never written, so that whatever the library reads it writes, and whatever it writes it reads back.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, cube, InvalidInputError, meshToSoup, writeMesh, writeSoup } from '../../src/index.js';
import { makePly, parseError, read, text } from './helpers.js';

/** A binary STL of one triangle whose first corner's x is `x`. */
function stlWith(x: number): Uint8Array {
  const bytes = new Uint8Array(84 + 50);
  const view = new DataView(bytes.buffer);
  view.setUint32(80, 1, true);
  [x, 0, 0, 1, 0, 0, 0, 1, 0].forEach((value, k) => view.setFloat32(84 + 12 + 4 * k, value, true));
  return bytes;
}

describe('values that are not finite', () => {
  it('are refused in every format, naming the element and the attribute', () => {
    const props = ['x', 'y', 'z'].map((name) => ({ name, type: 'float' }));
    const square = { name: 'vertex', props, rows: [[0, 0, 0], [1, 0, 0], [0, 1, 0]] };
    const cases: Array<[string, () => unknown, string]> = [
      ['binary PLY NaN', () => read(makePly('binary_big_endian', [{ ...square, rows: [[0, 0, 0], [1, Number.NaN, 0], [0, 1, 0]] }])), "ply: vertex 1's position (item 1) is NaN, not a number"],
      ['ascii PLY float beyond float32', () => read(makePly('ascii', [{ ...square, rows: [[0, 0, 0], [1, 0, 0], [0, 1, 5e38]] }])), "ply: vertex 2's position (item 2) is infinity: a value written as infinite, or beyond the range of float32, where it is kept"],
      ['OBJ normal beyond float32', () => read(text('v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 5e38 0 0\nf 1//1 2//1 3//1\n'), 'a.obj'), "obj: face corner 0's normal (item 0) is infinity: a value written as infinite, or beyond the range of float32, where it is kept"],
      ['binary STL minus infinity', () => read(stlWith(-Infinity), 'a.stl'), "stl: vertex 0's position (item 0) is minus infinity: a value written as infinite, or beyond the range of float32, where it is kept"],
    ];
    for (const [name, readIt, message] of cases) expect(parseError(readIt).message, name).toBe(message);
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
