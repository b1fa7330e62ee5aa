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

/**
 * A new array of `length` zeros to add into (`sums[i] += …`, `count[v]++`), its memory written
 * once, in order, before anything reads it. Fresh memory read first maps the kernel's shared page
 * of zeros, which the first write must then swap for a page of its own; while another thread of
 * the process runs (a level's helper thread), those swaps slow both threads down, most likely as
 * each one flushes the other core's cached address mappings. Measured on a 1M-quad torus with the
 * helper at work: the neighbour sums of Catmull-Clark took 185–230 ms that way, 40–75 ms in
 * memory written first; plain first writes to fresh memory showed no such cost.
 */
export function zeros<T extends Float64Array | Int32Array>(Type: new (length: number) => T, length: number): T {
  const array = new Type(length);
  array.fill(0);
  return array;
}

/**
 * The sum of the first `count` bytes (a mesh's deleted flags: how many are set). Four bytes at a
 * time where the array lines up: a subdivided mesh of millions of elements arrives whole on the
 * page, which recounts its flags before it draws (21 ms at 5.2M faces a byte at a time).
 */
export function byteSum(bytes: Uint8Array, count: number): number {
  let sum = 0;
  let i = 0;
  for (; i < count && (bytes.byteOffset + i) % 4 !== 0; i++) sum += bytes[i];
  // none when the bytes ran out before a word began
  const words = i < count ? new Uint32Array(bytes.buffer, bytes.byteOffset + i, (count - i) >> 2) : new Uint32Array(0);
  for (let w = 0; w < words.length; ) {
    // two bytes of each word into each of two 16-bit lanes: 128 words fill neither past 65,280
    let lanes = 0;
    for (const end = Math.min(words.length, w + 128); w < end; w++) lanes += (words[w] & 0x00ff00ff) + ((words[w] >>> 8) & 0x00ff00ff);
    sum += (lanes & 0xffff) + (lanes >>> 16);
  }
  for (i += 4 * words.length; i < count; i++) sum += bytes[i];
  return sum;
}
