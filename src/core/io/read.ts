/**
 * `readMesh`: bytes in, polygon soup out, whatever the format. Pure (no file system, no DOM), so
 * the same call serves Node, a Web Worker and a page.
 */
import { ParseError } from '../errors.js';
import { detectFormat } from './detect.js';
import { firstNonFiniteValue } from './finite.js';
import type { MeshFile, MeshFormat, Progress, ReadOptions } from './mesh-file.js';
import { readObj } from './obj.js';
import { readOff } from './off.js';
import { readPly } from './ply.js';
import { readStl } from './stl.js';

const readers: Record<MeshFormat, (bytes: Uint8Array, progress: Progress) => MeshFile> = {
  ply: readPly,
  off: readOff,
  obj: readObj,
  stl: readStl,
};

/**
 * Reads a PLY, OFF, OBJ or STL file. The format comes from the content (the file name is asked
 * only when the content does not say); faces stay polygons, attributes come along.
 * @example
 *   const file = readMesh(bytes, { fileName: 'bunny.ply' });
 *   const { mesh, report } = buildMesh(file.soup);
 * @throws ParseError for any malformed file, naming the line and column or the byte offset, and
 *   for a value that is NaN or infinite (after reading), naming the element and the attribute.
 */
export function readMesh(data: ArrayBuffer | Uint8Array, options: ReadOptions = {}): MeshFile {
  const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
  const progress = options.onProgress ?? (() => {});
  const format = detectFormat(bytes, options.fileName);
  progress(0);
  const file = readers[format](bytes, progress);
  const nonFinite = firstNonFiniteValue(file.soup);
  if (nonFinite) throw new ParseError(format, {}, nonFinite);
  progress(1);
  return file;
}
