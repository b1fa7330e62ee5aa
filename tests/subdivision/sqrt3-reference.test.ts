/**
 * √3 subdivision against an independent reference on open meshes: the paper's formulas (Kobbelt,
 * "√3-Subdivision", SIGGRAPH 2000) evaluated straight from an indexed triangle list — no
 * halfedges, neighbours found by searching the triangles — giving every vertex position a level
 * must produce. The library's positions must be the same set of points.
 *
 * Inside: a face point at each triangle's centroid, and an old vertex with n neighbours moves to
 * (1 − α)·itself + α·(their mean), α = (4 − 2cos(2π/n))/9. On the boundary, every other level
 * (the odd ones) trisects each boundary edge with the ternary cubic B-spline rule: an old vertex
 * goes to (4, 19, 4)/27 of its boundary neighbours and itself, the points on edge P2P3 of the
 * boundary P1 P2 P3 P4 to (1, 16, 10)/27 and (10, 16, 1)/27, and a triangle with one boundary
 * edge gets no face point; on the even levels the boundary stays.
 */
import { describe, expect, it } from 'vitest';
import { runOperation } from '../../src/core/change/operation.js';
import { sqrt3Subdivision } from '../../src/core/subdivision/index.js';
import { cube, fan, grid, type PolygonSoup, soupFromArrays } from '../../src/index.js';
import { faceLists, meshOf, triangulate } from './helpers.js';

type Point = number[];

const add = (...terms: Array<[number, Point]>): Point =>
  [0, 1, 2].map((k) => terms.reduce((sum, [weight, p]) => sum + weight * p[k], 0));

function referencePoints(soup: PolygonSoup, odd: boolean): Point[] {
  const p: Point[] = [];
  for (let v = 0; v < soup.positions.length / 3; v++) p.push(Array.from(soup.positions.subarray(3 * v, 3 * v + 3)));
  const triangles = faceLists(soup);
  const sides = (t: number[]) => [0, 1, 2].map((k) => [t[k], t[(k + 1) % 3]]);
  const trianglesOn = (a: number, b: number) => triangles.filter((t) => sides(t).some(([x, y]) => (x === a && y === b) || (x === b && y === a)));
  const onBoundary = (a: number, b: number) => trianglesOn(a, b).length === 1;
  const neighbours = (v: number) => [...new Set(triangles.filter((t) => t.includes(v)).flat().filter((u) => u !== v))];
  const boundaryNeighbours = (v: number) => neighbours(v).filter((u) => onBoundary(v, u));

  const points: Point[] = [];
  for (let v = 0; v < p.length; v++) {
    const ring = neighbours(v);
    const along = boundaryNeighbours(v);
    if (along.length === 0) {
      const alpha = (4 - 2 * Math.cos((2 * Math.PI) / ring.length)) / 9;
      points.push(add([1 - alpha, p[v]], ...ring.map((u): [number, Point] => [alpha / ring.length, p[u]])));
    } else {
      points.push(odd ? add([4 / 27, p[along[0]]], [19 / 27, p[v]], [4 / 27, p[along[1]]]) : p[v]);
    }
  }
  for (const t of triangles) {
    const boundarySides = sides(t).filter(([a, b]) => onBoundary(a, b)).length;
    if (!odd || boundarySides !== 1) points.push(add(...t.map((v): [number, Point] => [1 / 3, p[v]])));
  }
  if (odd) {
    for (const t of triangles) {
      for (const [b, c] of sides(t)) {
        if (!onBoundary(b, c)) continue;
        const a = boundaryNeighbours(b).find((u) => u !== c)!;
        const d = boundaryNeighbours(c).find((u) => u !== b)!;
        points.push(add([1 / 27, p[a]], [16 / 27, p[b]], [10 / 27, p[c]]), add([10 / 27, p[b]], [16 / 27, p[c]], [1 / 27, p[d]]));
      }
    }
  }
  return points;
}

/** Points in a fixed order, rounded enough that sums in another order compare equal. */
function sorted(points: Point[]): string[] {
  return points.map((q) => q.map((x) => (Math.abs(x) < 5e-13 ? 0 : x).toFixed(10)).join(' ')).sort();
}

function libraryPoints(soup: PolygonSoup, level: number): Point[] {
  const mesh = meshOf(soup);
  runOperation(sqrt3Subdivision(mesh, { level }));
  return [...mesh.vertices()].map((v) => Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)));
}

/** A cube of triangles without its top: a box open along one square. */
function openBox(): PolygonSoup {
  const box = triangulate(cube());
  const top = faceLists(box).filter((t) => !t.every((v) => box.positions[3 * v + 2] === 1));
  return soupFromArrays(box.positions, top);
}

const fixtures: Array<[string, () => PolygonSoup]> = [
  ['a 3 × 3 grid of triangles', () => grid(3, 3)],
  ['a fan of 5 triangles', () => fan(5)],
  ['a box open at the top', openBox],
];

describe('√3 subdivision against the paper, on open meshes', () => {
  for (const [name, make] of fixtures) {
    for (const level of [0, 1]) {
      it(`places every vertex of ${name} as the paper's rules say, on an ${level % 2 ? 'odd' : 'even'} level`, () => {
        const soup = make();
        expect(sorted(libraryPoints(soup, level))).toEqual(sorted(referencePoints(soup, level % 2 === 1)));
      });
    }
  }
});
