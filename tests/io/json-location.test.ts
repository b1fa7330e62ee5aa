import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { jsonLocation, pathText, syntaxErrorLocation, syntaxErrorOffset } from '../../src/core/io/json-location.js';
import { text } from './helpers.js';

const SEED = 20261126;

/** A JSON text as a `.gltf` or halfedge JSON file holds it. */
const file = (source: string) => ({ bytes: text(source), start: 0, end: text(source).length, byteOffsets: false });

describe('places in a JSON text', () => {
  it('finds the value at a path, or the deepest value along it there is, the last of a repeated key', () => {
    const source = '{\n  "a": [1, {"b": 2}],\n  "c\\u0022": "x",\n  "a": [3, {"b":  4}]\n}';
    expect(JSON.parse(source).a[1].b).toBe(4);
    expect(jsonLocation(file(source), ['a', 1, 'b'])).toEqual({ line: 4, column: 19, path: 'a[1].b' });
    expect(jsonLocation(file(source), ['c"'])).toEqual({ line: 3, column: 14, path: '["c\\""]' });
    // past what there is: the deepest value there is
    expect(jsonLocation(file(source), ['a', 7, 'b'])).toEqual({ line: 4, column: 8, path: 'a[7].b' });
    expect(jsonLocation(file(source), [])).toEqual({ line: 1, column: 1, path: '' });
    // a .glb places by the byte offset in the file
    expect(jsonLocation({ ...file(`${'\0'.repeat(20)}{"a": 5}`), start: 20, byteOffsets: true }, ['a'])).toEqual({ byteOffset: 26, path: 'a' });
    // without the text, the path alone
    expect(jsonLocation(null, ['vertices', 3, 'position', 1])).toEqual({ path: 'vertices[3].position[1]' });
    expect(pathText(['attributes', 'a b', '__proto__'])).toBe('attributes["a b"].__proto__');
  });

  it('finds where a text breaks the grammar, a line and column in it', () => {
    expect(syntaxErrorLocation(file('{\n  "format": "halfedge-json",\n  "version": 1,,\n}'))).toEqual({ line: 3, column: 16 });
    expect(syntaxErrorLocation(file('[1, 2'))).toEqual({ line: 1, column: 6 });
    // nested far deeper than a recursive walk could go
    const deep = `${'['.repeat(1e6)}1${']'.repeat(1e6 - 1)}`;
    expect(syntaxErrorOffset(text(deep))).toBe(deep.length);
  });

  it(`breaks where JSON.parse does: it refuses the same texts, at the position it names when it names one (seed ${SEED})`, () => {
    const ascii = fc.jsonValue({ maxDepth: 3 }).map((value) => JSON.stringify(value, null, 1).replace(/[^\x20-\x7e\n]/g, 'x'));
    const edit = fc.tuple(ascii, fc.nat(), fc.constantFrom('', ',', ':', '"', '\\', '}', ']', '{', '[', '-', '.', 'e', '0', 't', '\n', '\u0001'), fc.nat(3));
    fc.assert(
      fc.property(edit, ([source, at, insert, cut]) => {
        const position = at % (source.length + 1);
        const edited = source.slice(0, position) + insert + source.slice(position + cut);
        let named: number | null = null;
        let valid = true;
        try {
          JSON.parse(edited);
        } catch (error) {
          valid = false;
          const match = /at position (\d+)/.exec((error as Error).message);
          if (match) named = Number(match[1]);
        }
        const offset = syntaxErrorOffset(text(edited));
        expect(offset < 0).toBe(valid);
        if (named !== null) expect(offset).toBe(named);
      }),
      { seed: SEED, numRuns: 20000 },
    );
  });
});
