/**
 * One binary reader for every binary format (PLY, STL, OFF BINARY): the scalar types they share,
 * each with a reader for one value and one for a run of values, and a cursor that checks each
 * read against the end of the file.
 *
 * Binary mesh files are tables: rows of scalars, each of a type fixed by the header. The reader
 * for a type is chosen once, before the loop over rows, so the hot loop never asks "which type
 * is this?" again. A read past the end of the file raises `ParseError` with the byte offset.
 */
import type { AttributeType } from '../attributes.js';
import { ParseError } from '../errors.js';

/** Anything values can be stored into by index: a typed array of any type. */
export type NumberTarget = { [index: number]: number };

export type ScalarReader = (view: DataView, offset: number, littleEndian: boolean) => number;

/**
 * Reads `count` values spaced `stride` bytes apart from `offset` on, into
 * `target[at]`, `target[at + step]`, … (a column of a table, or the items of a list).
 */
export type RunReader = (
  view: DataView,
  offset: number,
  stride: number,
  count: number,
  littleEndian: boolean,
  target: NumberTarget,
  at: number,
  step: number,
) => void;

export interface ScalarType {
  type: AttributeType;
  /** Bytes per value. */
  size: number;
  /** One value, for occasional reads. */
  read: ScalarReader;
  /**
   * Many values, for hot loops. Each type has its own loop with its own DataView call, so the
   * loop stays specialised to one type however many types a program reads.
   */
  readRun: RunReader;
  write: (view: DataView, offset: number, value: number, littleEndian: boolean) => void;
}

export const scalarTypes: Record<AttributeType, ScalarType> = {
  int8: {
    type: 'int8',
    size: 1,
    read: (view, offset) => view.getInt8(offset),
    readRun: (view, o, stride, n, _, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getInt8(o);
    },
    write: (view, offset, value) => view.setInt8(offset, value),
  },
  uint8: {
    type: 'uint8',
    size: 1,
    read: (view, offset) => view.getUint8(offset),
    readRun: (view, o, stride, n, _, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getUint8(o);
    },
    write: (view, offset, value) => view.setUint8(offset, value),
  },
  int16: {
    type: 'int16',
    size: 2,
    read: (view, offset, le) => view.getInt16(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getInt16(o, le);
    },
    write: (view, offset, value, le) => view.setInt16(offset, value, le),
  },
  uint16: {
    type: 'uint16',
    size: 2,
    read: (view, offset, le) => view.getUint16(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getUint16(o, le);
    },
    write: (view, offset, value, le) => view.setUint16(offset, value, le),
  },
  int32: {
    type: 'int32',
    size: 4,
    read: (view, offset, le) => view.getInt32(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getInt32(o, le);
    },
    write: (view, offset, value, le) => view.setInt32(offset, value, le),
  },
  uint32: {
    type: 'uint32',
    size: 4,
    read: (view, offset, le) => view.getUint32(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getUint32(o, le);
    },
    write: (view, offset, value, le) => view.setUint32(offset, value, le),
  },
  float32: {
    type: 'float32',
    size: 4,
    read: (view, offset, le) => view.getFloat32(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getFloat32(o, le);
    },
    write: (view, offset, value, le) => view.setFloat32(offset, value, le),
  },
  float64: {
    type: 'float64',
    size: 8,
    read: (view, offset, le) => view.getFloat64(offset, le),
    readRun: (view, o, stride, n, le, target, at, step) => {
      for (let i = 0; i < n; i++, o += stride, at += step) target[at] = view.getFloat64(o, le);
    },
    write: (view, offset, value, le) => view.setFloat64(offset, value, le),
  },
};

/** A DataView over exactly the bytes of `bytes`, wherever they sit in their buffer. */
export function viewOf(bytes: Uint8Array): DataView {
  return new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
}

/** A cursor over binary data that checks every read against the end of the file. */
export class BinaryReader {
  readonly view: DataView;
  readonly format: string;
  readonly littleEndian: boolean;
  offset: number;

  constructor(bytes: Uint8Array, format: string, littleEndian: boolean, offset = 0) {
    this.view = viewOf(bytes);
    this.format = format;
    this.littleEndian = littleEndian;
    this.offset = offset;
  }

  /** Bytes left after the cursor. */
  get remaining(): number {
    return this.view.byteLength - this.offset;
  }

  /** @throws ParseError saying what was cut off when fewer than `bytes` bytes are left. */
  need(bytes: number, what: string): void {
    if (bytes > this.remaining) this.fail(`the file ends inside ${what}`);
  }

  /** Reads one value of `type` and moves past it (hot loops use `ScalarType.readRun` instead). */
  read(type: ScalarType): number {
    if (type.size > this.remaining) this.fail('the file ends too early');
    const value = type.read(this.view, this.offset, this.littleEndian);
    this.offset += type.size;
    return value;
  }

  int32(): number {
    return this.read(scalarTypes.int32);
  }

  uint32(): number {
    return this.read(scalarTypes.uint32);
  }

  float32(): number {
    return this.read(scalarTypes.float32);
  }

  /** @throws ParseError at `at` (default: the cursor). */
  fail(reason: string, at = this.offset): never {
    throw new ParseError(this.format, { byteOffset: at }, reason);
  }
}
