/**
 * The queue of candidate collapses: the cheapest (cost, edge) entry first, exactly, with push and
 * pop cheap even when the queue holds every edge of a million-triangle mesh.
 *
 * Entries are filed in buckets by cost: the bucket is the cost's float32 bit pattern shifted right
 * (BUCKET_SHIFT), so costs within about 9% of each other share one, and a costlier bucket never
 * holds a cheaper entry. Only the lowest bucket that holds anything (the *current* one) is kept as
 * a binary min-heap; every other bucket is a plain list, heap-ordered once, when it becomes
 * current. So a push above the current bucket is an append, and pops sift through a heap of one
 * bucket (thousands of entries, in cache) rather than of the whole queue (a million, out of it,
 * where each level of a sift waits on memory).
 * ```
 *   bucket   …  12 (current: a heap)   13 (list)   14 (list)   …
 *   pop  ──► the heap's top            push 0.7 ──► append to 13
 * ```
 *
 * The queue cannot find an entry to update or remove it, so the decimation never asks it to:
 *   - lazy deletion: an entry whose edge has been deleted stays in the queue, and is skipped when
 *     it comes to the top;
 *   - lazy update: a collapse makes the edges around the survivor costlier (their ends only gain
 *     planes, so the least error over all points can only grow), so their entries stay as they
 *     are, filed under a cost that is now a lower bound. When such an entry comes to the top,
 *     its real cost is computed; if that is above the next entry's cost, the edge is pushed again
 *     under it, else it is the cheapest. (Where the merged vertex may only go to an end or the
 *     midpoint, a cost can drop a little when an end moves; such an edge just comes up a little
 *     late.)
 * ```
 *   top (e7, 0.2) ─ pop ─► e7 deleted?  skip
 *                          real cost 0.5 > next top 0.3?  push (e7, 0.5), pop again
 *                          else collapse e7
 * ```
 * So each edge has at most one entry, and an edge is planned again mostly when its entry reaches
 * the top.
 */

/** Float32 bits >>> BUCKET_SHIFT: 3 mantissa bits are kept, so 8 buckets per doubling of the cost. */
const BUCKET_SHIFT = 20;
/** Buckets for every finite cost ≥ 0, and one more for anything above. */
const BUCKETS = (0x7f800000 >>> BUCKET_SHIFT) + 1;

const float32 = new Float32Array(1);
const bits32 = new Uint32Array(float32.buffer);

/** The bucket of a cost ≥ 0; monotone: a higher cost never gets a lower bucket. */
function bucketOf(cost: number): number {
  float32[0] = cost;
  return Math.min(bits32[0] >>> BUCKET_SHIFT, BUCKETS - 1);
}

/** The entries of one bucket: a list, or a heap while the bucket is current. */
class Bucket {
  costs = new Float64Array(16);
  edges = new Int32Array(16);
  size = 0;

  append(cost: number, edge: number): void {
    if (this.size === this.costs.length) {
      const costs = new Float64Array(2 * this.size);
      const edges = new Int32Array(2 * this.size);
      costs.set(this.costs);
      edges.set(this.edges);
      this.costs = costs;
      this.edges = edges;
    }
    this.costs[this.size] = cost;
    this.edges[this.size++] = edge;
  }

  /** Orders the list into a heap, bottom up: O(n). */
  heapify(): void {
    for (let i = (this.size >> 1) - 1; i >= 0; i--) this.siftDown(i, this.costs[i], this.edges[i]);
  }

  push(cost: number, edge: number): void {
    this.append(cost, edge);
    const { costs, edges } = this;
    // move parents down until the new entry's place is found
    let i = this.size - 1;
    while (i > 0) {
      const parent = (i - 1) >> 1;
      if (costs[parent] <= cost) break;
      costs[i] = costs[parent];
      edges[i] = edges[parent];
      i = parent;
    }
    costs[i] = cost;
    edges[i] = edge;
  }

  pop(): void {
    const last = --this.size;
    if (last > 0) this.siftDown(0, this.costs[last], this.edges[last]);
  }

  /** Places the entry (cost, edge) at `i` or below, moving cheaper children up. */
  private siftDown(i: number, cost: number, edge: number): void {
    const { costs, edges } = this;
    const n = this.size;
    for (;;) {
      let child = 2 * i + 1;
      if (child >= n) break;
      if (child + 1 < n && costs[child + 1] < costs[child]) child++;
      if (costs[child] >= cost) break;
      costs[i] = costs[child];
      edges[i] = edges[child];
      i = child;
    }
    costs[i] = cost;
    edges[i] = edge;
  }
}

export class CollapseQueue {
  /** Made when first used: most costs fall in a few dozen of them. */
  private readonly buckets: Array<Bucket | undefined> = new Array(BUCKETS);
  /** The lowest bucket holding an entry, heap-ordered; BUCKETS when the queue is empty. */
  private current = BUCKETS;
  size = 0;

  /** Cost and edge of the cheapest entry (read only when `size > 0`). */
  get topCost(): number {
    return this.buckets[this.current]!.costs[0];
  }
  get topEdge(): number {
    return this.buckets[this.current]!.edges[0];
  }

  /** Appends an entry without ordering it; call `heapify` after a run of these. */
  append(cost: number, edge: number): void {
    this.bucket(bucketOf(cost)).append(cost, edge);
    this.size++;
  }

  /** Orders appended entries: finds the current bucket and makes it a heap. */
  heapify(): void {
    this.current = 0;
    this.advance();
  }

  push(cost: number, edge: number): void {
    const b = bucketOf(cost);
    const bucket = this.bucket(b);
    if (b > this.current) bucket.append(cost, edge);
    else {
      // below the current bucket: that one was empty, and becomes current (the old one stays a
      // heap, which is also a list)
      this.current = b;
      bucket.push(cost, edge);
    }
    this.size++;
  }

  /** Removes the cheapest entry. */
  pop(): void {
    const bucket = this.buckets[this.current]!;
    bucket.pop();
    this.size--;
    if (bucket.size === 0) this.advance();
  }

  clear(): void {
    for (const bucket of this.buckets) if (bucket) bucket.size = 0;
    this.current = BUCKETS;
    this.size = 0;
  }

  /** Moves `current` up to the next bucket holding an entry, and makes that one a heap. */
  private advance(): void {
    let b = this.current;
    while (b < BUCKETS && !this.buckets[b]?.size) b++;
    this.current = b;
    if (b < BUCKETS) this.buckets[b]!.heapify();
  }

  private bucket(b: number): Bucket {
    return (this.buckets[b] ??= new Bucket());
  }
}
