// Counts every halfedge at the vertex, in and out: each edge twice.
export default function (mesh, v) {
  let count = 0;
  for (const h of mesh.halfedges()) {
    if (mesh.origin(h) === v || mesh.target(h) === v) count++;
  }
  return count;
}
