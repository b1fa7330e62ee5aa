/** The grid's nearest point equals the brute-force one over every triangle, whatever the first guess. */
import { describe, expect, it } from 'vitest';
import { buildMesh, disk, seededRandom, torus, uvSphere } from '../../src/index.js';
import { NearestTriangle } from '../../src/core/remeshing/nearest-triangle.js';
import { pointTriangleDistance, triangles } from '../decimation/helpers.js';
import { triangulate } from '../subdivision/helpers.js';

const SEED = 424242;

const surfaces = [
  ['a sphere', () => buildMesh(triangulate(uvSphere(8, 12))).mesh],
  ['a torus', () => buildMesh(triangulate(torus(12, 8))).mesh],
  ['an open disk', () => buildMesh(disk(3)).mesh],
] as const;

describe.each(surfaces)(`the nearest point on %s (seed ${SEED})`, (_, make) => {
  it.each([0.05, 0.3, 2])('is the brute-force one, with cells %s wide and any first guess', (cellSize) => {
    const mesh = make();
    const grid = new NearestTriangle(mesh, cellSize);
    const corners = triangles(mesh);
    const random = seededRandom(SEED);
    for (let i = 0; i < 300; i++) {
      const p = [0, 1, 2].map(() => 3 * random() - 1.5);
      let best = Infinity;
      for (let k = 0; k < corners.length; k += 9) best = Math.min(best, pointTriangleDistance(p, corners, k));
      const guess = i % 3 === 0 ? -1 : Math.floor(random() * grid.count);
      const squared = grid.nearest(p[0], p[1], p[2], guess);
      expect(Math.sqrt(squared)).toBeCloseTo(best, 12);
      expect(Math.hypot(p[0] - grid.x, p[1] - grid.y, p[2] - grid.z)).toBeCloseTo(best, 12);
      // the point found is on the triangle it names
      expect(pointTriangleDistance([grid.x, grid.y, grid.z], corners, 9 * grid.triangle)).toBeCloseTo(0, 12);
    }
  });
});
