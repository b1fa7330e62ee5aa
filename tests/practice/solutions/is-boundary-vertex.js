export default function (mesh, v) {
  const start = mesh.vertexHalfedge(v);
  let h = start;
  do {
    if (mesh.isBoundary(h)) return true;
    h = mesh.twin(mesh.prev(h));
  } while (h !== start);
  return false;
}
