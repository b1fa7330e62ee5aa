export default function (mesh, v) {
  const ring = [];
  const start = mesh.vertexHalfedge(v);
  let h = start;
  do {
    ring.push(mesh.target(h));
    h = mesh.twin(mesh.prev(h));
  } while (h !== start);
  return ring;
}
