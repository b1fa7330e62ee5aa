/**
 * One tokenizer for every text format (PLY ascii, OFF, OBJ, ascii STL), working on the file's
 * bytes: no decoding of the whole file, no splitting into lines or strings.
 *
 * Text mesh files are lines of tokens separated by spaces or tabs (any byte up to the space
 * character counts as one, so a stray carriage return or NUL does no harm). The scanner keeps a
 * cursor (`pos`), the current line number and where that line starts, so every error can say
 * "line 12, column 5". Numbers are read straight from the digits: the mantissa is gathered as an
 * integer and scaled by one exact power of ten, which rounds correctly when the mantissa is below
 * 2^53 (every 15-digit number, most 16-digit ones) and the exponent at most 22 either way — the
 * usual case, "0.123456" or "-1.5e-3". Numbers of up to 19 digits scaled down by at most 10^22, as
 * a double's shortest round trip is written ("0.12345678901234567"), are rounded exactly with a
 * remainder in two doubles (`longNumberValue`). Anything else falls back to the engine's own parser
 * on that one token, so every value is read exactly. `nan`, `inf` and `infinity` (in any case, with
 * or without a sign: what C's printf and most languages write) are read as NaN and infinity, and a
 * number beyond a double's range as infinity: whether a value may be one is for the reader to say
 * (a position may not; an attribute's value is dropped with a note, see `finite.ts`).
 *
 * Most lines of most files are nothing but numbers: `plainLines` reads those a batch of lines at a
 * time, in a loop that builds no string and calls nothing per token, and stops at the first other
 * line, which the reader then takes token by token (and which, if it is wrong, says how).
 *
 * Formats differ only in what counts as a comment: OFF and OBJ skip from `#` to the end of the
 * line, PLY has no comments in its data.
 *
 * @example
 *   const scanner = new TextScanner(bytes, 'off', { hashComments: true });
 *   scanner.skipBlankLines();
 *   const x = scanner.number();
 */
import { ParseError } from '../errors.js';
import { type Progress, PROGRESS_ROWS } from './mesh-file.js';

const TAB = 9;
const LF = 10;
const SPACE = 32;
const HASH = 35;
const PLUS = 43;
const MINUS = 45;
const DOT = 46;
const SLASH = 47;
const ZERO = 48;
const NINE = 57;
const UPPER_E = 69;
const LOWER_E = 101;

/** Largest integer below which every integer is an exact double (2^53). */
const EXACT_INTEGER_LIMIT = 9007199254740992;
/** Powers of ten that are exact doubles; scaling by one of them rounds correctly. */
const EXACT_POWERS_OF_TEN = Array.from({ length: 23 }, (_, k) => 10 ** k);

export interface ScannerOptions {
  /** `#` starts a comment that runs to the end of the line (OFF, OBJ). */
  hashComments?: boolean;
  /** Where to start reading (default 0). */
  start?: number;
  /** The number of the line that `start` is on (default 1). */
  line?: number;
  /** Receives the text of each `#` comment passed over. */
  comments?: string[];
}

/** Comments kept per file; a file with a comment on every line would otherwise keep millions. */
const MAX_COMMENTS = 1000;

/** The most numbers a line of the fast lane holds (see `TextScanner.plainLines`). */
const PLAIN_LINE_NUMBERS = 64;
/** Lines of the fast lane start with their first number. */
const NO_KEYWORD = -1;

/**
 * Stores the first rows of a batch of `lines` plain lines (the first being row `row`, `bytesLeft`
 * bytes of the file after them) for as long as each is what a row holds, as reading it token by
 * token would find it; returns how many it stored (see `TextScanner.readRows`).
 */
export type StoreRows = (batch: PlainLines, lines: number, row: number, bytesLeft: number) => number;

/** Lines of plain numbers read ahead by `TextScanner.plainLines`, in arrays kept for batch after batch. */
export class PlainLines {
  readonly values = new Float64Array(16384);
  /** 1 where the number was written as a whole number. */
  readonly integral = new Uint8Array(16384);
  /** Line r's numbers are `values[ends[r - 1] … ends[r])` (from 0 for line 0). */
  readonly ends = new Uint32Array(2048);
  /** Where line r starts (line 0: where the cursor was); one more, where the last line read ends. */
  readonly starts = new Uint32Array(2049);
  /** The number of line 0, and where it starts. */
  firstLine = 0;
  firstLineStart = 0;
}

