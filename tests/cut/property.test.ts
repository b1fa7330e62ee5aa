import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { Plane } from '../../src/core/cut/index.js';
import { boundingBox, signedVolume } from '../../src/core/geometry.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { cube, doubleTorus, tetrahedron, torus, uvSphere } from '../../src/core/shapes.js';
import { meshStats } from '../../src/core/stats.js';
import { capDistance, halfVolumes, hollowBall, meshOf, size, steppedBlock, stepCut, uPrism } from './helpers.js';

const SEED = 1357911;

const shapes: Array<[string, () => HalfedgeMesh]> = [
  ['tetrahedron', () => meshOf(tetrahedron())],
  ['cube', () => meshOf(cube())],
  ['sphere', () => meshOf(uvSphere(7, 9))],
  ['torus', () => meshOf(torus(10, 7))],
  ['voxel double torus', () => meshOf(doubleTorus())],
  ['hollow ball', () => meshOf(hollowBall())],
  ['stepped voxel block', () => meshOf(steppedBlock())],
  ['U-shaped prism', () => meshOf(uPrism())],
];

/** A unit normal: any direction, or one along the axes or the diagonals of the lattice. */
const normal = fc.oneof(
  fc
    .tuple(fc.double({ min: 0, max: 2 * Math.PI, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true }))
    .map(([theta, z]) => [Math.sqrt(1 - z * z) * Math.cos(theta), Math.sqrt(1 - z * z) * Math.sin(theta), z]),
  fc.constantFrom([1, 0, 0], [0, -1, 0], [0, 0, 1], [1, 1, 0], [0, 1, -1], [1, 1, 1]),
);

/** Where the plane passes: through a vertex, or through a point of the bounding box. */
const anchor = fc.oneof(
  fc.record({ vertex: fc.nat() }),
  fc.record({ box: fc.tuple(fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true }), fc.double({ min: 0, max: 1, noNaN: true })) }),
);

function planeThrough(mesh: HalfedgeMesh, n: readonly number[], where: { vertex: number } | { box: number[] }): Plane {
  let p: number[];
  if ('vertex' in where) p = mesh.position(where.vertex % mesh.vertexSlots);
  else {
    const { min, max } = boundingBox(mesh)!;
    p = where.box.map((t, i) => min[i] + t * (max[i] - min[i]));
  }
  return [n[0], n[1], n[2], -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2])];
}

describe(`random planes through closed meshes (seed ${SEED})`, () => {
  for (const [name, make] of shapes) {
    it(`cut a ${name} into valid, closed, capped halves whose volumes add up to the whole`, () => {
      const original = make();
      const volume = signedVolume(original);
      fc.assert(
        fc.property(normal, anchor, (n, where) => {
          const plane = planeThrough(original, n, where);
          const [above, below] = halfVolumes(original, plane);
          expect(Math.abs(above + below - volume) / volume).toBeLessThan(1e-9);
          const both = original.clone();
          const phases = stepCut(both, plane);
          expect(meshStats(both).closed).toBe(true);
          expect(capDistance(both, phases, plane)).toBeLessThan(1e-12 * size(original));
        }),
        { seed: SEED, numRuns: 60 },
      );
    });
  }
});
