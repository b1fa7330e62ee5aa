/** Building the halfedge mesh from a soup, beside three-mesh-halfedge building the same triangles. */
import { BufferAttribute, BufferGeometry } from 'three';
import { HalfedgeDS } from 'three-mesh-halfedge/build/index.esm.js';
import type { BenchCase } from '../harness.js';
import { buildMesh, type BuildResult, meshByteLength, type PolygonSoup, torus, uvSphere } from '../../src/index.js';

/** Slices and stacks of a latitude–longitude sphere with about `faces` triangles. */
function sphereShape(faces: number): { stacks: number; slices: number } {
  const slices = Math.round(Math.sqrt(faces));
  return { stacks: Math.round(faces / (2 * slices)) + 1, slices };
}

/** A closed latitude–longitude sphere with about `faces` triangles. */
export function sphereWithFaces(faces: number): PolygonSoup {
  const { stacks, slices } = sphereShape(faces);
  return uvSphere(stacks, slices);
}

/** The exact number of triangles `sphereWithFaces(faces)` has, without making it. */
export function sphereFaceCount(faces: number): number {
  const { stacks, slices } = sphereShape(faces);
  return 2 * slices * (stacks - 1);
}

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