export class TextScanner {
  readonly bytes: Uint8Array;
  readonly format: string;
  /** Byte offset of the cursor. */
  pos: number;
  /** 1-based number of the line the cursor is on. */
  line: number;
  /** Set by `number()`: true when the number had neither a decimal point nor an exponent. */
  integral = false;
  /** Comments passed over beyond the `MAX_COMMENTS` kept. */
  droppedComments = 0;
  private lineStart: number;
  private readonly hashComments: boolean;
  private readonly comments: string[] | null;

  constructor(bytes: Uint8Array, format: string, options: ScannerOptions = {}) {
    this.bytes = bytes;
    this.format = format;
    this.hashComments = options.hashComments ?? false;
    this.comments = options.comments ?? null;
    this.pos = options.start ?? 0;
    this.line = options.line ?? 1;
    this.lineStart = this.pos;
  }

  /** Skips spaces, tabs, carriage returns and (when enabled) a `#` comment; stops at a line feed. */
  skipSpaces(): void {
    const bytes = this.bytes;
    const end = bytes.length;
    let i = this.pos;
    while (i < end) {
      const c = bytes[i];
      if (c === LF) break;
      if (c <= SPACE) i++;
      else if (c === HASH && this.hashComments) {
        const start = i + 1;
        while (i < end && bytes[i] !== LF) i++;
        this.keepComment(start, i);
      } else break;
    }
    this.pos = i;
  }

  /** True when only spaces or a comment remain on this line (or the file has ended). */
  atLineEnd(): boolean {
    this.skipSpaces();
    return this.pos >= this.bytes.length || this.bytes[this.pos] === LF;
  }

  /** Moves past the end of this line, whatever is left on it. */
  nextLine(): void {
    const bytes = this.bytes;
    let i = this.pos;
    while (i < bytes.length && bytes[i] !== LF) i++;
    if (i < bytes.length) this.newLineAt(i);
    else this.pos = i;
  }

  /** Moves to the next token, across blank and comment-only lines; false at the end of the file. */
  skipBlankLines(): boolean {
    for (;;) {
      this.skipSpaces();
      if (this.pos >= this.bytes.length) return false;
      if (this.bytes[this.pos] !== LF) return true;
      this.newLineAt(this.pos);
    }
  }

  /**
   * Ends a line of data: only spaces or a comment may remain on it.
   * @throws ParseError naming `what` when more values follow (a function builds a message that
   *   names the row only then, not once per row).
   */
  endLine(what: string | (() => string)): void {
    if (!this.atLineEnd()) this.fail(`${typeof what === 'string' ? what : what()}, then found '${this.token()}'`);
    if (this.pos < this.bytes.length) this.newLineAt(this.pos);
  }

  /** The next token as a string (empty at the end of a line), without moving past it. */
  token(at = this.pos): string {
    return excerpt(this.bytes, at, tokenEnd(this.bytes, at));
  }

  /** Reads the next token as a word (a keyword, a name). Empty at the end of a line. */
  word(): string {
    this.skipSpaces();
    const start = this.pos;
    this.pos = tokenEnd(this.bytes, start);
    return decodeText(this.bytes, start, this.pos);
  }

  /**
   * Whether the next token is `keyword` (given in lower case ASCII letters), in any case; moves past
   * it when it is. Builds no string, for the keywords a format repeats on every line.
   */
  isWord(keyword: string): boolean {
    this.skipSpaces();
    const bytes = this.bytes;
    const start = this.pos;
    const end = start + keyword.length;
    if (end > bytes.length || (end < bytes.length && bytes[end] > SPACE)) return false;
    // setting bit 5 turns an ASCII capital into its small letter, and no other byte into a letter
    for (let k = 0; k < keyword.length; k++) if ((bytes[start + k] | 0x20) !== keyword.charCodeAt(k)) return false;
    this.pos = end;
    return true;
  }

