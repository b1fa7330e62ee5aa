/**
 * How far a decimated mesh strays from its original: from every vertex of the original to the
 * nearest point of the result's surface (a bounding-volume hierarchy over the result's triangles,
 * three-mesh-bvh). The largest of these is the one-sided Hausdorff distance measured at the
 * original's vertices; the mean says how close the result stays on the whole.
 */
import { BufferAttribute, BufferGeometry, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';

/**
 * `points`: x, y, z of each original vertex; `positions` and `indices`: the result's triangles.
 * Returns `{ max, mean }` in the mesh's units.
 */
export function distanceToSurface(points, positions, indices) {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(Float32Array.from(positions), 3));
  geometry.setIndex(new BufferAttribute(Uint32Array.from(indices), 1));
  const bvh = new MeshBVH(geometry);
  const point = new Vector3();
  const nearest = { point: new Vector3(), distance: 0, faceIndex: 0 };
  let max = 0;
  let sum = 0;
  const n = points.length / 3;
  for (let i = 0; i < n; i++) {
    point.set(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    bvh.closestPointToPoint(point, nearest);
    max = Math.max(max, nearest.distance);
    sum += nearest.distance;
  }
  return { max, mean: sum / n };
}

/** The corner indices of every live triangle of a halfedge mesh (its vertex slots as they are). */
export function triangleIndices(mesh) {
  const indices = new Uint32Array(3 * mesh.nFaces);
  let k = 0;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (mesh.fDeleted[f]) continue;
    const h = mesh.fHalfedge[f];
    indices[k++] = mesh.heVertex[h];
    indices[k++] = mesh.heVertex[mesh.heNext[h]];
    indices[k++] = mesh.heVertex[mesh.heNext[mesh.heNext[h]]];
  }
  return indices;
}
