/**
 * One level of subdivision, connectivity and positions: Loop on a sphere of triangles (beside
 * three-subdivide's Loop modifier on the same triangles) and Catmull-Clark on a torus of quads.
 *
 * Subdivision edits the mesh in place, and `run` is called once to warm up and then `repeat`
 * times, so `prepare` builds the input once and hands each run its own copy, cloned beforehand:
 * the time is the subdivision alone.
 *
 * The peer returns a triangle soup (no connectivity) and runs with `split: false`: by default it
 * first cuts triangles along their shared edges (to keep flat regions flat) and returns twice as
 * many triangles, which is not the same job. Its time grows faster than the input (about 3 s at
 * 100k triangles, over a minute and a half at a million), so it runs up to `peerFaceLimit`
 * triangles only.
 */
import { BufferAttribute, BufferGeometry } from 'three';
import { LoopSubdivision } from 'three-subdivide';
import { type BenchCase, FreshCopy } from '../harness.js';
import { torus } from '../../src/index.js';
import { buildMesh, subdivide } from '../library.js';
import { sphereFaceCount, sphereWithFaces } from './sphere.js';

const peerFaceLimit = 200_000;

export function subdivisionCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const repeat = size >= 1e6 ? 3 : 5;
    const side = Math.round(Math.sqrt(size));
    const geometry = new BufferGeometry();
    const loop = new FreshCopy();
    const catmullClark = new FreshCopy();
    return [
      {
        case: 'loop',
        size: sphereFaceCount(size),
        repeat,
        prepare(side) {
          const sphere = sphereWithFaces(size);
          if (side === 'ours') return loop.from(buildMesh(sphere).mesh);
          geometry.setAttribute('position', new BufferAttribute(new Float32Array(sphere.positions), 3));
          geometry.setIndex(new BufferAttribute(sphere.faceIndices, 1));
        },
        beforeEach: loop.renew,
        run: () => subdivide(loop.take(), 'loop'),
        peer:
          size <= peerFaceLimit
            ? { name: 'three-subdivide', run: () => LoopSubdivision.modify(geometry, 1, { split: false }) }
            : undefined,
      },
      {
        case: 'catmull-clark',
        size: side * side,
        repeat,
        prepare: () => catmullClark.from(buildMesh(torus(side, side)).mesh),
        beforeEach: catmullClark.renew,
        run: () => subdivide(catmullClark.take(), 'catmull-clark'),
      },
    ];
  });
}
