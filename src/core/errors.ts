/**
 * The few error types the core throws. Each message says what failed, where, and (when there is
 * one) what to do about it, in words a student understands.
 *
 * - `InvalidInputError`: the caller handed the core something it cannot use (a positions array
 *   whose length is not a multiple of 3, a face list that does not add up).
 * - `TopologyError`: an operation does not apply to this mesh or element (Loop on a quad mesh,
 *   collapsing an edge that would pinch the surface).
 * - `ParseError`: a mesh file is malformed; it names the format and the place (line and column for
 *   text, byte offset for binary).
 *
 * All three carry a `name` and plain fields, so they survive `structuredClone` and the worker
 * boundary: rebuild them with `errorFromJSON`.
 */

export class InvalidInputError extends Error {
  override readonly name = 'InvalidInputError';
}

export class TopologyError extends Error {
  override readonly name = 'TopologyError';
}

/**
 * Where in a file a parse error happened. Text formats give line/column, binary ones a byte offset,
 * JSON documents the path to the value (`accessors[2].count`; '' for the document itself).
 */
export interface FileLocation {
  line?: number;
  column?: number;
  byteOffset?: number;
  path?: string;
}

export class ParseError extends Error {
  override readonly name = 'ParseError';
  readonly format: string;
  readonly location: FileLocation;
  /** The message without the format and place prefix. */
  readonly reason: string;

  constructor(format: string, location: FileLocation, reason: string) {
    super(`${format}: ${describeLocation(location)}${reason}`);
    this.format = format;
    this.location = location;
    this.reason = reason;
  }
}

function describeLocation(location: FileLocation): string {
  if (location.line !== undefined) {
    return location.column !== undefined
      ? `line ${location.line}, column ${location.column}: `
      : `line ${location.line}: `;
  }
  if (location.byteOffset !== undefined) return `byte ${location.byteOffset}: `;
  return '';
}

/** Plain-object form of a core error, for `postMessage` and JSON. */
export interface ErrorRecord {
  name: string;
  message: string;
  format?: string;
  location?: FileLocation;
  reason?: string;
}

export function errorToJSON(error: unknown): ErrorRecord {
  if (error instanceof ParseError) {
    return {
      name: error.name,
      message: error.message,
      format: error.format,
      location: { ...error.location },
      reason: error.reason,
    };
  }
  if (error instanceof Error) return { name: error.name, message: error.message };
  return { name: 'Error', message: String(error) };
}

/** Rebuilds the error `errorToJSON` flattened, with its type, so `instanceof` works again. */
export function errorFromJSON(record: ErrorRecord): Error {
  switch (record.name) {
    case 'ParseError':
      return new ParseError(record.format ?? 'file', record.location ?? {}, record.reason ?? record.message);
    case 'InvalidInputError':
      return new InvalidInputError(record.message);
    case 'TopologyError':
      return new TopologyError(record.message);
    default: {
      const error = new Error(record.message);
      error.name = record.name;
      return error;
    }
  }
}
