/**
 * The queue of candidate collapses: a binary min-heap of (cost, edge) entries over two typed
 * arrays, rather than one object per entry. Push and pop are O(log n); nothing is ever sorted.
 *
 * A binary heap cannot find an entry to update or remove it, so the decimation never asks it to:
 *   - lazy deletion: an entry whose edge has been deleted stays in the heap, and is skipped when
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
export class CollapseQueue {
  private costs: Float64Array;
  private edges: Int32Array;
  size = 0;

  constructor(capacity: number) {
    this.costs = new Float64Array(Math.max(capacity, 16));
    this.edges = new Int32Array(this.costs.length);
  }

  /** Cost and edge of the cheapest entry (read only when `size > 0`). */
  get topCost(): number {
    return this.costs[0];
  }
  get topEdge(): number {
    return this.edges[0];
  }

  /** Appends an entry without ordering it; call `heapify` after a run of these. */
  append(cost: number, edge: number): void {
    if (this.size === this.costs.length) this.grow();
    this.costs[this.size] = cost;
    this.edges[this.size++] = edge;
  }

  /** Orders appended entries into a heap, bottom up: O(n), cheaper than n pushes. */
  heapify(): void {
    for (let i = (this.size >> 1) - 1; i >= 0; i--) this.siftDown(i, this.costs[i], this.edges[i]);
  }

  push(cost: number, edge: number): void {
    if (this.size === this.costs.length) this.grow();
    const { costs, edges } = this;
    // move parents down until the new entry's place is found
    let i = this.size++;
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

  /** Removes the cheapest entry. */
  pop(): void {
    const last = --this.size;
    if (last > 0) this.siftDown(0, this.costs[last], this.edges[last]);
  }

  clear(): void {
    this.size = 0;
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

  private grow(): void {
    const costs = new Float64Array(2 * this.costs.length);
    const edges = new Int32Array(costs.length);
    costs.set(this.costs);
    edges.set(this.edges);
    this.costs = costs;
    this.edges = edges;
  }
}