  /** The rest of this line as text, trimmed, without moving to the next line. */
  restOfLine(): string {
    const bytes = this.bytes;
    const start = this.pos;
    let end = start;
    while (end < bytes.length && bytes[end] !== LF) end++;
    this.pos = end;
    return trimmedText(bytes, start, end);
  }

  /**
   * Reads a decimal number ("12", "-0.5", "1.5e-3", ".5"), or NaN or infinity written as a word
   * ("nan", "-inf"); a number beyond a double's range is infinite. Sets `integral` (false for
   * NaN and infinity).
   * @throws ParseError when the next token is not a number.
   */
  number(): number {
    this.skipSpaces();
    const start = this.pos;
    let end = scanNumber(this.bytes, start, this.hashComments);
    if (end >= 0 && Number.isNaN(scanned.value)) {
      // only a number beyond a double's range scans as NaN (see `engineValue`)
      scanned.value = this.bytes[start] === MINUS ? -Infinity : Infinity;
      scanned.integral = false;
    } else if (end < 0) {
      end = scanNonFiniteWord(this.bytes, start, this.hashComments);
      if (end < 0) this.notANumber(start);
    }
    this.pos = end;
    this.integral = scanned.integral;
    return scanned.value;
  }

  /**
   * The fast lane for lines of plain numbers, which most lines of most files are: reads up to
   * `maxLines` lines from the cursor on into `batch`, each line being up to `PLAIN_LINE_NUMBERS`
   * numbers separated by spaces, and returns how many lines it read. It stops before the first
   * other line (a comment, a word, a number beyond a double's range, too many numbers, no number at
   * all), which the caller then reads token by token, and which also says what is wrong with it,
   * and before a last line that no line feed ends. Either way a number gets the same value. With a
   * `keyword` (a byte: OBJ's `v` or `f`), each line must start with it and a space or tab, and the
   * numbers after it are read. The cursor moves to the start of the line after the last one read;
   * `backTo` moves it back to one.
   */
  plainLines(batch: PlainLines, maxLines: number, keyword = NO_KEYWORD): number {
    batch.firstLine = this.line;
    batch.firstLineStart = this.lineStart;
    const lines = scanPlainLines(this.bytes, this.pos, batch, maxLines, keyword);
    if (lines > 0) this.backTo(batch, lines);
    return lines;
  }

  /**
   * Reads the `rows` rows of one element, each on a line of its own (a row read by tokens may go
   * on over more). The fast lane reads a batch of plain lines at a time, of which `store` stores
   * what it can and says how many rows that was; the first row it leaves, `readRow` reads token by
   * token, which also says what is wrong with it. Without `store`, every row goes by tokens.
   * `endsEarly(row)` words the error when the file ends before row `row`; `progress` hears of
   * the reading every `PROGRESS_ROWS` rows or so.
   */
  readRows(rows: number, store: StoreRows | null, readRow: (row: number) => void, endsEarly: (row: number) => string, progress: Progress): void {
    const batch = new PlainLines();
    for (let row = 0, reportAt = 0; row < rows; ) {
      if (!this.skipBlankLines()) this.fail(endsEarly(row));
      if (row >= reportAt) {
        progress(this.pos / this.bytes.length);
        reportAt = row + PROGRESS_ROWS;
      }
      const lines = store === null ? 0 : this.plainLines(batch, rows - row);
      const r = lines === 0 ? 0 : store!(batch, lines, row, this.bytes.length - this.pos);
      row += r;
      if (r > 0 && r === lines) continue;
      if (r < lines) this.backTo(batch, r);
      readRow(row++);
    }
  }

  /** Moves the cursor back to the start of line `r` of the last `plainLines` batch. */
  backTo(batch: PlainLines, r: number): void {
    this.pos = batch.starts[r];
    this.line = batch.firstLine + r;
    this.lineStart = r === 0 ? batch.firstLineStart : batch.starts[r];
  }

