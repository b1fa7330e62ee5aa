// Collapse edge e of a triangle mesh: b = target(h) merges into a = origin(h), at the midpoint.
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  const a = mesh.origin(h);
  const b = mesh.origin(t);
  const f0 = mesh.face(h);
  const f1 = mesh.face(t);
  const outgoing = (v) => {
    const out = [];
    const first = mesh.vertexHalfedge(v);
    let g = first;
    do {
      out.push(g);
      g = mesh.twin(mesh.prev(g));
    } while (g !== first);
    return out;
  };
  const onBoundary = (v) => outgoing(v).some((g) => mesh.isBoundary(g));

  // when not to collapse
  if (f0 !== -1 && f1 !== -1 && onBoundary(a) && onBoundary(b)) return -1;
  const c = f0 !== -1 ? mesh.origin(mesh.prev(h)) : -1;
  const d = f1 !== -1 ? mesh.origin(mesh.prev(t)) : -1;
  if (c !== -1 && c === d) return -1;
  for (const g of [h, t]) {
    if (!mesh.isBoundary(g) && mesh.isBoundary(mesh.twin(mesh.next(g))) && mesh.isBoundary(mesh.twin(mesh.prev(g)))) return -1;
  }
  const neighboursOfB = outgoing(b).map((g) => mesh.target(g));
  for (const g of outgoing(a)) {
    const y = mesh.target(g);
    if (y === b && g !== h) return -1;
    if (y !== b && y !== c && y !== d && neighboursOfB.includes(y)) return -1; // the link condition
  }
  if (c !== -1 && d !== -1) {
    const acrossA = mesh.face(mesh.twin(mesh.prev(h)));
    const acrossB = mesh.face(mesh.twin(mesh.next(h)));
    if (acrossA !== -1 && acrossA === mesh.face(mesh.twin(mesh.next(t))) && acrossB !== -1 && acrossB === mesh.face(mesh.twin(mesh.prev(t)))) return -1;
  }

  const [pa, pb] = [mesh.position(a), mesh.position(b)];
  const hn = mesh.next(h), hp = mesh.prev(h);
  const tn = mesh.next(t), tp = mesh.prev(t);
  const dying = new Set([t]);
  if (f0 !== -1) dying.add(hn);
  if (f1 !== -1) dying.add(mesh.twin(tp));
  const leavingB = outgoing(b).filter((g) => !dying.has(g));

  if (f0 !== -1) {
    // triangle a → b → c goes; hp (c → a) takes the place of x (c → b) in the face beyond
    const x = mesh.twin(hn);
    const beyond = mesh.face(x);
    mesh.setNext(mesh.prev(x), hp);
    mesh.setNext(hp, mesh.next(x));
    mesh.setFace(hp, beyond);
    if (beyond !== -1 && mesh.faceHalfedge(beyond) === x) mesh.setFaceHalfedge(beyond, hp);
    if (mesh.vertexHalfedge(c) === x) mesh.setVertexHalfedge(c, hp);
    mesh.deleteEdge(mesh.edge(hn));
    mesh.deleteFace(f0);
  } else {
    mesh.setNext(hp, hn);
  }
  if (f1 !== -1) {
    // triangle b → a → d goes; tn (a → d) takes the place of w (b → d) in the face beyond
    const w = mesh.twin(tp);
    const beyond = mesh.face(w);
    mesh.setNext(mesh.prev(w), tn);
    mesh.setNext(tn, mesh.next(w));
    mesh.setFace(tn, beyond);
    if (beyond !== -1 && mesh.faceHalfedge(beyond) === w) mesh.setFaceHalfedge(beyond, tn);
    if (mesh.vertexHalfedge(d) === tp) mesh.setVertexHalfedge(d, mesh.twin(tn));
    mesh.deleteEdge(mesh.edge(tp));
    mesh.deleteFace(f1);
  } else {
    // prev(t), not tp: where f0 had a second boundary side, that side went, and t's prev with it
    mesh.setNext(mesh.prev(t), tn);
  }
  for (const g of leavingB) mesh.setOrigin(g, a);
  mesh.deleteEdge(e);
  mesh.deleteVertex(b);
  mesh.setPosition(a, [(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2]);
  // a's halfedge: one that still leaves it, the boundary one if it has one
  // (c → a, or on the boundary side a → d: hn may have gone with an ear of f1)
  const around = rotate(mesh, f0 !== -1 ? mesh.twin(hp) : tn);
  mesh.setVertexHalfedge(a, around.find((g) => mesh.isBoundary(g)) ?? around[0]);
  return a;
}

function rotate(mesh, first) {
  const out = [];
  let g = first;
  do {
    out.push(g);
    g = mesh.twin(mesh.prev(g));
  } while (g !== first);
  return out;
}
