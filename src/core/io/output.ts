/**
 * What the writers share: text built line by line and encoded in batches, and numbers written so
 * that they read back exactly. A float32 value gets the fewest digits that read back as that
 * float32, a float64 value the fewest that read back as that float64; positions are float64 in a
 * mesh, but when every one is a float32 value they are written (and typed) as float32.
 */
import type { AttributeType } from '../attributes.js';
import { encodeText } from './text.js';

/** Lines of text, encoded to bytes a batch at a time so no huge string is ever built. */
export class TextOutput {
  private lines: string[] = [];
  private readonly chunks: Uint8Array[] = [];

  line(text: string): void {
    this.lines.push(text);
    if (this.lines.length === 8192) this.flush();
  }

  bytes(): Uint8Array {
    this.flush();
    return concatBytes(this.chunks);
  }

  private flush(): void {
    if (this.lines.length === 0) return;
    this.chunks.push(encodeText(this.lines.join('\n') + '\n'));
    this.lines = [];
  }
}

export function concatBytes(chunks: Uint8Array[]): Uint8Array {
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let at = 0;
  for (const chunk of chunks) {
    out.set(chunk, at);
    at += chunk.length;
  }
  return out;
}

/** True when every value is exactly a float32 (so float32 digits and types lose nothing). */
export function allFloat32(values: ArrayLike<number>): boolean {
  for (let i = 0; i < values.length; i++) {
    const x = values[i];
    if (Math.fround(x) !== x && !Number.isNaN(x)) return false;
  }
  return true;
}

/** A function that writes values of `type` as text that reads back to the same value. */
export function numberFormat(type: AttributeType): (x: number) => string {
  return type === 'float32' ? formatFloat32 : type === 'float64' ? formatFloat64 : String;
}

/** The shortest decimal that reads back as `x`; unlike `String`, it keeps the sign of -0. */
export function formatFloat64(x: number): string {
  return Object.is(x, -0) ? '-0' : String(x);
}

/**
 * The shortest decimal that reads back as the float32 nearest `x` ("0.1", not
 * "0.10000000149011612").
 */
export function formatFloat32(value: number): string {
  const x = Math.fround(value);
  if (!Number.isFinite(x) || x === 0) return formatFloat64(x);
  const roundTrips = (digits: number) => Math.fround(Number(x.toPrecision(digits))) === x;
  // float32 needs at most 9 significant digits; most values need 6 to 9
  let digits = 6;
  if (roundTrips(digits)) {
    while (digits > 1 && roundTrips(digits - 1)) digits--;
  } else {
    while (!roundTrips(digits)) digits++;
  }
  return String(Number(x.toPrecision(digits)));
}
