/** Reading and writing mesh files for the CLI, and turning failures into one line on stderr. */
import { readFileSync, writeFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { parseArgs } from 'node:util';
import {
  buildMesh,
  type BuildResult,
  gltfBufferUris,
  type HalfedgeMesh,
  InvalidInputError,
  meshToHalfedgeJSON,
  type MeshFile,
  ParseError,
  readMeshAsync,
  TopologyError,
  writeFormatFromFileName,
  writeMeshAsync,
} from '../index.js';

/** Bad arguments or an unreadable file: exit status 2. */
export class UsageError extends Error {
  override readonly name = 'UsageError';
}

export interface LoadedMesh extends BuildResult {
  path: string;
  file: MeshFile;
}

/** How every command reads its input mesh (`--weld-tolerance D`: see `takeReadSettings`). */
export interface ReadSettings {
  weldTolerance?: number;
}

/**
 * Takes the options of reading out of a command's arguments: `--weld-tolerance D` (or `=D`), the
 * distance within which STL and glTF vertices are welded (default: exactly equal positions).
 */
export function takeReadSettings(args: string[]): { settings: ReadSettings; rest: string[] } {
  const settings: ReadSettings = {};
  const rest: string[] = [];
  for (let i = 0; i < args.length; i++) {
    const arg = args[i]!;
    if (arg !== '--weld-tolerance' && !arg.startsWith('--weld-tolerance=')) {
      rest.push(arg);
      continue;
    }
    const text = arg.includes('=') ? arg.slice(arg.indexOf('=') + 1) : args[++i];
    const value = Number(text);
    if (text === undefined || text.trim() === '' || !Number.isFinite(value) || value < 0) {
      throw new UsageError(`--weld-tolerance takes a distance of 0 or more, not ${text === undefined ? 'nothing' : `'${text}'`}`);
    }
    settings.weldTolerance = value;
  }
  return { settings, rest };
}

export async function loadMesh(path: string, settings: ReadSettings = {}): Promise<LoadedMesh> {
  const bytes = readBytes(path);
  try {
    const file = await readMeshAsync(bytes, { fileName: basename(path), resources: gltfResources(path, bytes), weldTolerance: settings.weldTolerance });
    return { path, file, ...buildMesh(file.soup) };
  } catch (error) {
    // name the file: the parser only knows the place inside it
    if (error instanceof ParseError || error instanceof InvalidInputError) throw new UsageError(`${path}: ${error.message}`);
    throw error;
  }
}

export function readBytes(path: string): Uint8Array<ArrayBuffer> {
  try {
    return readFileSync(path) as Uint8Array<ArrayBuffer>;
  } catch (error) {
    throw new UsageError(`cannot read ${path}: ${(error as NodeJS.ErrnoException).code ?? (error as Error).message}`);
  }
}

/** The buffers a `.gltf` names, read from beside it (a `.glb` or any other file needs none). */
function gltfResources(path: string, bytes: Uint8Array): Map<string, Uint8Array<ArrayBuffer>> | undefined {
  if (!path.toLowerCase().endsWith('.gltf')) return undefined;
  const resources = new Map<string, Uint8Array<ArrayBuffer>>();
  for (const uri of gltfBufferUris(bytes)) {
    // only files beside the .gltf or below it: a buffer cannot name /etc/passwd or ../../secret
    let name: string;
    try {
      name = decodeURIComponent(uri);
    } catch {
      continue; // not a file name: the reader says the buffer was not given
    }
    if (name.includes('..') || name.startsWith('/') || name.includes(':') || name.includes('\\')) continue;
    resources.set(uri, readBytes(join(dirname(path), name)));
  }
  return resources;
}

/** Writes `mesh` to `path` in the format its extension names (`.json`: the halfedge tables; `.glb`: binary glTF). */
export async function saveMesh(mesh: HalfedgeMesh, path: string, format?: string): Promise<void> {
  let bytes: Uint8Array;
  if (format === 'json' || (!format && path.toLowerCase().endsWith('.json'))) {
    bytes = new TextEncoder().encode(JSON.stringify(meshToHalfedgeJSON(mesh)));
  } else {
    const writeFormat = format ?? (path.toLowerCase().endsWith('.glb') ? 'glb' : writeFormatFromFileName(path));
    if (!writeFormat || !['ply', 'ply-binary', 'off', 'obj', 'glb'].includes(writeFormat)) {
      throw new UsageError(`cannot tell the output format of ${path}: use .ply, .off, .obj, .glb or .json, or --format`);
    }
    try {
      bytes = await writeMeshAsync(mesh, writeFormat as Parameters<typeof writeMeshAsync>[1]);
    } catch (error) {
      if (error instanceof InvalidInputError) throw new UsageError(`cannot write ${path}: ${error.message}`);
      throw error;
    }
  }
  try {
    writeFileSync(path, bytes);
  } catch (error) {
    throw new UsageError(`cannot write ${path}: ${(error as NodeJS.ErrnoException).code ?? (error as Error).message}`);
  }
}

/** `parseArgs` that turns its errors into usage errors. */
type OptionSpecs = Record<string, { type: 'string' | 'boolean'; short?: string }>;

export interface ParsedArgs<T extends OptionSpecs> {
  values: { [K in keyof T]?: T[K]['type'] extends 'string' ? string : boolean };
  positionals: string[];
}

export function parseOptions<T extends OptionSpecs>(args: string[], options: T, positionals: number): ParsedArgs<T> {
  let parsed: ParsedArgs<T>;
  try {
    parsed = parseArgs({ args, options, allowPositionals: true, strict: true }) as ParsedArgs<T>;
  } catch (error) {
    throw new UsageError((error as Error).message);
  }
  if (parsed.positionals.length !== positionals) {
    throw new UsageError(`expected ${positionals} file argument(s), got ${parsed.positionals.length}`);
  }
  return parsed;
}

/** One line on stderr; returns the exit status. */
export function reportFailure(error: unknown): number {
  if (error instanceof ParseError || error instanceof UsageError || error instanceof InvalidInputError || error instanceof TopologyError) {
    console.error(`halfedge-lab: ${error.message}`);
    return 2;
  }
  console.error(`halfedge-lab: internal error: ${error instanceof Error ? (error.stack ?? error.message) : String(error)}`);
  return 3;
}
