/**
 * The capped plane cut through a closed sphere of triangles. The plane is tilted and off-centre,
 * so it meets no row of vertices: every edge it crosses is split. Each run cuts a fresh copy of
 * the mesh (the copy is part of the time: `clone` of a million triangles is a few tens of ms).
 */
import { buildMesh } from '../../src/core/build.js';
import { cutMesh, type KeepSide } from '../../src/core/cut/index.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import type { BenchCase } from '../harness.js';
import { sphereFaceCount, sphereWithFaces } from './build.js';

const PLANE = [0.1, 0.2, 1, -0.05] as const;

export function cutCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size) => {
    let sphere: HalfedgeMesh;
    const cutCopy = (keep: KeepSide) => () => {
      const mesh = sphere.clone();
      cutMesh(mesh, PLANE, { keep });
      return mesh;
    };
    const common = {
      size: sphereFaceCount(size),
      repeat: size >= 1e6 ? 5 : 9,
      prepare() {
        sphere = buildMesh(sphereWithFaces(size)).mesh;
      },
    };
    return [
      { ...common, case: 'cut-capped', run: cutCopy('both') },
      { ...common, case: 'cut-capped-keep-below', run: cutCopy('below') },
    ];
  });
}
