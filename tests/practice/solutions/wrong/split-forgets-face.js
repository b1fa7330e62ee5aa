// A split that makes the new faces but never gives them a halfedge.
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  const b = mesh.origin(t);
  const [pa, pb] = [mesh.position(mesh.origin(h)), mesh.position(b)];
  const m = mesh.newVertex([(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2]);
  const hn = mesh.next(h), hp = mesh.prev(h), tn = mesh.next(t), tp = mesh.prev(t);
  const g = mesh.newEdge();
  const gt = mesh.twin(g);
  mesh.setOrigin(g, m);
  mesh.setOrigin(gt, b);
  mesh.setOrigin(t, m);
  mesh.setNext(h, g);
  mesh.setNext(g, hn);
  mesh.setFace(g, mesh.face(h));
  mesh.setNext(tp, gt);
  mesh.setNext(gt, t);
  mesh.setFace(gt, mesh.face(t));
  if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, gt);
  mesh.setVertexHalfedge(m, mesh.isBoundary(t) ? t : g);
  const cut = (x0, x1, x2, x3) => {
    const k = mesh.newEdge();
    mesh.setOrigin(k, mesh.origin(x2));
    mesh.setOrigin(mesh.twin(k), m);
    mesh.setNext(x0, x1);
    mesh.setNext(x1, k);
    mesh.setNext(k, x0);
    mesh.setFace(k, mesh.face(x0));
    const f = mesh.newFace();
    mesh.setNext(x2, x3);
    mesh.setNext(x3, mesh.twin(k));
    mesh.setNext(mesh.twin(k), x2);
    for (const x of [x2, x3, mesh.twin(k)]) mesh.setFace(x, f);
  };
  if (!mesh.isBoundary(h)) cut(g, hn, hp, h);
  if (!mesh.isBoundary(t)) cut(t, tn, tp, gt);
  return m;
}
