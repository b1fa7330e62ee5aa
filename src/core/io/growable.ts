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
    if (needed > this.data.length) this.grow(Math.max(needed, 2 * this.data.length));
    return this.data;
  }

  /**
   * Makes room for the `extra` values of row `row` of `rows`, and returns the (possibly new)
   * backing array. The rows of one element mostly hold as many values each (faces of four corners
   * in an array sized for triangles, say), so when it must grow it grows to what the rows so far
   * hold on average times all the rows, rather than doubling and being trimmed again; never to more
   * than `most`, what the rest of the file can hold. An estimate that would hardly grow it (later
   * rows longer than the first) gives way to doubling.
   */
  reserveRow(extra: number, row: number, rows: number, most: number): T {
    const needed = this.length + extra;
    if (needed <= this.data.length) return this.data;
    const estimate = Math.min(Math.ceil((needed / (row + 1)) * rows), most);
    this.grow(Math.max(needed, estimate >= this.data.length * 1.125 ? estimate : 2 * this.data.length));
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

  private grow(capacity: number): void {
    const grown = this.make(capacity);
    grown.set(this.data.subarray(0, this.length));
    this.data = grown;
  }

  /** The values written so far, in an array of exactly that length. */
  finish(): T {
    return this.length === this.data.length ? this.data : (this.data.slice(0, this.length) as T);
  }
}
