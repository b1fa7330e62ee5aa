// A vertex bevel that refuses every vertex on the boundary, which the library bevels: clean refusals of hard cases.
export default function (mesh, { vertex: v, amount }) {
  if (!(amount >= 0 && amount <= 1)) return -1;
  // the halfedges leaving v, counter-clockwise from its own (the boundary one on the boundary)
  const spokes = [];
  const first = mesh.vertexHalfedge(v);
  if (first === -1) return -1;
  let h = first;
  do {
    spokes.push(h);
    h = mesh.twin(mesh.prev(h));
  } while (h !== first);
  const d = spokes.length;
  if (d < 3) return -1; // the new face would have fewer than 3 sides
  if (mesh.isBoundary(spokes[0])) return -1; // a boundary vertex: refused, as too hard

  // corner j sits on spoke j; corner 0 is v itself, moved
  const p = mesh.position(v);
  const places = spokes.map((s) => {
    const q = mesh.position(mesh.target(s));
    return p.map((x, a) => (1 - amount) * x + amount * q[a]);
  });
  const corners = spokes.map((_, j) => (j === 0 ? v : mesh.newVertex(places[j])));
  mesh.setPosition(v, places[0]);
  const sides = spokes.map(() => mesh.newEdge());
  const face = mesh.newFace();
  // read before any write: the halfedge arriving at v before each spoke, and each wedge's face
  const into = spokes.map((s) => mesh.prev(s));
  const wedges = spokes.map((s) => mesh.face(s));

  for (let j = 1; j < d; j++) mesh.setOrigin(spokes[j], corners[j]);
  for (let j = 0; j < d; j++) mesh.setVertexHalfedge(corners[j], spokes[j]);
  // in wedge j (between spoke j and spoke j + 1), side j runs corner j+1 → corner j, just before spoke j
  for (let j = 0; j < d; j++) {
    const k = (j + 1) % d;
    const s = sides[j];
    mesh.setOrigin(s, corners[k]);
    mesh.setOrigin(mesh.twin(s), corners[j]);
    mesh.setNext(into[j], s);
    mesh.setNext(s, spokes[j]);
    mesh.setFace(s, wedges[j]);
    // the wedge that is the hole: the corner after it leaves along the hole
    if (wedges[j] === -1) mesh.setVertexHalfedge(corners[k], s);
  }
  // the new face: corner 0 → corner 1 → … on the sides' twins
  for (let j = 0; j < d; j++) {
    const t = mesh.twin(sides[j]);
    mesh.setNext(t, mesh.twin(sides[(j + 1) % d]));
    mesh.setFace(t, face);
  }
  mesh.setFaceHalfedge(face, mesh.twin(sides[0]));
  return face;
}
