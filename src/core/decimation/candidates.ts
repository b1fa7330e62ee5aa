/**
 * The candidates of one pass of decimation: the cheapest planned collapses, in order of cost to
 * within an eighth.
 *
 * A pass needs only the cheapest few of the edges (about the number it will collapse, and those
 * a little costlier), so it does not sort them all. While the pass scans the edges it counts
 * their costs in buckets (`count`): the bucket is the cost's float32 bit pattern shifted right
 * (BUCKET_SHIFT), so a bucket spans an eighth of a doubling (costs 6–12% apart), and a costlier
 * bucket never holds a cheaper cost. The buckets then say below which cost the cheapest `wanted`
 * lie, and `collect` takes the edges up to a little above that (MARGIN buckets: half as costly
 * again), placing each in its bucket's share of the list: bucket by bucket, and within a bucket
 * in the order of the live edges, which is id order.
 * ```
 *   bucket     0 … 11   12   13   14 … 17   18 …
 *   count      0 …  0  900 4100 …       …         wanted 3000: bucket 13 holds the 3000th,
 *   collected  ─────────────────────────┘             so 12 … 13 + MARGIN are collected
 * ```
 * Costs within a bucket count as equal, as meshoptimizer's simplifier sorts by a quantised cost.
 * Sorting them exactly (a radix sort on all 32 bits) took longer, and so did the choosing after
 * it, which then read the mesh at the edges in random order rather than in id order: decimating
 * the 1.3M-triangle icosphere took 1761 and 1805 ms that way against 1649 and 1728 in two runs,
 * and strayed as far from the input (at most 6.1e-5 on the unit sphere that way, 5.8e-5 this way).
 */

/** Float32 bits >>> BUCKET_SHIFT: 3 mantissa bits are kept, so 8 buckets per doubling of the cost. */
const BUCKET_SHIFT = 20;
/** Float32 bits of +Infinity: every finite cost ≥ 0 has fewer. */
const INFINITY_BITS = 0x7f800000;
const BUCKETS = INFINITY_BITS >>> BUCKET_SHIFT;
/** Buckets collected beyond the one holding the `wanted`-th cost: 2^(5/8) ≈ 1.54 times as costly. */
const MARGIN = 5;

const float32 = new Float32Array(1);
const bits32 = new Uint32Array(float32.buffer);

export class Candidates {
  /** The collected edges, cheapest bucket first, and their cost bits (`size` of each are in use). */
  edges = new Int32Array(1024);
  costBits = new Uint32Array(1024);
  size = 0;
  /** Finite costs counted in each bucket since the last `collect`. */
  private readonly histogram = new Uint32Array(BUCKETS);
  /** Finite costs counted since the last `collect`. */
  counted = 0;

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
   * Collects, cheapest bucket first and in edge order within a bucket, every edge of `live[0…n)`
   * whose cost is at most about 1.5 times the `wanted`-th cheapest (all of them when fewer are
   * counted); `costBits` holds each edge's cost as float32 bits, as counted. Clears the counts for
   * the next pass.
   */
  collect(live: Int32Array, n: number, costBits: Uint32Array, wanted: number): void {
    const { histogram } = this;
    // the bucket of the wanted-th cheapest, and the last bucket collected
    let last = BUCKETS - 1;
    for (let b = 0, total = 0; b < BUCKETS; b++) {
      total += histogram[b];
      if (total >= wanted) {
        last = Math.min(b + MARGIN, BUCKETS - 1);
        break;
      }
    }
    // where each collected bucket's share of the list starts
    let size = 0;
    for (let b = 0; b <= last; b++) {
      const count = histogram[b];
      histogram[b] = size;
      size += count;
    }
    this.reserve(size);
    const { edges, costBits: bits } = this;
    const limit = (last + 1) << BUCKET_SHIFT;
    for (let i = 0; i < n; i++) {
      const e = live[i];
      const key = costBits[e];
      if (key < limit) {
        const at = histogram[key >>> BUCKET_SHIFT]++;
        edges[at] = e;
        bits[at] = key;
      }
    }
    this.size = size;
    histogram.fill(0);
    this.counted = 0;
  }

  /** Room for `n` collected edges. */
  private reserve(n: number): void {
    if (n <= this.edges.length) return;
    const length = Math.max(n, 2 * this.edges.length);
    this.edges = new Int32Array(length);
    this.costBits = new Uint32Array(length);
  }
}
