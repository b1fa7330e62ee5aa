export default function (mesh) {
  return mesh.vertexCount() - mesh.edgeCount() + mesh.faceCount();
}
