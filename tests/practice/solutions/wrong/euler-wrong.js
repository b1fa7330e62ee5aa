export default function (mesh) {
  return mesh.vertexCount() - mesh.halfedgeCount() + mesh.faceCount();
}
