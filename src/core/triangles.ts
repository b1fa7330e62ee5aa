/** The check of every algorithm that works on triangles only (Loop, Butterfly, √3, cotangent weights, decimation). */
import type { HalfedgeMesh } from './mesh.js';

/**
 * "`method` needs triangles; f3 is a quad." for the first live face that is not a triangle, or
 * null when every face is one.
 * @example needsTriangles(buildMesh(cube()).mesh, 'decimation') // "decimation needs triangles; f0 is a quad."
 */
export function needsTriangles(mesh: HalfedgeMesh, method: string): string | null {
  const { heNext, fHalfedge, fDeleted } = mesh;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const h = fHalfedge[f];
    if (heNext[heNext[heNext[h]]] !== h) return `${method} needs triangles; f${f} is ${polygonName(mesh.faceDegree(f))}.`;
  }
  return null;
}

function polygonName(degree: number): string {
  const names: Record<number, string> = { 4: 'a quad', 5: 'a pentagon', 6: 'a hexagon' };
  return names[degree] ?? `a polygon of ${degree} sides`;
}
