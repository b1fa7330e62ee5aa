export default function (mesh, v) {
  const start = mesh.vertexHalfedge(v);
  if (start === -1) return 0;
  let count = 0;
  let h = start;
  do {
    count++;
    h = mesh.twin(mesh.prev(h));
  } while (h !== start);
  return count;
}
