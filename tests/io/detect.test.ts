import { describe, expect, it } from 'vitest';
import { ParseError, uvSphere } from '../../src/index.js';
import { detectFormat, formatFromFileName, readMesh, writeFormatFromFileName, writeSoup } from '../../src/core/io/index.js';
import { parseError, text } from './helpers.js';

describe('detectFormat', () => {
  it('goes by the content first, whatever the name says', () => {
    expect(detectFormat(text('ply\nformat ascii 1.0\nend_header\n'), 'model.obj')).toBe('ply');
    expect(detectFormat(text('ply\r\nformat ascii 1.0\r\n'))).toBe('ply');
    expect(detectFormat(text('# a comment\n\nCOFF\n3 1 0\n'), 'model.ply')).toBe('off');
    expect(detectFormat(text('OFF28048 35408 0\n'))).toBe('off');
    expect(detectFormat(text('appearance {\n}\nSTOFF\n'))).toBe('off');
    expect(detectFormat(text('solid x\n facet normal 0 0 1\n'))).toBe('stl');
    expect(detectFormat(text('# exported\nmtllib a.mtl\nv 0 0 0\n'))).toBe('obj');
    expect(detectFormat(text('v 0 0 0\nf 1 1 1\n'), 'strange.off')).toBe('obj');
  });

  it('takes a binary STL by its size rule, even when its header starts with "solid"', () => {
    const bytes = new Uint8Array(84 + 50);
    bytes.set(text('solid but binary'));
    bytes[80] = 1;
    expect(detectFormat(bytes)).toBe('stl');
  });

  it('knows glTF by the GLB magic or by JSON with an asset, and by the names .glb and .gltf', () => {
    expect(detectFormat(Uint8Array.of(0x67, 0x6c, 0x54, 0x46, 2, 0, 0, 0), 'model.bin')).toBe('gltf');
    expect(detectFormat(text('\n  { "asset": { "version": "2.0" }, "meshes": [] }'))).toBe('gltf');
    expect(detectFormat(text('{ "name": "not a model" }'), 'x.gltf')).toBe('gltf');
    expect(() => detectFormat(text('{ "name": "not a model" }'), 'x.json')).toThrow(ParseError);
    expect([formatFromFileName('a.GLB'), formatFromFileName('b.gltf')]).toEqual(['gltf', 'gltf']);
  });

  it('asks the file name only when the content does not say', () => {
    expect(detectFormat(text('3 1 0\n0 0 0\n'), 'TRI.OFF')).toBe('off');
    expect(detectFormat(text('\x00\x01garbage'), 'part.stl')).toBe('stl');
    expect(formatFromFileName('cube.noff')).toBe('off');
    expect(formatFromFileName('cube.txt')).toBeUndefined();
  });

  it('refuses an empty file and an unknown one, naming the supported formats', () => {
    expect(parseError(() => detectFormat(new Uint8Array(0), 'a.ply')).message).toBe('ply: byte 0: the file is empty (0 bytes)');
    const unknown = parseError(() => detectFormat(text('<html>hello</html>'), 'page.html'));
    expect(unknown).toBeInstanceOf(ParseError);
    expect(unknown.message).toBe(
      "file: byte 0: unknown format of 'page.html'; it starts with '<html>hello</html>'. " +
        'Supported: PLY (.ply), OFF (.off), OBJ (.obj), STL (.stl), glTF (.glb, .gltf)',
    );
  });
});

describe('writeFormatFromFileName', () => {
  it('maps .ply to ascii PLY, .off and .obj to themselves, anything else to undefined', () => {
    const names = ['a.ply', 'b.OFF', 'c.obj', 'd.stl', 'e'];
    expect(names.map(writeFormatFromFileName)).toEqual(['ply', 'off', 'obj', undefined, undefined]);
  });
});

describe('readMesh', () => {
  it('reports progress from 0 to 1, never going back', () => {
    for (const format of ['ply', 'ply-binary', 'off', 'obj'] as const) {
      const fractions: number[] = [];
      readMesh(writeSoup(uvSphere(300, 300), format), { onProgress: (f) => fractions.push(f) });
      expect(fractions[0]).toBe(0);
      expect(fractions.at(-1)).toBe(1);
      expect(fractions.length).toBeGreaterThan(2);
      expect(fractions.every((f, i) => i === 0 || f >= fractions[i - 1])).toBe(true);
    }
  });
});
