/**
 * The icosphere the native peers run on: an icosahedron whose triangles are split in four, level
 * after level, new vertices pushed out to the unit sphere, in the order a generator leaves them
 * (each level's midpoints after the old vertices, faces level by level: not sorted for locality).
 * 20 · 4^level triangles: level 8 is the 1.31M-triangle case.
 */
import { type PolygonSoup, soupFromArrays } from '../../src/index.js';

export function icosphere(level: number): PolygonSoup {
  const t = (1 + Math.sqrt(5)) / 2;
  const positions: number[] = [-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1];
  let faces = [0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1];
  for (let l = 0; l < level; l++) {
    const midpoints = new Map<number, number>();
    const nV = positions.length / 3;
    const midpoint = (a: number, b: number) => {
      const key = Math.min(a, b) * nV + Math.max(a, b);
      let m = midpoints.get(key);
      if (m === undefined) {
        m = positions.length / 3;
        positions.push((positions[3 * a] + positions[3 * b]) / 2, (positions[3 * a + 1] + positions[3 * b + 1]) / 2, (positions[3 * a + 2] + positions[3 * b + 2]) / 2);
        midpoints.set(key, m);
      }
      return m;
    };
    const next: number[] = [];
    for (let f = 0; f < faces.length; f += 3) {
      const [a, b, c] = [faces[f], faces[f + 1], faces[f + 2]];
      const [ab, bc, ca] = [midpoint(a, b), midpoint(b, c), midpoint(c, a)];
      next.push(a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca);
    }
    faces = next;
  }
  for (let v = 0; v < positions.length; v += 3) {
    const length = Math.hypot(positions[v], positions[v + 1], positions[v + 2]);
    for (let k = 0; k < 3; k++) positions[v + k] /= length;
  }
  const polygons: number[][] = [];
  for (let f = 0; f < faces.length; f += 3) polygons.push([faces[f], faces[f + 1], faces[f + 2]]);
  return soupFromArrays(positions, polygons);
}
