/**
 * The bytes of a `data:` URI, as a `.gltf` holds its buffers inside itself
 * (`data:application/octet-stream;base64,AAAA…`). Decoded here, checked, rather than by
 * glTF-Transform, which takes any text for base64 (so a buffer would come out shorter than its
 * accessors, found only as it reads them) and fails on a URI without a comma without saying which.
 */
import { encodeText } from './text.js';

const BASE64_DIGITS = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
/** The value of each ASCII character as a base64 digit, -1 for those that are none. */
const base64Values = new Int8Array(128).fill(-1);
for (let k = 0; k < BASE64_DIGITS.length; k++) base64Values[BASE64_DIGITS.charCodeAt(k)] = k;

/** ASCII white space, which base64 may be broken by (as the web platform's `atob` allows). */
const WHITE_SPACE = /[\t\n\f\r ]+/g;

/**
 * The bytes `uri` holds: base64 when its type ends `;base64`, else percent-encoded text; null when
 * it is no `data:` URI or its base64 holds anything but base64 digits, white space, and padding at
 * the end.
 */
export function dataUriBytes(uri: string): Uint8Array<ArrayBuffer> | null {
  const comma = uri.indexOf(',');
  if (!uri.startsWith('data:') || comma < 0) return null;
  const written = uri.slice(comma + 1);
  if (!uri.slice(0, comma).endsWith(';base64')) return encodeText(percentDecoded(written)) as Uint8Array<ArrayBuffer>;
  const data = written.replace(WHITE_SPACE, '');
  const end = data.endsWith('==') ? data.length - 2 : data.endsWith('=') ? data.length - 1 : data.length;
  // a last group of one digit holds no whole byte
  if (end % 4 === 1) return null;
  const bytes = new Uint8Array(Math.floor((end * 3) / 4));
  let n = 0;
  let bits = 0;
  let held = 0;
  for (let i = 0; i < end; i++) {
    const c = data.charCodeAt(i);
    const value = c < 128 ? base64Values[c] : -1;
    if (value < 0) return null;
    // 6 bits a digit; a byte out whenever 8 are held (never more than 14, so 24 bits keep them)
    bits = ((bits << 6) | value) & 0xffffff;
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes[n++] = (bits >> held) & 0xff;
    }
  }
  return bytes;
}

function percentDecoded(text: string): string {
  try {
    return decodeURIComponent(text);
  } catch {
    return text;
  }
}
