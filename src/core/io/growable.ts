/**
 * A typed array that grows by doubling, for data whose size no header states (the corners of an
 * OBJ, the items of PLY lists). Hot loops call `reserve` once per row and write into `data`
 * directly; `finish` trims it to `length`.
 */
type GrowableData =
  | Uint32Array<ArrayBuffer>
  | Int32Array<ArrayBuffer>
  | Float32Array<ArrayBuffer>
  | Float64Array<ArrayBuffer>;

export class GrowableArray<T extends GrowableData> {
  data: T;
  length = 0;
  private readonly make: (capacity: number) => T;

  constructor(make: (capacity: number) => T, capacity = 64) {
    this.make = make;
    this.data = make(Math.max(8, capacity));
  }

  /** Makes room for `extra` more values and returns the (possibly new) backing array. */
  reserve(extra: number): T {
    const needed = this.length + extra;
    if (needed > this.data.length) {
      const grown = this.make(Math.max(needed, 2 * this.data.length));
      grown.set(this.data.subarray(0, this.length));
      this.data = grown;
    }
    return this.data;
  }

  push(value: number): void {
    if (this.length === this.data.length) this.reserve(1);
    this.data[this.length++] = value;
  }

  /** Appends `count` copies of `value`. */
  pushRepeated(value: number, count: number): void {
    this.reserve(count).fill(value, this.length, this.length + count);
    this.length += count;
  }

  /** The values written so far, in an array of exactly that length. */
  finish(): T {
    return this.length === this.data.length ? this.data : (this.data.slice(0, this.length) as T);
  }
}
