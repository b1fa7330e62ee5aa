// A face made a hole whose corners, now on the boundary, keep a halfedge that is not their boundary one.
export default function (mesh, f) {
  const sides = [];
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    sides.push(h);
    h = mesh.next(h);
  } while (h !== start);
  const k = sides.length;
  const onBoundary = (v) => {
    const first = mesh.vertexHalfedge(v);
    let g = first;
    do {
      if (mesh.isBoundary(g)) return true;
      g = mesh.twin(mesh.prev(g));
    } while (g !== first);
    return false;
  };
  const cornerOnBoundary = sides.map((g) => onBoundary(mesh.origin(g)));
  const alongHole = sides.map((g) => mesh.isBoundary(mesh.twin(g)));
  for (let i = 0; i < k; i++) {
    // a pinch: a corner already on the boundary where neither edge of f is
    if (!alongHole[(i + k - 1) % k] && !alongHole[i] && cornerOnBoundary[i]) return false;
  }
  if (alongHole.every(Boolean)) return false; // a lone face: nothing would be left of it

  for (const g of sides) mesh.setFace(g, -1);
  // a corner that was inside is on the boundary now: it leaves along f's old halfedge
  for (let i = 0; i < k; i++) if (alongHole[i]) removeEdgeBetweenHoles(mesh, sides[i]);
  mesh.deleteFace(f);
  return true;
}

// g's edge has the hole on both sides: it goes, and the loop(s) run on where it was
function removeEdgeBetweenHoles(mesh, g) {
  const t = mesh.twin(g);
  const a = mesh.origin(g);
  const b = mesh.origin(t);
  const n = mesh.next(g);
  const p = mesh.prev(g);
  const nt = mesh.next(t);
  const pt = mesh.prev(t);
  if (n === t && nt === g) {
    // a dangling edge on its own
    mesh.deleteVertex(a);
    mesh.deleteVertex(b);
  } else if (n === t) {
    // b has no other edge: the loop skips the spike, and b goes
    mesh.setNext(p, nt);
    if (mesh.vertexHalfedge(a) === g) mesh.setVertexHalfedge(a, nt);
    mesh.deleteVertex(b);
  } else if (nt === g) {
    mesh.setNext(pt, n);
    if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, n);
    mesh.deleteVertex(a);
  } else {
    // each loop runs on into the other
    mesh.setNext(p, nt);
    mesh.setNext(pt, n);
    if (mesh.vertexHalfedge(a) === g) mesh.setVertexHalfedge(a, nt);
    if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, n);
  }
  mesh.deleteEdge(mesh.edge(g));
}
