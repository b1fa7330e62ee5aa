/**
 * `readMesh`: bytes in, polygon soup out, whatever the format. Pure (no file system, no DOM), so
 * the same call serves Node, a Web Worker and a page.
 */
import { ParseError } from '../errors.js';
import { detectFormat } from './detect.js';
import { checkFiniteValues } from './finite.js';
import type { GltfReadOptions } from './gltf.js';
import type { MeshFile, MeshFormat, Progress, ReaderOutput, ReadOptions } from './mesh-file.js';
import { readObj } from './obj.js';
import { readOff } from './off.js';
import { readPly } from './ply.js';
import { readStl } from './stl.js';

const readers: Record<Exclude<MeshFormat, 'gltf'>, (bytes: Uint8Array, progress: Progress, weldTolerance?: number) => ReaderOutput> = {
  ply: readPly,
  off: readOff,
  obj: readObj,
  stl: readStl,
};

/**
 * Reads a PLY, OFF, OBJ or STL file (glTF, whose decoders load on demand, is `readMeshAsync`'s).
 * The format comes from the content (the file name is asked only when the content does not say);
 * faces stay polygons, attributes come along. A value that is NaN or infinite refuses the file
 * when it is a position; any other is dropped, with a note (see `finite.ts`).
 * @example
 *   const file = readMesh(bytes, { fileName: 'bunny.ply' });
 *   const { mesh, report } = buildMesh(file.soup);
 * @throws ParseError for any malformed file, naming the line and column or the byte offset.
 */
export function readMesh(data: ArrayBuffer | Uint8Array, options: ReadOptions = {}): MeshFile {
  const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
  const progress = options.onProgress ?? (() => {});
  const format = detectFormat(bytes, options.fileName);
  if (format === 'gltf') throw new ParseError('glTF', { byteOffset: 0 }, 'a glTF file is read with `await readMeshAsync(bytes)`');
  return readAs(format, bytes, progress, options.weldTolerance);
}

/**
 * Reads any file `readMesh` reads, and glTF 2.0 (`.glb`, or `.gltf` with its buffers in
 * `options.resources`), whose vertices are welded by position (see `readGltf`).
 * @example
 *   const file = await readMeshAsync(bytes, { fileName: 'duck.glb' });
 * @throws ParseError as `readMesh` does; for glTF, naming the path to the value in its JSON (with
 *   the line and column of a `.gltf`, the byte offset in a `.glb`).
 */
export async function readMeshAsync(data: ArrayBuffer | Uint8Array, options: ReadOptions & GltfReadOptions = {}): Promise<MeshFile> {
  const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
  const progress = options.onProgress ?? (() => {});
  const format = detectFormat(bytes, options.fileName);
  if (format !== 'gltf') return readAs(format, bytes, progress, options.weldTolerance);
  progress(0);
  // glTF-Transform and the decoders load only when a glTF file comes
  const { readGltf } = await import('./gltf.js');
  // glTF checks its values as it reads them, where it knows their accessor and element
  const file = await readGltf(bytes, options);
  progress(1);
  return file;
}

function readAs(format: Exclude<MeshFormat, 'gltf'>, bytes: Uint8Array, progress: Progress, weldTolerance?: number): MeshFile {
  progress(0);
  const { file, locate } = readers[format](bytes, progress, weldTolerance);
  checkFiniteValues(file, locate);
  progress(1);
  return file;
}
