export default function (mesh) {
  let count = 0;
  for (const e of mesh.edges()) {
    const h = mesh.edgeHalfedge(e);
    if (mesh.isBoundary(h) || mesh.isBoundary(mesh.twin(h))) count++;
  }
  return count;
}
