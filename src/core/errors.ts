/**
 * The few error types the core throws. Each message says what failed, where, and (when there is
 * one) what to do about it, in words a student understands.
 *
 * - `InvalidInputError`: the caller handed the core something it cannot use (a positions array
 *   whose length is not a multiple of 3, a face list that does not add up).
 * - `TopologyError`: an operation does not apply to this mesh or element (Loop on a quad mesh,
 *   collapsing an edge that would pinch the surface).
 * - `ParseError`: a mesh file is malformed; it names the format and the place (line and column for
 *   text, byte offset for binary, the path to the value in a JSON document).
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
 * Where in a file a parse error happened, never nowhere: text formats give the line (and column),
 * binary ones the byte offset, JSON documents (halfedge JSON, glTF) the path to the value
 * (`accessors[2].count`; '' for the document itself), with the line and column of its text, or
 * its byte offset in a `.glb`, when the text is at hand.
 */
export type FileLocation = TextLocation | ByteLocation | PathLocation;

interface Place {
  line?: number;
  /** 1-based, counted in bytes (as the text scanner counts). */
  column?: number;
  byteOffset?: number;
  path?: string;
}

interface TextLocation extends Place {
  line: number;
}

interface ByteLocation extends Place {
  byteOffset: number;
}

interface PathLocation extends Place {
  path: string;
}

export class ParseError extends Error {
  override readonly name = 'ParseError';
  readonly format: string;
  readonly location: FileLocation;
  /** The message without the format and place prefix. */
  readonly reason: string;

  constructor(format: string, location: FileLocation, reason: string) {
    super(`${format}: ${describeLocation(location)}: ${reason}`);
    this.format = format;
    this.location = location;
    this.reason = reason;
  }
}

/**
 * A location in words: "line 12, column 5", "byte 84", "accessors[2].count", or both kinds
 * ("line 3, column 7 (accessors[2].count)").
 */
export function describeLocation(location: FileLocation): string {
  const { line, column, byteOffset, path } = location;
  let place = '';
  if (line !== undefined) place = column !== undefined ? `line ${line}, column ${column}` : `line ${line}`;
  else if (byteOffset !== undefined) place = `byte ${byteOffset}`;
  if (!path) return place || 'the document';
  return place ? `${place} (${path})` : path;
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
  // `errorToJSON` gives every ParseError's record a location; a record without one stays a plain error
  if (record.name === 'ParseError' && record.location) {
    return new ParseError(record.format ?? 'file', record.location, record.reason ?? record.message);
  }
  switch (record.name) {
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
