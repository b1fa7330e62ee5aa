/**
 * A small ZIP writer: each file stored or deflated (whichever is smaller), with its CRC-32, a
 * UTF-8 name and Unix permission bits (so a script stays executable when it is unpacked). Every
 * entry has the same time, 1980-01-01 00:00, so the same files always make the same bytes. No
 * ZIP64: an archive holds fewer than 65,535 files and less than 4 GiB.
 *
 * Layout (APPNOTE.TXT): for each file a local header and its data, then the central directory
 * (a header per file again, with where its local header starts), then the end record.
 */
import { deflateRawSync } from 'node:zlib';

export interface ZipEntry {
  /** Its path in the archive, folders separated by `/`. */
  name: string;
  data: Uint8Array;
  /** Unix permission bits, 0o644 unless given (0o755 for a script). */
  mode?: number;
}

const CRC_TABLE = (() => {
  const table = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    table[n] = c >>> 0;
  }
  return table;
})();

/** The CRC-32 of `data` (the polynomial of ZIP, gzip and PNG). */
export function crc32(data: Uint8Array): number {
  let c = 0xffffffff;
  for (let i = 0; i < data.length; i++) c = CRC_TABLE[(c ^ data[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

const STORED = 0;
const DEFLATED = 8;
/** Bit 11: the name is UTF-8. */
const UTF8_NAMES = 0x0800;
/** MS-DOS date of 1980-01-01 (day 1, month 1, year 0 from 1980); the time is 00:00. */
const DOS_DATE = (1 << 5) | 1;
/** Version 2.0 (deflate); made by Unix (3), so the external attributes hold a file mode. */
const VERSION = 20;
const MADE_BY_UNIX = (3 << 8) | VERSION;
const REGULAR_FILE = 0o100000;

/**
 * The bytes of a ZIP archive of `entries`, in their order.
 * @throws RangeError for an unsafe or repeated name, or an archive too large without ZIP64.
 */
export function writeZip(entries: readonly ZipEntry[]): Uint8Array {
  if (entries.length >= 0xffff) throw new RangeError(`a ZIP without ZIP64 holds fewer than 65,535 files, not ${entries.length}`);
  const seen = new Set<string>();
  const encoder = new TextEncoder();
  const locals: Uint8Array[] = [];
  const centrals: Uint8Array[] = [];
  let offset = 0;
  for (const entry of entries) {
    const { name } = entry;
    // a name that climbs out of the folder it is unpacked in, or is absolute, is refused by careful readers
    if (!name || name.startsWith('/') || name.includes('\\') || name.split('/').some((part) => part === '..' || part === '.' || part === '')) {
      throw new RangeError(`a ZIP entry's name must be a relative path with / between folders, not "${name}"`);
    }
    if (seen.has(name)) throw new RangeError(`two ZIP entries are named "${name}"`);
    seen.add(name);
    const nameBytes = encoder.encode(name);
    const crc = crc32(entry.data);
    const deflated = deflateRawSync(entry.data, { level: 9 });
    const method = deflated.length < entry.data.length ? DEFLATED : STORED;
    const body = method === DEFLATED ? deflated : entry.data;

    const local = new Uint8Array(30 + nameBytes.length);
    const l = new DataView(local.buffer);
    l.setUint32(0, 0x04034b50, true);
    l.setUint16(4, VERSION, true);
    l.setUint16(6, UTF8_NAMES, true);
    l.setUint16(8, method, true);
    l.setUint16(10, 0, true); // time
    l.setUint16(12, DOS_DATE, true);
    l.setUint32(14, crc, true);
    l.setUint32(18, body.length, true);
    l.setUint32(22, entry.data.length, true);
    l.setUint16(26, nameBytes.length, true);
    l.setUint16(28, 0, true); // no extra field
    local.set(nameBytes, 30);

    const central = new Uint8Array(46 + nameBytes.length);
    const c = new DataView(central.buffer);
    c.setUint32(0, 0x02014b50, true);
    c.setUint16(4, MADE_BY_UNIX, true);
    c.setUint16(6, VERSION, true);
    c.setUint16(8, UTF8_NAMES, true);
    c.setUint16(10, method, true);
    c.setUint16(12, 0, true);
    c.setUint16(14, DOS_DATE, true);
    c.setUint32(16, crc, true);
    c.setUint32(20, body.length, true);
    c.setUint32(24, entry.data.length, true);
    c.setUint16(28, nameBytes.length, true);
    // extra field, comment, disk number, internal attributes: all 0
    c.setUint32(38, ((REGULAR_FILE | (entry.mode ?? 0o644)) << 16) >>> 0, true);
    c.setUint32(42, offset, true);
    central.set(nameBytes, 46);

    locals.push(local, body);
    centrals.push(central);
    offset += local.length + body.length;
  }
  const directorySize = centrals.reduce((sum, c) => sum + c.length, 0);
  if (offset + directorySize > 0xffffffff) throw new RangeError('a ZIP without ZIP64 holds less than 4 GiB');
  const end = new Uint8Array(22);
  const e = new DataView(end.buffer);
  e.setUint32(0, 0x06054b50, true);
  e.setUint16(8, entries.length, true);
  e.setUint16(10, entries.length, true);
  e.setUint32(12, directorySize, true);
  e.setUint32(16, offset, true);

  const zip = new Uint8Array(offset + directorySize + end.length);
  let at = 0;
  for (const part of [...locals, ...centrals, end]) {
    zip.set(part, at);
    at += part.length;
  }
  return zip;
}
