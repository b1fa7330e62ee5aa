/**
 * Places in a JSON text, for the errors of the readers of JSON documents (halfedge JSON, glTF).
 * `JSON.parse` gives the values but not where they were written, and names the place of a
 * syntax error in only some of its messages (differently in each engine); so a reader that
 * refuses a value asks here for its place, by the path to it (`accessors[2].count`), and a text
 * that is not JSON is walked here to where it breaks the grammar.
 *
 * Both walks go over the bytes once, without recursion (a document nested a million deep does
 * not overflow the stack), and run only for an error.
 */
import type { FileLocation } from '../errors.js';
import { decodeText } from './text.js';

/** Keys and indices from the top of a document down to one value. */
export type JsonPath = ReadonlyArray<string | number>;

/**
 * A JSON document's text and where it sits in its file: a `.glb` holds it in a chunk, and is
 * placed by byte offset; a text file (`.gltf`, halfedge JSON) by line and column.
 */
export interface JsonText {
  bytes: Uint8Array;
  start: number;
  end: number;
  byteOffsets: boolean;
}

const TAB = 0x09;
const LF = 0x0a;
const CR = 0x0d;
const SPACE = 0x20;
const QUOTE = 0x22;
const PLUS = 0x2b;
const COMMA = 0x2c;
const MINUS = 0x2d;
const DOT = 0x2e;
const ZERO = 0x30;
const NINE = 0x39;
const COLON = 0x3a;
const LEFT_BRACKET = 0x5b;
const BACKSLASH = 0x5c;
const RIGHT_BRACKET = 0x5d;
const LEFT_BRACE = 0x7b;
const RIGHT_BRACE = 0x7d;

/** `accessors[2].count`; a key that is not a plain name is quoted (`attributes["a b"]`); '' for the top. */
export function pathText(path: JsonPath): string {
  let text = '';
  for (const key of path) {
    if (typeof key === 'number') text += `[${key}]`;
    else if (/^[A-Za-z_$][\w$]*$/.test(key)) text += text ? `.${key}` : key;
    else text += `[${JSON.stringify(key.length > 40 ? `${key.slice(0, 40)}…` : key)}]`;
  }
  return text;
}

/** Where the value at `path` is: its path, and its place in `text` when the text is at hand. */
export function jsonLocation(text: JsonText | null, path: JsonPath): FileLocation {
  if (text === null) return { path: pathText(path) };
  return { ...place(text, valueOffset(textBytes(text), path)), path: pathText(path) };
}

/** Where `text`, which `JSON.parse` refused, first breaks JSON's grammar. */
export function syntaxErrorLocation(text: JsonText): FileLocation {
  // (the walk finds a fault wherever JSON.parse does; should it not, the document's start is named)
  return place(text, Math.max(0, syntaxErrorOffset(textBytes(text))));
}

/** The bytes of the text alone: offsets below count from its start, and nothing after it is read. */
function textBytes({ bytes, start, end }: JsonText): Uint8Array {
  return bytes.subarray(start, end);
}

/** Offset `offset` of the text as a place in its file. */
function place(text: JsonText, offset: number): FileLocation {
  if (text.byteOffsets) return { byteOffset: text.start + offset };
  const { bytes, start } = text;
  let line = 1;
  let lineStart = 0;
  for (let i = 0; i < offset; i++) {
    if (bytes[start + i] === LF) {
      line++;
      lineStart = i + 1;
    }
  }
  return { line, column: offset - lineStart + 1 };
}

/**
 * The offset of the value at `path`, or of the deepest value along it that the text has (a key
 * that is not there names its object). Of a key written twice, the last counts, as for
 * `JSON.parse`. The text is one `JSON.parse` took.
 */
function valueOffset(bytes: Uint8Array, path: JsonPath): number {
  let at = skipSpace(bytes, 0);
  for (const key of path) {
    const isArray = bytes[at] === LEFT_BRACKET && typeof key === 'number';
    if (!isArray && !(bytes[at] === LEFT_BRACE && typeof key === 'string')) return at;
    let found = -1;
    let i = skipSpace(bytes, at + 1);
    for (let index = 0; i < bytes.length && bytes[i] !== RIGHT_BRACKET && bytes[i] !== RIGHT_BRACE; index++) {
      let matches = index === key;
      if (!isArray) {
        const keyEnd = skipValue(bytes, i);
        matches = keyText(bytes.subarray(i, keyEnd)) === key;
        // past the colon, to the value
        i = skipSpace(bytes, skipSpace(bytes, keyEnd) + 1);
      }
      if (matches) found = i;
      if (matches && isArray) break;
      i = skipSpace(bytes, skipValue(bytes, i));
      if (bytes[i] !== COMMA) break;
      i = skipSpace(bytes, i + 1);
    }
    if (found < 0) return at;
    at = found;
  }
  return at;
}

/** A key as `JSON.parse` reads it, escapes and all. */
function keyText(quoted: Uint8Array): string | null {
  try {
    return JSON.parse(decodeText(quoted)) as string;
  } catch {
    return null;
  }
}

function skipSpace(bytes: Uint8Array, i: number): number {
  while (bytes[i] === SPACE || bytes[i] === LF || bytes[i] === CR || bytes[i] === TAB) i++;
  return i;
}

