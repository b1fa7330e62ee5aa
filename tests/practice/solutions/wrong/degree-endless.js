// Turns with next(twin(h)) instead of twin(prev(h)): around a face, never back to the start.
export default function (mesh, v) {
  const start = mesh.vertexHalfedge(v);
  let count = 0;
  let h = mesh.twin(start);
  while (h !== start) {
    count++;
    h = mesh.next(h);
  }
  return count;
}
