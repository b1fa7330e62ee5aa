import { describe, expect, it } from 'vitest';
import { keepsOrientation } from '../../src/core/decimation/collapses.js';
import { addPlane, optimalPoint, quadricError } from '../../src/core/decimation/quadric.js';
import { CollapseQueue } from '../../src/core/decimation/queue.js';
import { halfedgeFromTo } from '../../src/core/edits/index.js';
import { seededRandom } from '../../src/core/random.js';
import { disk } from '../../src/core/shapes.js';
import { meshOf } from './helpers.js';

const SEED = 4242;

describe('the collapse queue', () => {
  it(`pops entries in the order of a sort, pushed and heapified alike (seed ${SEED})`, () => {
    const next = seededRandom(SEED);
    const queue = new CollapseQueue(); // buckets start small, so they have to grow
    const entries: Array<[number, number]> = [];
    for (let i = 0; i < 500; i++) {
      const cost = Math.floor(next() * 100); // ties included
      entries.push([cost, i]);
      if (i < 300) queue.append(cost, i);
      else queue.push(cost, i);
      if (i === 299) queue.heapify();
    }
    const popped: number[] = [];
    while (queue.size > 0) {
      popped.push(queue.topCost);
      queue.pop();
    }
    expect(popped).toEqual(entries.map(([cost]) => cost).sort((p, q) => p - q));
  });

  it(`always pops the cheapest, however pushes and pops interleave, across costs from 0 to 1e12 (seed ${SEED})`, () => {
    const next = seededRandom(SEED);
    const queue = new CollapseQueue();
    const held: number[] = []; // the reference: every cost in the queue
    const randomCost = () => (next() < 0.05 ? 0 : 10 ** (24 * next() - 12) * (1 + next()));
    // a queue cleared after use starts afresh
    for (let i = 0; i < 100; i++) queue.push(randomCost(), i);
    queue.clear();
    expect(queue.size).toBe(0);
    for (let i = 0; i < 3000; i++) {
      const cost = randomCost();
      queue.append(cost, i);
      held.push(cost);
    }
    queue.heapify();
    for (let step = 0; step < 20000; step++) {
      if (next() < 0.45 || held.length === 0) {
        // a push, sometimes far below everything held (a newly allowed cheap edge)
        const cost = next() < 0.1 ? randomCost() * 1e-6 : randomCost();
        queue.push(cost, step);
        held.push(cost);
      } else {
        const cheapest = Math.min(...held);
        expect(queue.topCost).toBe(cheapest);
        held.splice(held.indexOf(cheapest), 1);
        queue.pop();
      }
      expect(queue.size).toBe(held.length);
    }
  });

  it('keeps each entry’s edge with its cost', () => {
    const queue = new CollapseQueue();
    [5, 1, 4, 2, 3].forEach((cost) => queue.push(cost, 10 * cost));
    const edges: number[] = [];
    while (queue.size > 0) {
      edges.push(queue.topEdge);
      queue.pop();
    }
    expect(edges).toEqual([10, 20, 30, 40, 50]);
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
