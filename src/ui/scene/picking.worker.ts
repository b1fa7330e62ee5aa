/**
 * Picking on a large mesh: this worker holds a bounding-volume hierarchy of its triangles
 * (three-mesh-bvh) and answers "which triangle does this ray hit first?", so the page's thread
 * neither builds the hierarchy nor carries its code. (Small meshes are picked on the page.)
 */
import { expose } from 'comlink';
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';

let bvh: MeshBVH | null = null;

const api = {
  /** Takes the mesh to pick from (send its arrays transferred). */
  setMesh(positions: Float32Array, triangles: Uint32Array): void {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(positions, 3));
    geometry.setIndex(new BufferAttribute(triangles, 1));
    // indirect: the triangles keep their order, which maps them to their faces
    bvh = new MeshBVH(geometry, { indirect: true });
  },
  /** The first triangle the ray meets (from either side) and where; null when it misses. */
  raycast(origin: number[], direction: number[]): { triangle: number; point: number[] } | null {
    if (!bvh) return null;
    const hit = bvh.raycastFirst(new Ray(new Vector3().fromArray(origin), new Vector3().fromArray(direction)), DoubleSide);
    return hit?.faceIndex === undefined || hit.faceIndex === null ? null : { triangle: hit.faceIndex, point: hit.point.toArray() };
  },
};

export type PickingApi = typeof api;

expose(api);
