/** Building the halfedge mesh from a soup, beside three-mesh-halfedge building the same triangles. */
import { BufferAttribute, BufferGeometry } from 'three';
import { HalfedgeDS } from 'three-mesh-halfedge/build/index.esm.js';
import type { BenchCase } from '../harness.js';
import { buildMesh, type BuildResult, HalfedgeMesh, type PolygonSoup, torus, uvSphere } from '../../src/index.js';

/** A closed latitude–longitude sphere with about `faces` triangles. */
export function sphereWithFaces(faces: number): PolygonSoup {
  const slices = Math.round(Math.sqrt(faces));
  return uvSphere(Math.round(faces / (2 * slices)) + 1, slices);
}

export function meshBytes(mesh: HalfedgeMesh): number {
  const arrays = [mesh.heNext, mesh.hePrev, mesh.heVertex, mesh.heFace, mesh.vHalfedge, mesh.fHalfedge];
  const flags = [mesh.vDeleted, mesh.eDeleted, mesh.fDeleted];
  return [...arrays, ...flags, mesh.positions].reduce((sum, a) => sum + a.byteLength, 0);
}

export function buildCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size): BenchCase[] => {
    const sphere = sphereWithFaces(size);
    const side = Math.round(Math.sqrt(size));
    const quads = torus(side, side);
    let geometry: BufferGeometry;
    return [
      {
        case: 'build-sphere',
        size: sphere.faceStarts.length - 1,
        repeat: size >= 1e6 ? 3 : 7,
        prepare() {
          geometry = new BufferGeometry();
          geometry.setAttribute('position', new BufferAttribute(new Float32Array(sphere.positions), 3));
          geometry.setIndex(new BufferAttribute(sphere.faceIndices, 1));
        },
        run: () => buildMesh(sphere),
        bytes: (result) => meshBytes((result as BuildResult).mesh),
        peer: { name: 'three-mesh-halfedge', run: () => new HalfedgeDS().setFromGeometry(geometry) },
      },
      {
        case: 'build-torus-quads',
        size: quads.faceStarts.length - 1,
        repeat: size >= 1e6 ? 3 : 7,
        run: () => buildMesh(quads),
        bytes: (result) => meshBytes((result as BuildResult).mesh),
      },
    ];
  });
}
