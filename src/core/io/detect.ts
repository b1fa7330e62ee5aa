/**
 * Which format a file is in, decided by its content first: the `ply` magic line, an OFF keyword
 * (possibly after comments), STL's size rule or its `solid … facet` text, the first OBJ
 * statement. The file name's extension is asked only when the content does not say, because
 * names lie more often than contents (a `.txt` download, an `.off` that is really PLY).
 */
import { ParseError } from '../errors.js';
import type { MeshFormat } from './mesh-file.js';
import { isBinaryStl } from './stl.js';
import { decodeText, TextScanner } from './text.js';

const OFF_KEYWORD = /^(ST)?C?N?4?n?OFF/;

/** Statements an OBJ file may begin with. */
const OBJ_STATEMENTS = new Set(['v', 'vt', 'vn', 'vp', 'f', 'l', 'p', 'o', 'g', 's', 'usemtl', 'mtllib']);

/** How much of a file is looked at for a first word (comments before it included). */
const SNIFF_BYTES = 1 << 16;

/**
 * @example
 *   detectFormat(bytes, 'bunny.ply'); // 'ply' when the content starts with the line "ply"
 * @throws ParseError for an empty file, or one neither its content nor its name identifies.
 */
export function detectFormat(bytes: Uint8Array, fileName?: string): MeshFormat {
  const named = fileName === undefined ? undefined : formatFromFileName(fileName);
  if (bytes.length === 0) throw new ParseError(named ?? 'file', { byteOffset: 0 }, 'the file is empty (0 bytes)');
  if (startsWithPlyLine(bytes)) return 'ply';
  if (isGltf(bytes)) return 'gltf';
  if (isBinaryStl(bytes)) return 'stl';
  const head = bytes.subarray(0, SNIFF_BYTES);
  const first = firstWord(head);
  if (OFF_KEYWORD.test(first) || first === 'appearance') return 'off';
  if (first === 'solid' && /\b(facet|endsolid)\b/.test(decodeText(head, 0, 1024))) return 'stl';
  if (OBJ_STATEMENTS.has(first)) return 'obj';
  if (named) return named;
  const name = fileName ? ` of '${fileName}'` : '';
  const start = first ? `; it starts with '${first.slice(0, 24)}'` : '';
  const supported = 'Supported: PLY (.ply), OFF (.off), OBJ (.obj), STL (.stl), glTF (.glb, .gltf)';
  throw new ParseError('file', { byteOffset: 0 }, `unknown format${name}${start}. ${supported}`);
}

/** The format a file name's extension suggests: `.off`, `.coff`, `.noff` … all say OFF. */
export function formatFromFileName(name: string): MeshFormat | undefined {
  const extension = /\.([a-z0-9]+)$/i.exec(name)?.[1].toLowerCase() ?? '';
  if (extension === 'ply' || extension === 'obj' || extension === 'stl') return extension;
  if (extension === 'glb' || extension === 'gltf') return 'gltf';
  if (extension.endsWith('off')) return 'off';
  return undefined;
}

/** The magic number that starts a GLB: "glTF" in ASCII, read as a little-endian uint32. */
const GLB_MAGIC = 0x46546c67;

/** Whether the bytes are a binary glTF (a GLB): its magic number. */
export function isGlb(bytes: Uint8Array): boolean {
  return bytes.length >= 4 && new DataView(bytes.buffer, bytes.byteOffset, 4).getUint32(0, true) === GLB_MAGIC;
}

/** A GLB (its magic), or glTF JSON (an object with an `asset` near its start). */
function isGltf(bytes: Uint8Array): boolean {
  if (isGlb(bytes)) return true;
  const head = decodeText(bytes.subarray(0, 4096), 0, 4096).trimStart();
  return head.startsWith('{') && /"asset"\s*:/.test(head);
}

/** "ply", then the end of the line (or a space before it). */
function startsWithPlyLine(bytes: Uint8Array): boolean {
  const after = bytes[3];
  const ply = bytes[0] === 0x70 && bytes[1] === 0x6c && bytes[2] === 0x79;
  return ply && (after === 0x0a || after === 0x0d || after === 0x20);
}

/** The first word after blank lines and `#` comments. */
function firstWord(head: Uint8Array): string {
  const scanner = new TextScanner(head, 'file', { hashComments: true });
  return scanner.skipBlankLines() ? scanner.word() : '';
}
