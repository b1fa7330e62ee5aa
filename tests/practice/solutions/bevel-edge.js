// Bevel edge input.edge: a new face with a corner on every edge leaving its two ends (the edge
// itself excepted), input.amount of the way along.
export default function (mesh, { edge: e, amount }) {
  if (!(amount >= 0 && amount <= 1)) return -1;
  const h = mesh.edgeHalfedge(e); // a → b, in f0
  const t = mesh.twin(h); // b → a, in f1
  const f0 = mesh.face(h);
  const f1 = mesh.face(t);
  if (f0 === -1 || f1 === -1) return -1; // a boundary edge: nothing to put a face between
  const a = mesh.origin(h);
  const b = mesh.origin(t);
  const rotation = (g) => {
    const out = [];
    let x = g;
    do {
      out.push(x);
      x = mesh.twin(mesh.prev(x));
    } while (x !== g);
    return out;
  };
  // the spokes at each end, counter-clockwise, without the edge itself
  const spokesA = rotation(h).slice(1);
  const spokesB = rotation(t).slice(1);
  if (spokesA.length + spokesB.length + 2 < 5) return -1; // the new face would have 2 sides

  // read everything first
  const placesOf = (v, spokes) => {
    const p = mesh.position(v);
    return spokes.map((s) => mesh.position(mesh.target(s)).map((x, i) => (1 - amount) * p[i] + amount * x));
  };
  const placesA = placesOf(a, spokesA);
  const placesB = placesOf(b, spokesB);
  const beforeT = mesh.prev(t);
  const afterT = mesh.next(t);
  const fans = [
    { v: a, spokes: spokesA, places: placesA },
    { v: b, spokes: spokesB, places: placesB },
  ].map(({ v, spokes, places }) => ({
    v,
    spokes,
    places,
    into: spokes.map((s) => mesh.prev(s)),
    wedges: spokes.map((s) => mesh.face(s)),
  }));

  // each end opens like a vertex bevel, between its spokes only (not across f0 or f1)
  const inside = fans.map(({ v, spokes, places, into, wedges }) => {
    const corners = spokes.map((_, j) => (j === 0 ? v : mesh.newVertex(places[j])));
    mesh.setPosition(v, places[0]);
    for (let j = 1; j < spokes.length; j++) mesh.setOrigin(spokes[j], corners[j]);
    for (let j = 0; j < spokes.length; j++) mesh.setVertexHalfedge(corners[j], spokes[j]);
    const loop = [];
    for (let j = 0; j + 1 < spokes.length; j++) {
      const s = mesh.newEdge(); // corner j+1 → corner j, in wedge j
      mesh.setOrigin(s, corners[j + 1]);
      mesh.setOrigin(mesh.twin(s), corners[j]);
      mesh.setNext(into[j], s);
      mesh.setNext(s, spokes[j]);
      mesh.setFace(s, wedges[j]);
      if (wedges[j] === -1) mesh.setVertexHalfedge(corners[j + 1], s);
      loop.push(mesh.twin(s));
    }
    return { loop, last: corners[corners.length - 1] };
  });
  const [A, B] = inside;

  // f1's side: a new edge g from b to a's last corner, where t was
  const g = mesh.newEdge();
  mesh.setOrigin(g, b);
  mesh.setOrigin(mesh.twin(g), A.last);
  mesh.setNext(beforeT, g);
  mesh.setNext(g, afterT);
  mesh.setFace(g, f1);
  if (mesh.faceHalfedge(f1) === t) mesh.setFaceHalfedge(f1, g);
  // f0's side is the edge itself: t now leaves b's last corner, in the new face
  mesh.setOrigin(t, B.last);
  const face = mesh.newFace();
  const loop = [t, ...A.loop, mesh.twin(g), ...B.loop];
  loop.forEach((x, i) => {
    mesh.setNext(x, loop[(i + 1) % loop.length]);
    mesh.setFace(x, face);
  });
  mesh.setFaceHalfedge(face, t);
  return face;
}
