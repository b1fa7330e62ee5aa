// Dissolve vertex input: it and its edges go, and the faces around it merge into one
// (at a boundary vertex, closed by a new edge between its two neighbours along the boundary).
export default function (mesh, v) {
  const start = mesh.vertexHalfedge(v);
  if (start === -1) return -1;
  // the outgoing halfedges, counter-clockwise (the boundary one first on the boundary)
  const out = [];
  let x = start;
  do {
    out.push(x);
    x = mesh.twin(mesh.prev(x));
  } while (x !== start);
  const d = out.length;
  const boundary = mesh.isBoundary(out[0]);
  const first = boundary ? 1 : 0;
  if (boundary && d === 2) return -1; // one face: nothing to merge with

  // each face's far path runs from next(x) to prev(prev(x)); together they are the merged outline
  const firsts = out.map((g) => mesh.next(g));
  const entering = out.map((g) => mesh.prev(g));
  const lasts = entering.map((g) => mesh.prev(g));
  const faces = out.map((g) => mesh.face(g));
  const met = new Set();
  let sides = 0;
  for (let i = first; i < d; i++) {
    for (let g = firsts[i]; g !== entering[i]; g = mesh.next(g)) {
      const u = mesh.origin(g);
      if (met.has(u)) return -1; // the merged face would pass through u twice
      met.add(u);
      sides++;
    }
  }
  let a = -1;
  let b = -1;
  if (boundary) {
    // the hole runs a → v → b
    a = mesh.origin(entering[0]);
    b = mesh.target(out[0]);
    if (met.has(b)) return -1;
    sides++;
    const aroundA = [];
    const aStart = mesh.vertexHalfedge(a);
    let g = aStart;
    do {
      aroundA.push(mesh.target(g));
      g = mesh.twin(mesh.prev(g));
    } while (g !== aStart);
    if (aroundA.includes(b)) return -1; // a second edge between a and b
  }
  if (sides < 3) return -1;

  const face = faces[first];
  const handle = mesh.faceHalfedge(face);
  const neighbours = out.map((g) => mesh.target(g));
  const handles = neighbours.map((u) => mesh.vertexHalfedge(u));
  const holeBefore = boundary ? mesh.prev(entering[0]) : -1;
  const holeAfter = boundary ? mesh.next(out[0]) : -1;
  for (let i = first; i < d; i++) {
    if (faces[i] !== face) {
      for (let g = firsts[i]; g !== entering[i]; g = mesh.next(g)) mesh.setFace(g, face);
    }
    if (i + 1 < d) mesh.setNext(lasts[i], firsts[i + 1]);
  }
  if (!boundary) {
    mesh.setNext(lasts[d - 1], firsts[0]);
  } else {
    // a new edge closes the merged face: n runs b → a in it, its twin a → b along the hole
    const n = mesh.newEdge();
    mesh.setOrigin(n, b);
    mesh.setOrigin(mesh.twin(n), a);
    mesh.setFace(n, face);
    mesh.setNext(lasts[d - 1], n);
    mesh.setNext(n, firsts[1]);
    mesh.setNext(holeBefore, mesh.twin(n));
    mesh.setNext(mesh.twin(n), holeAfter);
    mesh.setVertexHalfedge(a, mesh.twin(n));
  }
  if (handle === out[first] || handle === entering[first]) mesh.setFaceHalfedge(face, firsts[first]);
  // a neighbour whose halfedge ran to v takes the far path's halfedge leaving it
  for (let i = first; i < d; i++) {
    if (handles[i] === mesh.twin(out[i]) && neighbours[i] !== a) mesh.setVertexHalfedge(neighbours[i], firsts[i]);
  }
  for (let i = first + 1; i < d; i++) mesh.deleteFace(faces[i]);
  for (const g of out) mesh.deleteEdge(mesh.edge(g));
  mesh.deleteVertex(v);
  return face;
}
