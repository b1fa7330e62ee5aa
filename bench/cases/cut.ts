/**
 * The capped plane cut through a closed sphere of triangles. The plane is tilted and off-centre,
 * so it meets no row of vertices: every edge it crosses is split. Each run cuts its own copy of
 * the mesh, made before the timing.
 */
import type { KeepSide } from '../../src/core/cut/index.js';
import { type BenchCase, FreshCopy } from '../harness.js';
import { buildMesh, cutMesh } from '../library.js';
import { sphereFaceCount, sphereWithFaces } from './sphere.js';

const PLANE = [0.1, 0.2, 1, -0.05] as const;

export function cutCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size) => {
    const repeat = size >= 1e6 ? 5 : 9;
    const cut = (keep: KeepSide): BenchCase => {
      const copies = new FreshCopy();
      return {
        case: keep === 'both' ? 'cut-capped' : `cut-capped-keep-${keep}`,
        size: sphereFaceCount(size),
        repeat,
        prepare: () => copies.from(buildMesh(sphereWithFaces(size)).mesh),
        beforeEach: copies.renew,
        run: () => cutMesh(copies.take(), PLANE, { keep }),
      };
    };
    return [cut('both'), cut('below')];
  });
}
