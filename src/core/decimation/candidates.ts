/**
 * The candidates of one pass of decimation: the cheapest planned collapses, in order of cost.
 *
 * A pass needs only the cheapest few of the edges (about the number it will collapse, and those
 * a little costlier), so it does not sort them all. While the pass scans the edges it counts
 * their costs in buckets (`count`): the bucket is the cost's float32 bit pattern shifted right
 * (BUCKET_SHIFT), so costs within about 9% of each other share one, and a costlier bucket never
 * holds a cheaper cost. The buckets then say below which cost the cheapest `wanted` lie, and
 * `collect` takes the edges up to a little above that (MARGIN buckets: half as costly again)
 * and sorts them with a radix sort on the same bits, 11 at a time.
 * ```
 *   bucket     0 … 11   12   13   14 … 17   18 …
 *   count      0 …  0  900 4100 …       …         wanted 3000: bucket 13 holds the 3000th,
 *   collected  ─────────────────────────┘             so 12 … 13 + MARGIN are collected, sorted
 * ```
 */

/** Float32 bits >>> BUCKET_SHIFT: 3 mantissa bits are kept, so 8 buckets per doubling of the cost. */
const BUCKET_SHIFT = 20;
/** Float32 bits of +Infinity: every finite cost ≥ 0 has fewer. */
const INFINITY_BITS = 0x7f800000;
const BUCKETS = INFINITY_BITS >>> BUCKET_SHIFT;
/** Buckets collected beyond the one holding the `wanted`-th cost: 2^(5/8) ≈ 1.54 times as costly. */
const MARGIN = 5;
/** A radix sort digit. */
const DIGIT_BITS = 11;
const DIGITS = 1 << DIGIT_BITS;

const float32 = new Float32Array(1);
const bits32 = new Uint32Array(float32.buffer);

export class Candidates {
  /** The collected edges, cheapest first, and their cost bits (`size` of each are in use). */
  edges = new Int32Array(1024);
  costBits = new Uint32Array(1024);
  size = 0;
  /** Finite costs counted in each bucket since the last `collect`. */
  private readonly histogram = new Uint32Array(BUCKETS);
  /** Finite costs counted since the last `collect`. */
  counted = 0;
  /** The radix sort's other half and its digit counts. */
  private spareEdges = new Int32Array(1024);
  private spareBits = new Uint32Array(1024);
  private readonly digitCounts = new Uint32Array(DIGITS);

  /** The cost of the `i`-th collected edge, as it was collected. */
  costAt(i: number): number {
    bits32[0] = this.costBits[i];
    return float32[0];
  }

  /** Counts one cost, given as its float32 bits; an infinite one (never allowed) is left out. */
  count(bits: number): void {
    if (bits >= INFINITY_BITS) return;
    this.histogram[bits >>> BUCKET_SHIFT]++;
    this.counted++;
  }

  /**
   * Collects, cheapest first, every edge of `live[0…n)` whose cost is at most about 1.5 times
   * the `wanted`-th cheapest (all of them when fewer are counted); `costBits` holds each edge's
   * cost as float32 bits, as counted. Clears the counts for the next pass.
   */
  collect(live: Int32Array, n: number, costBits: Uint32Array, wanted: number): void {
    const { histogram } = this;
    // the bucket of the wanted-th cheapest, and how many the collected buckets hold
    let last = BUCKETS - 1;
    let total = 0;
    for (let b = 0; b < BUCKETS; b++) {
      total += histogram[b];
      if (total >= wanted) {
        last = Math.min(b + MARGIN, BUCKETS - 1);
        for (let c = b + 1; c <= last; c++) total += histogram[c];
        break;
      }
    }
    histogram.fill(0);
    this.counted = 0;
    this.reserve(total);
    const { edges, costBits: bits } = this;
    const limit = (last + 1) << BUCKET_SHIFT;
    let size = 0;
    for (let i = 0; i < n; i++) {
      const e = live[i];
      const key = costBits[e];
      if (key < limit) {
        edges[size] = e;
        bits[size++] = key;
      }
    }
    this.size = size;
    this.sort();
  }

  /** Sorts the collected edges by cost, stably: least significant digit first. */
  private sort(): void {
    const { digitCounts: counts, size } = this;
    for (let shift = 0; shift < 32; shift += DIGIT_BITS) {
      const { edges, costBits } = this;
      const toEdges = this.spareEdges;
      const toBits = this.spareBits;
      counts.fill(0);
      for (let i = 0; i < size; i++) counts[(costBits[i] >>> shift) & (DIGITS - 1)]++;
      // every key shares this digit: already in order by it
      if (counts[(costBits[0] >>> shift) & (DIGITS - 1)] === size) continue;
      let start = 0;
      for (let d = 0; d < DIGITS; d++) {
        const c = counts[d];
        counts[d] = start;
        start += c;
      }
      for (let i = 0; i < size; i++) {
        const key = costBits[i];
        const at = counts[(key >>> shift) & (DIGITS - 1)]++;
        toEdges[at] = edges[i];
        toBits[at] = key;
      }
      this.spareEdges = edges;
      this.spareBits = costBits;
      this.edges = toEdges;
      this.costBits = toBits;
    }
  }

  /** Room for `n` collected edges, in both halves of the sort. */
  private reserve(n: number): void {
    if (n <= this.edges.length) return;
    const length = Math.max(n, 2 * this.edges.length);
    this.edges = new Int32Array(length);
    this.costBits = new Uint32Array(length);
    this.spareEdges = new Int32Array(length);
    this.spareBits = new Uint32Array(length);
  }
}
