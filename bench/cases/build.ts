/** Building the halfedge mesh from a soup, beside three-mesh-halfedge building the same triangles. */
import { BufferAttribute, BufferGeometry } from 'three';
import { HalfedgeDS } from 'three-mesh-halfedge/build/index.esm.js';
import type { BenchCase } from '../harness.js';
import { type BuildResult, type PolygonSoup, torus } from '../../src/index.js';
import { buildMesh, meshByteLength } from '../library.js';
import { sphereFaceCount, sphereWithFaces } from './sphere.js';

export function buildCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const side = Math.round(Math.sqrt(size));
    let sphere: PolygonSoup;
    let quads: PolygonSoup;
    let geometry: BufferGeometry;
    return [
      {
        case: 'build-sphere',
        size: sphereFaceCount(size),
        repeat: 7,
        prepare(side) {
          sphere = sphereWithFaces(size);
          if (side === 'ours') return;
          geometry = new BufferGeometry();
          geometry.setAttribute('position', new BufferAttribute(new Float32Array(sphere.positions), 3));
          geometry.setIndex(new BufferAttribute(sphere.faceIndices, 1));
        },
        run: () => buildMesh(sphere),
        bytes: (result) => meshByteLength((result as BuildResult).mesh),
        peer: { name: 'three-mesh-halfedge', run: () => new HalfedgeDS().setFromGeometry(geometry) },
      },
      {
        case: 'build-torus-quads',
        size: side * side,
        repeat: 7,
        prepare: () => void (quads = torus(side, side)),
        run: () => buildMesh(quads),
        bytes: (result) => meshByteLength((result as BuildResult).mesh),
      },
    ];
  });
}
