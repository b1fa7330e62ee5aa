/** Reading and writing mesh files for the CLI, and turning failures into one line on stderr. */
import { readFileSync, writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { parseArgs } from 'node:util';
import {
  buildMesh,
  type BuildResult,
  type HalfedgeMesh,
  InvalidInputError,
  meshToHalfedgeJSON,
  type MeshFile,
  ParseError,
  readMesh,
  TopologyError,
  writeFormatFromFileName,
  writeMesh,
} from '../index.js';

/** Bad arguments or an unreadable file: exit status 2. */
export class UsageError extends Error {
  override readonly name = 'UsageError';
}

export interface LoadedMesh extends BuildResult {
  path: string;
  file: MeshFile;
}

export function loadMesh(path: string): LoadedMesh {
  let bytes: Uint8Array;
  try {
    bytes = readFileSync(path);
  } catch (error) {
    throw new UsageError(`cannot read ${path}: ${(error as NodeJS.ErrnoException).code ?? (error as Error).message}`);
  }
  try {
    const file = readMesh(bytes, { fileName: basename(path) });
    return { path, file, ...buildMesh(file.soup) };
  } catch (error) {
    // name the file: the parser only knows the place inside it
    if (error instanceof ParseError || error instanceof InvalidInputError) throw new UsageError(`${path}: ${error.message}`);
    throw error;
  }
}

/** Writes `mesh` to `path` in the format its extension names (`.json`: the halfedge tables). */
export function saveMesh(mesh: HalfedgeMesh, path: string, format?: string): void {
  let bytes: Uint8Array;
  if (format === 'json' || (!format && path.toLowerCase().endsWith('.json'))) {
    bytes = new TextEncoder().encode(JSON.stringify(meshToHalfedgeJSON(mesh)));
  } else {
    const writeFormat = format ?? writeFormatFromFileName(path);
    if (!writeFormat || !['ply', 'ply-binary', 'off', 'obj'].includes(writeFormat)) {
      throw new UsageError(`cannot tell the output format of ${path}: use .ply, .off, .obj or .json, or --format`);
    }
    bytes = writeMesh(mesh, writeFormat as Parameters<typeof writeMesh>[1]);
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
