import { describe, expect, it } from 'vitest';
import { keepsOrientation } from '../../src/core/decimation/collapses.js';
import { AREA, addPlane, optimalPoint, QUADRIC_SIZE, quadricError, sumQuadrics } from '../../src/core/decimation/quadric.js';
import { Candidates } from '../../src/core/decimation/candidates.js';
import { halfedgeFromTo } from '../../src/core/edits/index.js';
import { seededRandom } from '../../src/core/random.js';
import { disk } from '../../src/core/shapes.js';
import { meshOf } from './helpers.js';

const SEED = 4242;

describe('the candidates of a pass', () => {
  /** Costs for edges 0 … n − 1 (some never allowed), counted as a pass counts them. */
  function counted(candidates: Candidates, costs: number[]): { live: Int32Array; bits: Uint32Array } {
    const floats = Float32Array.from(costs);
    const bits = new Uint32Array(floats.buffer);
    const live = Int32Array.from(costs.keys());
    for (const e of live) candidates.count(bits[e]);
    return { live, bits };
  }

  /** A cost's bucket: its float32 bits without the last 20 (8 buckets per doubling, as `candidates.ts` counts them). */
  const bucketOf = (cost: number) => new Uint32Array(Float32Array.of(cost).buffer)[0] >>> 20;

  it(`collects the cheapest bucket by bucket, in edge order within one, and all a half more costly than the wanted-th (seed ${SEED})`, () => {
    const next = seededRandom(SEED);
    const candidates = new Candidates(); // its arrays start small, so they have to grow
    for (const wanted of [1, 10, 700, 5000]) {
      // costs from 0 to 1e12, ties, and edges that may never collapse
      const costs = Array.from({ length: 3000 }, () => (next() < 0.05 ? 0 : next() < 0.1 ? Infinity : Math.fround(10 ** (24 * next() - 12))));
      const { live, bits } = counted(candidates, costs);
      expect(candidates.counted).toBe(costs.filter((c) => c < Infinity).length);
      candidates.collect(live, live.length, bits, wanted);
      const collected = Array.from(candidates.edges.subarray(0, candidates.size));
      collected.forEach((e, i) => expect(candidates.costAt(i)).toBe(costs[e]));
      // bucket by bucket, edges in order within one
      for (let i = 1; i < collected.length; i++) {
        const [before, here] = [bucketOf(costs[collected[i - 1]]), bucketOf(costs[collected[i]])];
        expect(here).toBeGreaterThanOrEqual(before);
        if (here === before) expect(collected[i]).toBeGreaterThan(collected[i - 1]);
        expect(costs[collected[i]] * (1 + 1 / 8)).toBeGreaterThanOrEqual(costs[collected[i - 1]]); // a bucket spans at most an eighth
      }
      // every edge up to half as costly again as the wanted-th cheapest, and none never allowed
      const finite = costs.filter((c) => c < Infinity).sort((p, q) => p - q);
      const bar = wanted <= finite.length ? 1.5 * finite[wanted - 1] : Infinity;
      const mustHave = costs.flatMap((c, e) => (c < Infinity && c <= bar ? [e] : []));
      expect(mustHave.length).toBeGreaterThanOrEqual(Math.min(wanted, finite.length));
      expect(collected.filter((e) => costs[e] <= bar).sort((p, q) => p - q)).toEqual(mustHave);
      expect(collected.every((e) => costs[e] < Infinity)).toBe(true);
      // the counts start again at zero
      expect(candidates.counted).toBe(0);
    }
  });

  it('collects nothing when every edge is out', () => {
    const candidates = new Candidates();
    const { live, bits } = counted(candidates, [Infinity, Infinity]);
    expect(candidates.counted).toBe(0);
    candidates.collect(live, live.length, bits, 1);
    expect(candidates.size).toBe(0);
  });
});

describe('quadrics', () => {
  it('measure the squared distance to their planes, and find the corner of three', () => {
    const q = new Float64Array(10);
    addPlane(q, 0, 1, 0, 0, -1, 1); // x = 1
    addPlane(q, 0, 0, 1, 0, -2, 1); // y = 2
    addPlane(q, 0, 0, 0, 1, -3, 2); // z = 3, twice as heavy
    expect(quadricError(q, 0, 0, 0, 0)).toBeCloseTo(1 + 4 + 2 * 9, 12);
    const point = new Float64Array(3);
    expect(optimalPoint(q, 0, point)).toBe(true);
    expect(Array.from(point).map((x) => +x.toFixed(12))).toEqual([1, 2, 3]);
    expect(quadricError(q, 0, 1, 2, 3)).toBe(0);
  });

  it('sum into a third quadric or into the first of the two', () => {
    const q = new Float64Array(2 * QUADRIC_SIZE);
    addPlane(q, 0, 1, 0, 0, -1, 1); // x = 1
    q[AREA] = 1;
    addPlane(q, QUADRIC_SIZE, 0, 1, 0, -2, 1); // y = 2
    q[QUADRIC_SIZE + AREA] = 2;
    const sum = new Float64Array(QUADRIC_SIZE);
    sumQuadrics(q, 0, QUADRIC_SIZE, sum, 0);
    expect(quadricError(sum, 0, 0, 0, 0)).toBe(1 + 4);
    expect(sum[AREA]).toBe(3);
    sumQuadrics(q, 0, QUADRIC_SIZE, q, 0);
    expect(Array.from(q.subarray(0, QUADRIC_SIZE))).toEqual(Array.from(sum));
  });

  it('refuse to pick a point when the planes are parallel or meet in a line', () => {
    const point = new Float64Array(3);
    const flat = new Float64Array(10);
    addPlane(flat, 0, 0, 0, 1, 0, 1);
    addPlane(flat, 0, 0, 0, 1, -1, 1);
    expect(optimalPoint(flat, 0, point)).toBe(false);
    const crease = new Float64Array(10);
    addPlane(crease, 0, 1, 0, 0, 0, 1);
    addPlane(crease, 0, 0, 1, 0, 0, 1);
    expect(optimalPoint(crease, 0, point)).toBe(false);
  });
});

describe('the fold-over check', () => {
  // a flat disk: collapsing the centre's edge to v1 moves both ends to a point
  const mesh = meshOf(disk(2));
  const e = halfedgeFromTo(mesh, 0, 1) >> 1;

  it('allows a point inside the ring of the two ends', () => {
    expect(keepsOrientation(mesh, e, 0.2, 0, 0)).toBe(true);
    expect(keepsOrientation(mesh, e, 0.2, 0.1, 0.3)).toBe(true); // lifted: the triangles tilt by less than 90°
  });

  it('refuses a point that turns a triangle over, or flattens one to nothing', () => {
    expect(keepsOrientation(mesh, e, -0.9, 0, 0)).toBe(false); // across the ring
    expect(keepsOrientation(mesh, e, 1.5, 0, 0)).toBe(false); // beyond the outer ring
    const [x, y] = mesh.position(2); // onto a neighbour: a triangle with two corners in one place
    expect(keepsOrientation(mesh, e, x, y, 0)).toBe(false);
  });
});
