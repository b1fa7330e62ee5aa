export default function (mesh, v) {
  const h = mesh.vertexHalfedge(v);
  const notThere = null;
  return notThere.length + h;
}