  /**
   * Reads a whole number ("12", "-3"). With `slashEnds`, a `/` also ends it (OBJ's "7/2/5").
   * @throws ParseError when the next token is not a whole number.
   */
  integer(slashEnds = false): number {
    this.skipSpaces();
    const bytes = this.bytes;
    const start = this.pos;
    let i = start;
    let c = bytes[i];
    const negative = c === MINUS;
    if (negative || c === PLUS) c = bytes[++i];
    let value = 0;
    const digitsStart = i;
    while (c >= ZERO && c <= NINE) {
      value = value * 10 + (c - ZERO);
      c = bytes[++i];
    }
    if (i === digitsStart || !(isDelimiter(c, this.hashComments) || (slashEnds && c === SLASH))) {
      const token = this.token(start);
      this.fail(`expected a whole number, found ${token ? `'${token}'` : 'the end of the line'}`, start);
    }
    this.pos = i;
    return negative ? -value : value;
  }

  /** Where the cursor is, as a line and column (1-based). */
  location(at = this.pos): { line: number; column: number } {
    return { line: this.line, column: at - this.lineStart + 1 };
  }

  /** @throws ParseError at `at` (default: the cursor) on the current line. */
  fail(reason: string, at = this.pos): never {
    throw new ParseError(this.format, this.location(at), reason);
  }

  private keepComment(start: number, end: number): void {
    if (this.comments === null) return;
    if (this.comments.length === MAX_COMMENTS) {
      this.droppedComments++;
      return;
    }
    this.comments.push(trimmedText(this.bytes, start, end));
  }

  private notANumber(start: number): never {
    const token = this.token(start);
    if (!token) {
      this.fail(`expected a number, found the end of the ${start >= this.bytes.length ? 'file' : 'line'}`, start);
    }
    this.fail(`expected a number, found '${token}'`, start);
  }

  private newLineAt(lineFeed: number): void {
    this.pos = lineFeed + 1;
    this.line++;
    this.lineStart = this.pos;
  }
}

/** Whether byte `c` ends a token: a space or control byte, the file's end or, with `hashComments`, a `#`. */
function isDelimiter(c: number | undefined, hashComments: boolean): boolean {
  return c === undefined || c <= SPACE || (c === HASH && hashComments);
}

/** What `scanNumber` found last; `value` is NaN when the number is beyond the range of a double. */
const scanned = { value: 0, integral: true, exponent: 0 };

/**
 * Scans the number written at `i` and returns where it ends, or -1 when no number is written there
 * (it must end at a space, the line's end, the file's end or, with `hashComments`, a `#`). Its value
 * goes to `scanned`: the mantissa is gathered as an integer and scaled by one exact power of ten
 * (see the top of this file), or else the engine rounds it.
 */
function scanNumber(bytes: Uint8Array, i: number, hashComments: boolean): number {
  const start = i;
  let c = bytes[i];
  const negative = c === MINUS;
  if (negative || c === PLUS) c = bytes[++i];
  let mantissa = 0;
  let digits = 0;
  let exponent = 0;
  let integral = true;
  while (c >= ZERO && c <= NINE) {
    mantissa = mantissa * 10 + (c - ZERO);
    digits++;
    c = bytes[++i];
  }
  if (c === DOT) {
    integral = false;
    c = bytes[++i];
    while (c >= ZERO && c <= NINE) {
      mantissa = mantissa * 10 + (c - ZERO);
      digits++;
      exponent--;
      c = bytes[++i];
    }
  }
  if (digits === 0) return -1;
  if (c === LOWER_E || c === UPPER_E) {
    integral = false;
    i = scanExponent(bytes, i + 1);
    if (i < 0) return -1;
    exponent += scanned.exponent;
    c = bytes[i];
  }
  if (!isDelimiter(c, hashComments)) return -1;
  scanned.integral = integral;
  if (mantissa < EXACT_INTEGER_LIMIT && exponent >= -22 && exponent <= 22) {
    const value = exponent < 0 ? mantissa / EXACT_POWERS_OF_TEN[-exponent] : mantissa * EXACT_POWERS_OF_TEN[exponent];
    scanned.value = negative ? -value : value;
  } else {
    scanned.value = longNumberValue(bytes, start, i);
  }
  return i;
}

