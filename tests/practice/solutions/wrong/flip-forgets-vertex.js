// A flip that forgets that a and b lose an outgoing halfedge.
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  if (mesh.isBoundary(h) || mesh.isBoundary(t)) return false;
  const hn = mesh.next(h), hp = mesh.prev(h);
  const tn = mesh.next(t), tp = mesh.prev(t);
  if (mesh.next(mesh.next(hn)) !== h || mesh.next(mesh.next(tn)) !== t) return false;
  const c = mesh.origin(hp), d = mesh.origin(tp);
  let g = mesh.vertexHalfedge(c);
  const first = g;
  do {
    if (mesh.target(g) === d) return false;
    g = mesh.twin(mesh.prev(g));
  } while (g !== first);
  const f0 = mesh.face(h), f1 = mesh.face(t);
  mesh.setNext(h, hp);
  mesh.setNext(hp, tn);
  mesh.setNext(tn, h);
  mesh.setNext(t, tp);
  mesh.setNext(tp, hn);
  mesh.setNext(hn, t);
  mesh.setOrigin(h, d);
  mesh.setOrigin(t, c);
  mesh.setFace(tn, f0);
  mesh.setFace(hn, f1);
  mesh.setFaceHalfedge(f0, h);
  mesh.setFaceHalfedge(f1, t);
  return true;
}
