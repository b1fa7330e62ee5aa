// The flip of the library (src/core/edits/flip.ts), in the practice API.
//        c                       c
//      /   \                   / | \
//    a --h-> b      -->      a   h   b      h now runs d -> c
//      \   /                   \ | /
//        d                       d
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  if (mesh.isBoundary(h) || mesh.isBoundary(t)) return false;
  const hn = mesh.next(h), hp = mesh.prev(h);
  const tn = mesh.next(t), tp = mesh.prev(t);
  if (mesh.next(hp) !== h || mesh.next(mesh.next(hn)) !== h) return false;
  if (mesh.next(mesh.next(tn)) !== t) return false;
  const a = mesh.origin(h), b = mesh.origin(t);
  const c = mesh.origin(hp), d = mesh.origin(tp);
  if (c === d) return false;
  // refuse when c and d are already joined
  let g = mesh.vertexHalfedge(c);
  const first = g;
  do {
    if (mesh.target(g) === d) return false;
    g = mesh.twin(mesh.prev(g));
  } while (g !== first);
  const f0 = mesh.face(h), f1 = mesh.face(t);
  // f0 becomes d -> c -> a: h, hp, tn
  mesh.setNext(h, hp);
  mesh.setNext(hp, tn);
  mesh.setNext(tn, h);
  // f1 becomes c -> d -> b: t, tp, hn
  mesh.setNext(t, tp);
  mesh.setNext(tp, hn);
  mesh.setNext(hn, t);
  mesh.setOrigin(h, d);
  mesh.setOrigin(t, c);
  mesh.setFace(tn, f0);
  mesh.setFace(hn, f1);
  mesh.setFaceHalfedge(f0, h);
  mesh.setFaceHalfedge(f1, t);
  if (mesh.vertexHalfedge(a) === h) mesh.setVertexHalfedge(a, tn);
  if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, hn);
  return true;
}
