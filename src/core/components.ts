/**
 * Connected components: the parts of a mesh that no edge joins (two tetrahedra side by side, or
 * the two halves a plane cut leaves). Found by union–find over the edges, each part named by its
 * lowest vertex id, so the names do not depend on the order the edges are met in.
 */
import type { HalfedgeMesh } from './mesh.js';

/**
 * The part of each vertex slot, as the lowest vertex id in it: `root[v] === root[w]` exactly when
 * a path of live edges joins v and w. A vertex no edge touches (isolated or deleted) is its own root.
 * @example
 *   const root = componentRoots(buildMesh(mergeSoups([tetrahedron(), tetrahedron()])).mesh);
 *   // [0, 0, 0, 0, 4, 4, 4, 4]
 */
export function componentRoots(mesh: HalfedgeMesh): Int32Array {
  const { heVertex, eDeleted } = mesh;
  const root = new Int32Array(mesh.vertexSlots);
  for (let v = 0; v < root.length; v++) root[v] = v;
  // with path halving, which keeps the trees shallow without a second pass
  const find = (v: number): number => {
    while (root[v] !== v) {
      root[v] = root[root[v]];
      v = root[v];
    }
    return v;
  };
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (eDeleted[e]) continue;
    const a = find(heVertex[2 * e]);
    const b = find(heVertex[2 * e + 1]);
    // the lower id becomes the root: a part is named by its lowest vertex
    if (a !== b) root[a < b ? b : a] = a < b ? a : b;
  }
  for (let v = 0; v < root.length; v++) root[v] = find(v);
  return root;
}
