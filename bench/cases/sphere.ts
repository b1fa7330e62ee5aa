/** The benchmarks' usual input: a closed latitude–longitude sphere of triangles, of a given size. */
import { type PolygonSoup, uvSphere } from '../../src/index.js';

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
