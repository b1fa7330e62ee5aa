/**
 * Triangulation ends on every polygon, however its corners repeat or line up: it gives triangles
 * that cover the polygon exactly, or refuses. Checked on random polygons whose corners are drawn
 * from a 3 × 3 grid of points, so corners at one point, corners on a line and outlines that cross
 * themselves are common, and through the plane cut's caps, which reach it with such outlines.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { cutMesh } from '../../src/core/cut/index.js';
import { triangulatePolygon } from '../../src/core/edits/index.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';
import { meshOf } from './helpers.js';

const SEED = 20261125;

/** Twice the signed area enclosed by the rings (outer counter-clockwise, holes clockwise). */
function ringsDoubleArea(coords: number[], holeStarts: number[]): number {
  const n = coords.length / 2;
  const starts = [0, ...holeStarts, n];
  let sum = 0;
  for (let r = 0; r + 1 < starts.length; r++) {
    for (let i = starts[r]; i < starts[r + 1]; i++) {
      const j = i + 1 < starts[r + 1] ? i + 1 : starts[r];
      sum += coords[2 * i] * coords[2 * j + 1] - coords[2 * j] * coords[2 * i + 1];
    }
  }
  return sum;
}

/**
 * What any triangulation of the polygon must be: triangles of first corners at their points,
 * none turning clockwise, every point used, and the areas adding up to the rings' area.
 */
function expectTriangulationOf(coords: number[], holeStarts: number[], triangles: Uint32Array): void {
  const n = coords.length / 2;
  const key = (i: number) => `${coords[2 * i]},${coords[2 * i + 1]}`;
  const firstAt = new Map<string, number>();
  for (let i = 0; i < n; i++) if (!firstAt.has(key(i))) firstAt.set(key(i), i);
  expect(triangles.length % 3).toBe(0);
  for (const c of triangles) expect(firstAt.get(key(c))).toBe(c);
  expect(new Set(triangles)).toEqual(new Set(firstAt.values()));
  let area = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
    const doubled =
      (coords[2 * b] - coords[2 * a]) * (coords[2 * c + 1] - coords[2 * a + 1]) -
      (coords[2 * b + 1] - coords[2 * a + 1]) * (coords[2 * c] - coords[2 * a]);
    expect(doubled).toBeGreaterThanOrEqual(0);
    area += doubled;
  }
  expect(area).toBeCloseTo(ringsDoubleArea(coords, holeStarts), 9);
}

describe(`triangulatePolygon on polygons with repeated and collinear corners (seed ${SEED})`, () => {
  it('does not loop on a polygon with two corners at one point (it crosses itself: refused)', () => {
    expect(triangulatePolygon([0, 1, 1, 1, 0, 0, 0, 0, 1, 0], [])).toBeNull();
  });

  const gridPoint = fc.tuple(fc.integer({ min: 0, max: 2 }), fc.integer({ min: 0, max: 2 }));
  const ring = fc.array(gridPoint, { minLength: 3, maxLength: 9 });

  it('ends on random outlines with a triangulation that covers them exactly, or a refusal', () => {
    let triangulated = 0;
    fc.assert(
      fc.property(ring, (points) => {
        const coords = points.flat();
        const triangles = triangulatePolygon(coords, []);
        if (triangles) {
          triangulated++;
          expectTriangulationOf(coords, [], triangles);
        }
      }),
      { seed: SEED, numRuns: 3000 },
    );
    // the grid makes most outlines cross themselves, but not all
    expect(triangulated).toBeGreaterThan(100);
  });

  it('ends on random outlines with a hole inside a larger square, covering them exactly or refusing', () => {
    // the outer square runs counter-clockwise round the grid, the hole is drawn inside it
    const outer = [-1, -1, 3, -1, 3, 3, -1, 3];
    fc.assert(
      fc.property(ring, (points) => {
        const coords = [...outer, ...points.flat()];
        const triangles = triangulatePolygon(coords, [4]);
        if (triangles) expectTriangulationOf(coords, [4], triangles);
      }),
      { seed: SEED, numRuns: 2000 },
    );
  });
});

describe('the plane cut through an outline with two corners at one point', () => {
  // an open tube of five quads around the outline (0,1) (1,1) (0,0) (0,0) (1,0), from z = -1 to
  // z = 1: the cut at z = 0 meets a cap outline with two corners at one point
  const outline = [
    [0, 1],
    [1, 1],
    [0, 0],
    [0, 0],
    [1, 0],
  ];
  const positions = [...outline.flatMap(([x, y]) => [x, y, -1]), ...outline.flatMap(([x, y]) => [x, y, 1])];
  const quads = outline.map((_, i) => {
    const j = (i + 1) % outline.length;
    return [i, j, 5 + j, 5 + i];
  });

  it('ends, and leaves a valid mesh capped or open', () => {
    const mesh = meshOf(soupFromArrays(positions, quads));
    cutMesh(mesh, [0, 0, 1, 0], { keep: 'above' });
    expect(validate(mesh)).toEqual([]);
    expect(meshStats(mesh).faces).toBeGreaterThanOrEqual(5);
  });
});