/** Where the value at `i` ends (in a text `JSON.parse` took). */
function skipValue(bytes: Uint8Array, i: number): number {
  const c = bytes[i];
  if (c === QUOTE) {
    const after = stringEnd(bytes, i);
    return after < 0 ? bytes.length : after;
  }
  if (c !== LEFT_BRACE && c !== LEFT_BRACKET) {
    while (i < bytes.length && !isValueEnd(bytes[i])) i++;
    return i;
  }
  for (let depth = 0; i < bytes.length; i++) {
    const b = bytes[i];
    if (b === QUOTE) {
      const after = stringEnd(bytes, i);
      if (after < 0) return bytes.length;
      i = after - 1;
    } else if (b === LEFT_BRACE || b === LEFT_BRACKET) depth++;
    else if ((b === RIGHT_BRACE || b === RIGHT_BRACKET) && --depth === 0) return i + 1;
  }
  return bytes.length;
}

/** Whether byte `c` ends a number or a literal. */
function isValueEnd(c: number): boolean {
  return c === COMMA || c === RIGHT_BRACKET || c === RIGHT_BRACE || c === SPACE || c === LF || c === CR || c === TAB;
}

/** The bytes that may follow a backslash on their own: " \ / b f n r t. */
const SIMPLE_ESCAPES = new Set(Array.from('"\\/bfnrt', (c) => c.charCodeAt(0)));

/**
 * Where the string that starts at `i` (its opening quote) ends, after its closing quote; or, when
 * it breaks the grammar, ~offset of the fault (a negative number): an unescaped control byte, a
 * bad escape, or the end of the text.
 */
function stringEnd(bytes: Uint8Array, i: number): number {
  for (i++; i < bytes.length; i++) {
    const c = bytes[i];
    if (c === QUOTE) return i + 1;
    if (c < SPACE) return ~i;
    if (c !== BACKSLASH) continue;
    const escape = bytes[++i];
    if (escape === 0x75) {
      // \uXXXX
      for (let k = 1; k <= 4; k++) if (!isHexDigit(bytes[i + k])) return ~(i + k);
      i += 4;
    } else if (!SIMPLE_ESCAPES.has(escape)) {
      return ~i;
    }
  }
  return ~bytes.length;
}

function isHexDigit(c: number | undefined): boolean {
  if (c === undefined) return false;
  const lower = c | 0x20;
  return (c >= ZERO && c <= NINE) || (lower >= 0x61 && lower <= 0x66);
}

/** Where the number at `i` ends, or ~offset of its fault (`-`, `1.`, `1e` with no digit after). */
function numberEnd(bytes: Uint8Array, i: number): number {
  const digitsEnd = (j: number): number => {
    while (bytes[j] >= ZERO && bytes[j] <= NINE) j++;
    return j;
  };
  if (bytes[i] === MINUS) i++;
  if (bytes[i] === ZERO) i++;
  else if (bytes[i] > ZERO && bytes[i] <= NINE) i = digitsEnd(i);
  else return ~i;
  if (bytes[i] === DOT) {
    const after = digitsEnd(i + 1);
    if (after === i + 1) return ~after;
    i = after;
  }
  if (bytes[i] === 0x65 || bytes[i] === 0x45) {
    i++;
    if (bytes[i] === PLUS || bytes[i] === MINUS) i++;
    const after = digitsEnd(i);
    if (after === i) return ~after;
    i = after;
  }
  return i;
}

/** Where `true`, `false` or `null` at `i` ends, or ~offset of the first byte that differs. */
function literalEnd(bytes: Uint8Array, i: number): number {
  const word = bytes[i] === 0x74 ? 'true' : bytes[i] === 0x66 ? 'false' : 'null';
  for (let k = 0; k < word.length; k++) if (bytes[i + k] !== word.charCodeAt(k)) return ~(i + k);
  return i + word.length;
}

/**
 * The offset of the first byte of `bytes` where JSON's grammar breaks (its length when the text
 * ends too early), or -1 when it is JSON. Nesting is kept as a list of the closing brackets
 * awaited, not by recursion.
 */
export function syntaxErrorOffset(bytes: Uint8Array): number {
  const closing: number[] = [];
  let i = 0;
  let valueNext = true;
  for (;;) {
    i = skipSpace(bytes, i);
    if (valueNext) {
      const c = bytes[i];
      if (c === LEFT_BRACE || c === LEFT_BRACKET) {
        const close = c === LEFT_BRACE ? RIGHT_BRACE : RIGHT_BRACKET;
        i = skipSpace(bytes, i + 1);
        if (bytes[i] === close) {
          i++;
          valueNext = false;
        } else {
          closing.push(close);
          if (close === RIGHT_BRACE) i = memberKeyEnd(bytes, i);
          if (i < 0) return ~i;
        }
        continue;
      }
      if (i >= bytes.length) return i;
      const number = c === MINUS || (c >= ZERO && c <= NINE);
      i = c === QUOTE ? stringEnd(bytes, i) : number ? numberEnd(bytes, i) : literalEnd(bytes, i);
      if (i < 0) return ~i;
      valueNext = false;
      continue;
    }
    // after a value: the end of the text, a comma, or the bracket that closes its container
    const close = closing[closing.length - 1];
    if (close === undefined) return i < bytes.length ? i : -1;
    if (bytes[i] === close) {
      closing.pop();
      i++;
    } else if (bytes[i] === COMMA) {
      i = skipSpace(bytes, i + 1);
      if (close === RIGHT_BRACE) i = memberKeyEnd(bytes, i);
      if (i < 0) return ~i;
      valueNext = true;
    } else {
      return i;
    }
  }
}

/** Where a member's key and its colon at `i` end, or ~offset of the fault. */
function memberKeyEnd(bytes: Uint8Array, i: number): number {
  if (bytes[i] !== QUOTE) return ~i;
  const after = stringEnd(bytes, i);
  if (after < 0) return after;
  i = skipSpace(bytes, after);
  return bytes[i] === COLON ? i + 1 : ~i;
}