/** How NaN and infinity are written as words, longest first (`inf` begins `infinity`), in small letters. */
const NON_FINITE_WORDS: ReadonlyArray<[string, number]> = [
  ['infinity', Infinity],
  ['inf', Infinity],
  ['nan', Number.NaN],
];

/**
 * Scans NaN or infinity written as a word at `i` ("nan", "-inf", "Infinity", in any case), into
 * `scanned`; returns where it ends, or -1 when no such word is there. Off the fast lane: only a
 * token that is not a decimal number comes here.
 */
function scanNonFiniteWord(bytes: Uint8Array, i: number, hashComments: boolean): number {
  const negative = bytes[i] === MINUS;
  if (negative || bytes[i] === PLUS) i++;
  for (const [word, value] of NON_FINITE_WORDS) {
    let k = 0;
    // setting bit 5 turns an ASCII capital into its small letter, and no other byte into a letter
    while (k < word.length && (bytes[i + k] | 0x20) === word.charCodeAt(k)) k++;
    if (k < word.length || !isDelimiter(bytes[i + k], hashComments)) continue;
    scanned.value = negative ? -value : value;
    scanned.integral = false;
    return i + k;
  }
  return -1;
}

/** Splits a double into two halves of 26 bits each (Dekker), for `productError`. */
const SPLITTER = 134217729; // 2^27 + 1
/**
 * How far inside half an ulp a remainder must be for `longNumberValue` to trust its quotient: far
 * more than the remainder's own rounding error (about 2^-50 of half an ulp).
 */
const TIE_MARGIN = 1 - 2 ** -30;
/** The double `ulpOf` reads the bits of. */
const ULP_BITS = new Float64Array(1);
const ULP_WORDS = new Uint32Array(ULP_BITS.buffer);
/** Which of the two words of a double holds its sign and exponent (1 on little-endian machines). */
const HIGH_WORD = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1 ? 1 : 0;

/**
 * A number the short path cannot round, written from `start` to `end`. Numbers of 16 to 19
 * significant digits scaled down by at most 10^22 (how the shortest round trip of a double is
 * written: 17 digits) are rounded here, exactly: the digits as a sum of two doubles, the quotient
 * corrected once by its remainder, and accepted only when that remainder shows it is the nearest
 * double by a clear margin. Every other number, and any near-tie, goes to the engine's parser.
 * It reads the digits again, so that `scanNumber` passes no more than it did to the engine.
 */
function longNumberValue(bytes: Uint8Array, start: number, end: number): number {
  // the significant digits as high · scale + low: high holds the first 15 (below 2^53), low the rest
  let high = 0;
  let low = 0;
  let scale = 1;
  let digits = 0;
  let exponent = 0;
  let point = false;
  for (let i = start; i < end; i++) {
    const c = bytes[i];
    if (c === LOWER_E || c === UPPER_E) {
      scanExponent(bytes, i + 1);
      exponent += scanned.exponent;
      break;
    }
    if (c === DOT) point = true;
    if (c < ZERO || c > NINE) continue; // sign, point
    if (point) exponent--;
    if (digits === 0 && c === ZERO) continue; // leading zeros
    if (digits < 15) high = high * 10 + (c - ZERO);
    else {
      low = low * 10 + (c - ZERO);
      scale *= 10;
    }
    digits++;
  }
  if (digits > 19 || exponent >= 0 || exponent < -22) return engineValue(bytes, start, end);
  // the digits exactly, as sum + rest: high · scale rounds to product, then adding low rounds to
  // sum; both rounding errors are whole numbers below 2^11, so their sum is exact
  const product = high * scale;
  const sum = product + low;
  const rest = sumError(product, low, sum) + productError(high, scale, product);
  const divisor = EXACT_POWERS_OF_TEN[-exponent];
  // sum / divisor is within an ulp or so of the quotient; one step by the remainder brings it within
  // half an ulp, and the remainder after that step says by how much
  let quotient = sum / divisor;
  quotient += remainder(sum, rest, quotient, divisor) / divisor;
  const left = remainder(sum, rest, quotient, divisor);
  const half = (divisor * ulpOf(quotient)) / 2;
  if (!(Math.abs(left) < half * TIE_MARGIN) || isPowerOfTwo(quotient)) return engineValue(bytes, start, end);
  return bytes[start] === MINUS ? -quotient : quotient;
}

