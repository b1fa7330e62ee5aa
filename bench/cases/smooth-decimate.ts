/**
 * Decimation and smoothing of a closed latitude–longitude sphere of triangles.
 *
 * `decimate`: quadric decimation to a tenth of the faces, beside meshoptimizer's simplifier (also
 * quadric error, WebAssembly) doing the same on the same triangles. Both run with no error limit,
 * so both stop at the face count. Each of our runs decimates its own copy of the mesh, made
 * before the timing (the peer reads its input arrays and returns a new index buffer).
 *
 * `smooth-taubin`: ten Taubin iterations (twenty Laplacian steps) on a copy; no peer.
 */
import { MeshoptSimplifier } from 'meshoptimizer';
import { buildMesh } from '../../src/core/build.js';
import { decimate } from '../../src/core/decimation/index.js';
import { smooth } from '../../src/core/smoothing/index.js';
import { type BenchCase, PreparedCopies } from '../harness.js';
import { sphereFaceCount, sphereWithFaces } from './build.js';

export function smoothDecimateCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const faces = sphereFaceCount(size);
    const targetFaces = Math.round(faces / 10);
    const repeat = size >= 1e6 ? 3 : 5;
    const toDecimate = new PreparedCopies(repeat + 1);
    const toSmooth = new PreparedCopies(repeat + 1);
    let indices: Uint32Array;
    let positions: Float32Array;
    return [
      {
        case: 'decimate',
        size: faces,
        repeat,
        async prepare(side) {
          const soup = sphereWithFaces(size);
          if (side === 'ours') toDecimate.fill(buildMesh(soup).mesh);
          else {
            indices = Uint32Array.from(soup.faceIndices);
            positions = new Float32Array(soup.positions);
            await MeshoptSimplifier.ready;
          }
        },
        run: () => decimate(toDecimate.take(), { targetFaces }),
        peer: { name: 'meshoptimizer', run: () => MeshoptSimplifier.simplify(indices, positions, 3, 3 * targetFaces, 1) },
      },
      {
        case: 'smooth-taubin',
        size: faces,
        repeat,
        prepare: () => toSmooth.fill(buildMesh(sphereWithFaces(size)).mesh),
        run: () => smooth(toSmooth.take(), { method: 'taubin', iterations: 10 }),
      },
    ];
  });
}
