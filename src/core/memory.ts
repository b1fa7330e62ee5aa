/**
 * Where a mesh's new arrays come from: plain memory, or memory that another thread shares (see
 * `subdivision/helper-thread.ts`). A function from a size in bytes to a buffer of that many zeros.
 */
export type Memory = (bytes: number) => ArrayBufferLike;

const plainMemory: Memory = (bytes) => new ArrayBuffer(bytes);

/** The arrays of a mesh and its attributes. */
export type TypedArray = Int8Array | Uint8Array | Int16Array | Uint16Array | Int32Array | Uint32Array | Float32Array | Float64Array;

/** A typed array of `length` zeros, of the same type as `like`, in `memory`. */
export function newArrayLike<T extends TypedArray>(like: T, length: number, memory: Memory = plainMemory): T {
  const Type = like.constructor as new (buffer: ArrayBufferLike) => T;
  return new Type(memory(length * like.BYTES_PER_ELEMENT));
}

/** True when the array's memory is shared with other threads. */
export function isShared(array: ArrayBufferView): boolean {
  return typeof SharedArrayBuffer !== 'undefined' && array.buffer instanceof SharedArrayBuffer;
}
