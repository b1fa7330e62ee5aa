// Weld boundary edges input[0] and input[1] into one edge, their ends merged pairwise at midpoints.
export default function (mesh, [e1, e2]) {
  if (e1 === e2) return false;
  const boundaryHalfedge = (e) => {
    const h = mesh.edgeHalfedge(e);
    return mesh.isBoundary(h) ? h : mesh.isBoundary(mesh.twin(h)) ? mesh.twin(h) : -1;
  };
  const h1 = boundaryHalfedge(e1); // a1 → b1, on the hole
  const h2 = boundaryHalfedge(e2); // a2 → b2, on the hole
  if (h1 === -1 || h2 === -1) return false; // only boundary edges can be welded
  const t2 = mesh.twin(h2);
  const [a1, b1, a2, b2] = [mesh.origin(h1), mesh.target(h1), mesh.origin(h2), mesh.target(h2)];
  if (a1 === b2 && b1 === a2) return false;
  const leaving = (first) => {
    const out = [];
    let x = first;
    do {
      out.push(x);
      x = mesh.twin(mesh.prev(x));
    } while (x !== first);
    return out;
  };
  // b2 merges into a1 and a2 into b1 (the orientation of the two faces decides the pairing)
  const merged = (u) => (u === b2 ? a1 : u === a2 ? b1 : u);
  for (const [x, y] of [[a1, b2], [b1, a2]]) {
    if (x === y) continue; // a zip: the two edges share this end
    const aroundX = leaving(mesh.vertexHalfedge(x));
    const aroundY = leaving(mesh.vertexHalfedge(y));
    if (aroundX.some((g) => mesh.target(g) === y)) return false; // their edge would become a loop
    const facesY = aroundY.map((g) => mesh.face(g)).filter((f) => f !== -1);
    if (aroundX.some((g) => mesh.face(g) !== -1 && facesY.includes(mesh.face(g)))) return false; // a face through both
    const ends = [];
    for (const g of [...aroundX, ...aroundY]) {
      if (mesh.edge(g) === e2) continue;
      const z = merged(mesh.target(g));
      if (ends.includes(z)) return false; // two edges between the same two vertices
      ends.push(z);
    }
  }

  // read before writing
  const [p1, n1, p2, n2] = [mesh.prev(h1), mesh.next(h1), mesh.prev(h2), mesh.next(h2)];
  const f2 = mesh.face(t2);
  const [beforeT2, afterT2] = [mesh.prev(t2), mesh.next(t2)];
  const zipAtB1 = b1 === a2;
  const zipAtA1 = a1 === b2;
  const fromB2 = zipAtA1 ? [] : leaving(t2).slice(1);
  const fromA2 = zipAtB1 ? [] : leaving(h2).slice(1);
  const mid = (u, v) => {
    const [p, q] = [mesh.position(u), mesh.position(v)];
    return [(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2];
  };

  if (!zipAtA1) mesh.setPosition(a1, mid(a1, b2));
  if (!zipAtB1) mesh.setPosition(b1, mid(b1, a2));
  for (const g of fromB2) mesh.setOrigin(g, a1);
  for (const g of fromA2) mesh.setOrigin(g, b1);
  // h1 leaves the hole and takes t2's place in its face
  mesh.setNext(beforeT2, h1);
  mesh.setNext(h1, afterT2);
  mesh.setFace(h1, f2);
  if (mesh.faceHalfedge(f2) === t2) mesh.setFaceHalfedge(f2, h1);
  // the hole runs on past the weld (at a zip's shared vertex it closes)
  if (!zipAtB1) mesh.setNext(p2, n1);
  if (!zipAtA1) mesh.setNext(p1, n2);
  mesh.deleteEdge(e2);
  if (!zipAtA1) mesh.deleteVertex(b2);
  if (!zipAtB1) mesh.deleteVertex(a2);
  // each merged vertex leaves along its boundary halfedge if it still has one
  for (const [v, from] of [[a1, h1], [b1, mesh.twin(h1)]]) {
    const around = leaving(from);
    mesh.setVertexHalfedge(v, around.find((g) => mesh.isBoundary(g)) ?? from);
  }
  return true;
}
