export default function (mesh, v) {
  return mesh.vertexHalfedge(v;
}
