// One level of Loop subdivision, in place: positions from the old mesh first, then the new topology.
export default function (mesh) {
  const oldVertices = mesh.vertices();
  const oldEdges = mesh.edges();
  const oldFaces = mesh.faces();
  const add = (p, q, w) => p.map((x, i) => x + w * q[i]);
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

  // even points: the old vertices, moved
  const moved = new Map();
  for (const v of oldVertices) {
    const around = outgoing(v);
    const p = mesh.position(v);
    const boundary = around.find((g) => mesh.isBoundary(g));
    let q;
    if (boundary !== undefined && around.length === 2) {
      q = p; // a corner of one triangle keeps its place
    } else if (boundary !== undefined) {
      q = p.map((x) => 0.75 * x);
      q = add(q, mesh.position(mesh.target(boundary)), 1 / 8);
      q = add(q, mesh.position(mesh.origin(mesh.prev(boundary))), 1 / 8);
    } else {
      const n = around.length;
      const beta = (5 / 8 - (3 / 8 + Math.cos((2 * Math.PI) / n) / 4) ** 2) / n;
      q = p.map((x) => (1 - n * beta) * x);
      for (const g of around) q = add(q, mesh.position(mesh.target(g)), beta);
    }
    moved.set(v, q);
  }

  // odd points: one per old edge, all from the old mesh (a split changes the corners of its faces)
  const isOld = new Set(oldVertices);
  const odd = oldEdges.map((e) => {
    const h = mesh.edgeHalfedge(e);
    const t = mesh.twin(h);
    const a = mesh.position(mesh.origin(h));
    const b = mesh.position(mesh.origin(t));
    let p;
    if (mesh.isBoundary(h) || mesh.isBoundary(t)) p = add(a.map((x) => x / 2), b, 1 / 2);
    else {
      p = add(a.map((x) => (3 / 8) * x), b, 3 / 8);
      p = add(p, mesh.position(mesh.origin(mesh.prev(h))), 1 / 8);
      p = add(p, mesh.position(mesh.origin(mesh.prev(t))), 1 / 8);
    }
    return p;
  });
  oldEdges.forEach((e, i) => splitEdge(mesh, mesh.edgeHalfedge(e), odd[i]));

  // each old triangle is now a hexagon a, m_ab, b, m_bc, c, m_ca: cut it into four
  for (const f of oldFaces) {
    let h0 = mesh.faceHalfedge(f);
    if (!isOld.has(mesh.origin(h0))) h0 = mesh.next(h0);
    const [, h1, h2, h3, h4, h5] = [h0, 1, 2, 3, 4, 5].reduce((list, _, i) => (i === 0 ? list : [...list, mesh.next(list[i - 1])]), [h0]);
    const mab = mesh.origin(h1), mbc = mesh.origin(h3), mca = mesh.origin(h5);
    const n1 = edgeBetween(mesh, mab, mca);
    const n2 = edgeBetween(mesh, mbc, mab);
    const n3 = edgeBetween(mesh, mca, mbc);
    triangle(mesh, [h0, n1, h5], mesh.newFace());
    triangle(mesh, [h2, n2, h1], mesh.newFace());
    triangle(mesh, [h4, n3, h3], mesh.newFace());
    triangle(mesh, [mesh.twin(n2), mesh.twin(n3), mesh.twin(n1)], f);
  }
  for (const [v, q] of moved) mesh.setPosition(v, q);
}

/** A new edge u → v (returns the halfedge from u). */
function edgeBetween(mesh, u, v) {
  const h = mesh.newEdge();
  mesh.setOrigin(h, u);
  mesh.setOrigin(mesh.twin(h), v);
  return h;
}

function triangle(mesh, sides, f) {
  sides.forEach((s, i) => {
    mesh.setNext(s, sides[(i + 1) % 3]);
    mesh.setFace(s, f);
  });
  mesh.setFaceHalfedge(f, sides[0]);
}

/** h: a → b becomes a → m → b; the faces on both sides gain a side. */
function splitEdge(mesh, h, p) {
  const t = mesh.twin(h);
  const b = mesh.origin(t);
  const m = mesh.newVertex(p);
  const hn = mesh.next(h);
  const tp = mesh.prev(t);
  const g = edgeBetween(mesh, m, b);
  const gt = mesh.twin(g);
  mesh.setOrigin(t, m);
  mesh.setNext(h, g);
  mesh.setNext(g, hn);
  mesh.setFace(g, mesh.face(h));
  mesh.setNext(tp, gt);
  mesh.setNext(gt, t);
  mesh.setFace(gt, mesh.face(t));
  if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, gt);
  mesh.setVertexHalfedge(m, mesh.isBoundary(t) ? t : g);
}
