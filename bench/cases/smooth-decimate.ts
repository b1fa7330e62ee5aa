/**
 * Decimation and smoothing of a closed latitude–longitude sphere of triangles.
 *
 * `decimate`: quadric decimation to a tenth of the faces, beside meshoptimizer's simplifier (also
 * quadric error, WebAssembly) doing the same on the same triangles. Both run with no error limit,
 * so both stop at the face count. Each of our runs decimates a fresh `clone()` of the prepared
 * mesh, and the copy is part of the time (a few tens of ms at a million triangles); the peer
 * reads its input arrays and returns a new index buffer, so it needs no copy.
 *
 * `smooth-taubin`: ten Taubin iterations (twenty Laplacian steps) on a fresh copy; no peer.
 */
import { MeshoptSimplifier } from 'meshoptimizer';
import { buildMesh } from '../../src/core/build.js';
import { decimate } from '../../src/core/decimation/index.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { smooth } from '../../src/core/smoothing/index.js';
import type { BenchCase } from '../harness.js';
import { sphereFaceCount, sphereWithFaces } from './build.js';

export function smoothDecimateCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const faces = sphereFaceCount(size);
    const targetFaces = Math.round(faces / 10);
    const repeat = size >= 1e6 ? 2 : 5;
    let sphere: HalfedgeMesh;
    let toSmooth: HalfedgeMesh;
    let indices: Uint32Array;
    let positions: Float32Array;
    return [
      {
        case: 'decimate',
        size: faces,
        repeat,
        async prepare() {
          const soup = sphereWithFaces(size);
          sphere = buildMesh(soup).mesh;
          indices = Uint32Array.from(soup.faceIndices);
          positions = new Float32Array(soup.positions);
          await MeshoptSimplifier.ready;
        },
        run() {
          const mesh = sphere.clone();
          decimate(mesh, { targetFaces });
          return mesh;
        },
        peer: { name: 'meshoptimizer', run: () => MeshoptSimplifier.simplify(indices, positions, 3, 3 * targetFaces, 1) },
      },
      {
        case: 'smooth-taubin',
        size: faces,
        repeat,
        prepare() {
          toSmooth = buildMesh(sphereWithFaces(size)).mesh;
        },
        run() {
          const mesh = toSmooth.clone();
          smooth(mesh, { method: 'taubin', iterations: 10 });
          return mesh;
        },
      },
    ];
  });
}