/** (sum + rest) − quotient · divisor, where quotient · divisor is near sum (so `sum − product` is exact). */
function remainder(sum: number, rest: number, quotient: number, divisor: number): number {
  const product = quotient * divisor;
  return sum - product - productError(quotient, divisor, product) + rest;
}

/** x + y − sum exactly, for sum = x + y rounded (Knuth's two-sum). */
function sumError(x: number, y: number, sum: number): number {
  const yRounded = sum - x;
  return x - (sum - yRounded) + (y - yRounded);
}

/** x · y − product exactly, for product = x · y rounded (Dekker's two-product without a fused multiply-add). */
function productError(x: number, y: number, product: number): number {
  const xs = SPLITTER * x;
  const xHigh = xs - (xs - x);
  const xLow = x - xHigh;
  const ys = SPLITTER * y;
  const yHigh = ys - (ys - y);
  const yLow = y - yHigh;
  return xHigh * yHigh - product + xHigh * yLow + xLow * yHigh + xLow * yLow;
}

/** The gap between a positive normal double and the next one up. */
function ulpOf(x: number): number {
  ULP_BITS[0] = x;
  const biased = ULP_WORDS[HIGH_WORD] >>> 20; // exponent bits (x is positive)
  return 2 ** (biased - 1075);
}

/** Whether a positive double is a power of two: below one, the double beneath it is only half an ulp away. */
function isPowerOfTwo(x: number): boolean {
  ULP_BITS[0] = x;
  return (ULP_WORDS[HIGH_WORD] & 0xfffff) === 0 && ULP_WORDS[1 - HIGH_WORD] === 0;
}

/**
 * A number of many digits or a large exponent, rounded by the engine's own parser; NaN when it is
 * beyond the range of a double.
 */
function engineValue(bytes: Uint8Array, start: number, end: number): number {
  const value = Number(decodeText(bytes, start, end));
  return Number.isFinite(value) ? value : Number.NaN;
}

/**
 * The loop of `TextScanner.plainLines`, from byte `pos` on. It touches no object but its arrays
 * and leaves the scanner's fields to its caller: written on the way out of the loop, they made the
 * engine throw its optimised code away again and again (it optimises a long loop before it has
 * seen the code after it run).
 */
function scanPlainLines(bytes: Uint8Array, pos: number, batch: PlainLines, maxLines: number, keyword: number): number {
  const end = bytes.length;
  const { values, integral, ends, starts } = batch;
  const most = Math.min(maxLines, ends.length);
  let lines = 0;
  let n = 0;
  let i = pos;
  for (;;) {
    starts[lines] = i;
    if (lines === most || n + PLAIN_LINE_NUMBERS > values.length) return lines;
    if (keyword !== NO_KEYWORD) {
      const after = bytes[i + 1];
      if (bytes[i] !== keyword || !(after === SPACE || after === TAB)) return lines;
      i++;
    }
    const first = n;
    while (i < end) {
      const c = bytes[i];
      if (c === LF) break;
      if (c <= SPACE) {
        i++;
        continue;
      }
      const next = n - first < PLAIN_LINE_NUMBERS ? scanNumber(bytes, i, false) : -1;
      if (next < 0 || Number.isNaN(scanned.value)) return lines;
      values[n] = scanned.value;
      integral[n++] = scanned.integral ? 1 : 0;
      i = next;
    }
    if (i === end || n === first) return lines;
    ends[lines++] = n;
    i++;
  }
}

/**
 * Scans the digits of an exponent at `i` (after its `e`) into `scanned.exponent`; returns where
 * they end, or -1 when there are none. Apart from `scanNumber`, the rarer part, so that
 * `scanNumber` stays small enough for the engine to build into the fast lane's loop.
 */
function scanExponent(bytes: Uint8Array, i: number): number {
  let c = bytes[i];
  const negative = c === MINUS;
  if (negative || c === PLUS) c = bytes[++i];
  if (!(c >= ZERO && c <= NINE)) return -1;
  let written = 0;
  while (c >= ZERO && c <= NINE) {
    if (written < 100000) written = written * 10 + (c - ZERO);
    c = bytes[++i];
  }
  scanned.exponent = negative ? -written : written;
  return i;
}

