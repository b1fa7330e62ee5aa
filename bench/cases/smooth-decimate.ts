/**
 * Decimation and smoothing.
 *
 * `decimate`: quadric decimation to a tenth of the faces, beside meshoptimizer's simplifier (also
 * quadric error, WebAssembly) doing the same on the same triangles. Both run with no error limit,
 * so both stop at the face count. Each of our runs decimates its own copy of the mesh, made
 * before the timing (the peer reads its input arrays and returns a new index buffer). Two inputs,
 * since the order of their vertices decides much of the peer's time: the latitude–longitude
 * sphere, whose vertices come in the best order for the cache, and the natives' icosphere
 * (`decimate-icosphere`), in the order its generator leaves them.
 *
 * `smooth-taubin`: ten Taubin iterations (twenty Laplacian steps) on a copy of the sphere; no peer.
 */
import { MeshoptSimplifier } from 'meshoptimizer';
import type { PolygonSoup } from '../../src/index.js';
import { type BenchCase, FreshCopy } from '../harness.js';
import { buildMesh, decimate, smooth } from '../library.js';
import { icosphere } from './icosphere.js';
import { sphereFaceCount, sphereWithFaces } from './sphere.js';

export function smoothDecimateCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const repeat = size >= 1e6 ? 3 : 5;
    // the icosphere level whose 20 · 4^level triangles come nearest `size` (level 8, 1.31M, for 1M)
    const level = Math.round(Math.log(size / 20) / Math.log(4));
    const toSmooth = new FreshCopy();
    return [
      decimateCase('decimate', sphereFaceCount(size), () => sphereWithFaces(size), repeat),
      decimateCase('decimate-icosphere', 20 * 4 ** level, () => icosphere(level), repeat),
      {
        case: 'smooth-taubin',
        size: sphereFaceCount(size),
        repeat,
        prepare: () => toSmooth.from(buildMesh(sphereWithFaces(size)).mesh),
        beforeEach: toSmooth.renew,
        run: () => smooth(toSmooth.take(), { method: 'taubin', iterations: 10 }),
      },
    ];
  });
}

/** Decimating the triangles `input` makes to a tenth of their `faces`, ours beside meshoptimizer's. */
function decimateCase(name: string, faces: number, input: () => PolygonSoup, repeat: number): BenchCase {
  const targetFaces = Math.round(faces / 10);
  const copies = new FreshCopy();
  let indices: Uint32Array;
  let positions: Float32Array;
  return {
    case: name,
    size: faces,
    repeat,
    async prepare(side) {
      const soup = input();
      if (side === 'ours') copies.from(buildMesh(soup).mesh);
      else {
        indices = Uint32Array.from(soup.faceIndices);
        positions = new Float32Array(soup.positions);
        await MeshoptSimplifier.ready;
      }
    },
    beforeEach: copies.renew,
    run: () => decimate(copies.take(), { targetFaces }),
    peer: { name: 'meshoptimizer', run: () => MeshoptSimplifier.simplify(indices, positions, 3, 3 * targetFaces, 1) },
  };
}
