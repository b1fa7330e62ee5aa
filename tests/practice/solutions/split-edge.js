// Split edge e at its midpoint m, then cut each triangle beside it from m to its opposite corner.
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  const a = mesh.origin(h);
  const b = mesh.origin(t);
  const [pa, pb] = [mesh.position(a), mesh.position(b)];
  const m = mesh.newVertex([(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2]);
  splitSide(mesh, h, t, m, b);
  return m;
}

/** h: a → b becomes a → m; t: b → a becomes m → a; the new g: m → b and its twin b → m. */
function splitSide(mesh, h, t, m, b) {
  const hn = mesh.next(h);
  const tp = mesh.prev(t);
  const hp = mesh.prev(h);
  const tn = mesh.next(t);
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
  // f0 is now a → m → b → c: cut from m to c
  if (!mesh.isBoundary(h)) cut(mesh, g, hn, hp, h);
  // f1 is now b → m → a → d: cut from m to d
  if (!mesh.isBoundary(t)) cut(mesh, t, tn, tp, gt);
}

/**
 * The quad x0 → x1 → x2 → x3, where x0 leaves m and x2 leaves the corner c opposite m, is cut by
 * a new edge c → m: the triangle (x0, x1, c → m) keeps the face, (x2, x3, m → c) is a new one.
 */
function cut(mesh, x0, x1, x2, x3) {
  const f = mesh.face(x0);
  const m = mesh.origin(x0);
  const c = mesh.origin(x2);
  const k = mesh.newEdge();
  const kt = mesh.twin(k);
  mesh.setOrigin(k, c);
  mesh.setOrigin(kt, m);
  mesh.setNext(x0, x1);
  mesh.setNext(x1, k);
  mesh.setNext(k, x0);
  mesh.setFace(k, f);
  mesh.setFaceHalfedge(f, x0);
  const g = mesh.newFace();
  mesh.setNext(x2, x3);
  mesh.setNext(x3, kt);
  mesh.setNext(kt, x2);
  for (const x of [x2, x3, kt]) mesh.setFace(x, g);
  mesh.setFaceHalfedge(g, x2);
}
