// Collapse face input to one vertex at its centroid: its corners merge, its edges and the face go,
// and a triangle beside it disappears, its two other edges becoming one.
export default function (mesh, f) {
  const sides = [];
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    sides.push(h);
    h = mesh.next(h);
  } while (h !== start);
  const k = sides.length;
  const corners = sides.map((s) => mesh.origin(s));
  const across = sides.map((s) => mesh.face(mesh.twin(s)));
  const degree = (g) => {
    let n = 0;
    const first = mesh.faceHalfedge(g);
    let x = first;
    do {
      n++;
      x = mesh.next(x);
    } while (x !== first);
    return n;
  };

  // when not to collapse
  const along = new Map(); // face → how many sides of f it lies along
  for (const g of across) if (g !== -1) along.set(g, (along.get(g) ?? 0) + 1);
  for (const [g, count] of along) if (count > 1 && degree(g) - count < 3) return -1;
  const triangles = sides.map((s, i) => across[i] !== -1 && along.get(across[i]) === 1 && degree(across[i]) === 3);
  // the spokes of corner i: the halfedges leaving it between f's two edges there, counter-clockwise
  const spokes = [];
  for (let i = 0; i < k; i++) {
    const list = [];
    let s = mesh.twin(mesh.prev(mesh.twin(sides[(i + k - 1) % k])));
    while (s !== sides[i]) {
      if (corners.includes(mesh.target(s))) return -1; // an edge between two corners would become a loop
      list.push(s);
      s = mesh.twin(mesh.prev(s));
    }
    spokes.push(list);
  }
  const ring = spokes.flat();
  if (ring.length === 0) return -1; // f is alone: there is nothing to collapse into
  // around the new vertex, a spoke merges with the next one across a triangle beside f
  const merges = spokes.flatMap((list, i) => list.map((_, j) => j === list.length - 1 && triangles[i]));
  const begin = merges.indexOf(false) + 1;
  if (begin === 0) return -1; // triangles all round, meeting at one vertex
  const reached = new Set();
  const wedges = [];
  let groups = 0;
  for (let n = 0; n < ring.length; n++) {
    const index = (begin + n) % ring.length;
    const s = ring[index];
    if (!(n > 0 && merges[(index + ring.length - 1) % ring.length])) {
      groups++;
      if (reached.has(mesh.target(s))) return -1; // the link condition: joined to the new vertex twice
      reached.add(mesh.target(s));
    }
    if (!merges[index]) {
      if (wedges.includes(mesh.face(s))) return -1; // a face (or the hole) at two places around it
      wedges.push(mesh.face(s));
    }
  }
  if (groups < 2) return -1; // a single edge would be left
  const left = (g) => (g === -1 ? 0 : degree(g) - (along.get(g) ?? 0));
  if (groups === 2 && left(wedges[0]) === 3 && left(wedges[1]) === 3) return -1; // two triangles on the same corners

  // the collapse
  const m = corners[0];
  const points = corners.map((v) => mesh.position(v));
  mesh.setPosition(m, [0, 1, 2].map((a) => points.reduce((sum, p) => sum + p[a], 0) / k));
  for (let i = 1; i < k; i++) for (const s of spokes[i]) mesh.setOrigin(s, m);
  for (let i = 0; i < k; i++) {
    const t = mesh.twin(sides[i]);
    if (triangles[i]) {
      // the triangle (v_i+1, v_i, c) goes: v_i → c takes the place of v_i+1 → c, now the same edge
      const gone = mesh.twin(mesh.prev(t));
      const kept = mesh.next(t);
      const beyond = mesh.face(gone);
      mesh.setNext(mesh.prev(gone), kept);
      mesh.setNext(kept, mesh.next(gone));
      mesh.setFace(kept, beyond);
      if (beyond !== -1 && mesh.faceHalfedge(beyond) === gone) mesh.setFaceHalfedge(beyond, kept);
      const c = mesh.origin(mesh.twin(gone));
      if (mesh.vertexHalfedge(c) === mesh.twin(gone)) mesh.setVertexHalfedge(c, mesh.twin(kept));
      mesh.deleteEdge(mesh.edge(gone));
      continue;
    }
    // a face (or the hole) across side i just loses it
    if (across[i] !== -1 && mesh.faceHalfedge(across[i]) === t) mesh.setFaceHalfedge(across[i], mesh.next(t));
    mesh.setNext(mesh.prev(t), mesh.next(t));
  }
  for (const s of sides) mesh.deleteEdge(mesh.edge(s));
  mesh.deleteFace(f);
  for (let i = 0; i < k; i++) if (triangles[i]) mesh.deleteFace(across[i]);
  for (let i = 1; i < k; i++) mesh.deleteVertex(corners[i]);
  // the new vertex's halfedge: a boundary one if it has one
  const live = new Set(mesh.halfedges());
  const left_ = ring.filter((s) => live.has(s));
  mesh.setVertexHalfedge(m, left_.find((s) => mesh.isBoundary(s)) ?? left_[0]);
  return m;
}