function tokenEnd(bytes: Uint8Array, start: number): number {
  let end = start;
  while (end < bytes.length && bytes[end] > SPACE) end++;
  return end;
}

function trimmedText(bytes: Uint8Array, start: number, end: number): string {
  while (start < end && bytes[start] <= SPACE) start++;
  while (end > start && bytes[end - 1] <= SPACE) end--;
  return decodeText(bytes, start, end);
}

/** A token quoted in an error message: at most 24 characters, control bytes made visible. */
function excerpt(bytes: Uint8Array, start: number, end: number): string {
  const text = decodeText(bytes, start, Math.min(end, start + 24));
  const hex = (ch: string) => `\\x${ch.charCodeAt(0).toString(16).padStart(2, '0')}`;
  const visible = text.replace(/[\u0000-\u001f\u007f]/g, hex);
  return end - start > 24 ? `${visible}…` : visible;
}

/** ASCII runs up to this long are decoded character by character. */
const SHORT_RUN = 32;

/**
 * Decodes UTF-8 bytes (ASCII being the common case) into a string; a malformed sequence becomes
 * U+FFFD. Used for names, comments and error excerpts, and for glTF's JSON (ASCII runs go whole).
 */
export function decodeText(bytes: Uint8Array, start = 0, end = bytes.length): string {
  end = Math.min(end, bytes.length);
  let text = '';
  let i = start;
  while (i < end) {
    const c = bytes[i];
    if (c < 0x80) {
      // a run of ASCII at once (most of any text), in pieces that fit an argument list
      let j = i + 1;
      while (j < end && j - i < 8192 && bytes[j] < 0x80) j++;
      if (j - i <= SHORT_RUN) {
        // a keyword, a name, a number of 17 digits: met once per line or number, where a view of
        // the bytes would cost more than the characters
        for (let k = i; k < j; k++) text += String.fromCharCode(bytes[k]);
      } else {
        text += String.fromCharCode.apply(null, bytes.subarray(i, j) as unknown as number[]);
      }
      i = j;
      continue;
    }
    const length = c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : c >= 0xc0 ? 2 : 0;
    let code = length === 4 ? c & 0x07 : length === 3 ? c & 0x0f : c & 0x1f;
    let ok = length > 0 && i + length <= end;
    for (let k = 1; ok && k < length; k++) {
      const next = bytes[i + k];
      ok = (next & 0xc0) === 0x80;
      code = (code << 6) | (next & 0x3f);
    }
    if (ok && code <= 0x10ffff) {
      text += String.fromCodePoint(code);
      i += length;
    } else {
      text += '\ufffd';
      i++;
    }
  }
  return text;
}

/** Encodes a string as UTF-8 bytes (the writers' counterpart of `decodeText`). */
export function encodeText(text: string): Uint8Array {
  const bytes = new Uint8Array(text.length * 3);
  let n = 0;
  for (let i = 0; i < text.length; i++) {
    let code = text.charCodeAt(i);
    if (code < 0x80) {
      bytes[n++] = code;
      continue;
    }
    if (code >= 0xd800 && code < 0xdc00 && i + 1 < text.length) {
      const low = text.charCodeAt(i + 1);
      if (low >= 0xdc00 && low < 0xe000) {
        code = 0x10000 + ((code - 0xd800) << 10) + (low - 0xdc00);
        i++;
      }
    }
    if (code < 0x800) {
      bytes[n++] = 0xc0 | (code >> 6);
    } else if (code < 0x10000) {
      bytes[n++] = 0xe0 | (code >> 12);
      bytes[n++] = 0x80 | ((code >> 6) & 0x3f);
    } else {
      bytes[n++] = 0xf0 | (code >> 18);
      bytes[n++] = 0x80 | ((code >> 12) & 0x3f);
      bytes[n++] = 0x80 | ((code >> 6) & 0x3f);
    }
    bytes[n++] = 0x80 | (code & 0x3f);
  }
  return bytes.slice(0, n);
}
