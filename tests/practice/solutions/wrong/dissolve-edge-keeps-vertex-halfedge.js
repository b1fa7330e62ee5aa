// An edge dissolve that deletes the edge its ends still name as their halfedge.
export default function (mesh, e) {
  const h = mesh.edgeHalfedge(e);
  const t = mesh.twin(h);
  const f0 = mesh.face(h);
  const f1 = mesh.face(t);
  const loop = (g) => {
    const out = [];
    let x = g;
    do {
      out.push(x);
      x = mesh.next(x);
    } while (x !== g);
    return out;
  };
  const outgoing = (v) => {
    const out = [];
    const first = mesh.vertexHalfedge(v);
    let x = first;
    do {
      out.push(x);
      x = mesh.twin(mesh.prev(x));
    } while (x !== first);
    return out;
  };

  if (f0 === -1 || f1 === -1) return makeHole(f0 === -1 ? f1 : f0);

  // the merged face must not pass through a corner twice
  const corners0 = loop(h).slice(2).map((g) => mesh.origin(g));
  const corners1 = loop(t).slice(2).map((g) => mesh.origin(g));
  if (f0 === f1 || corners0.some((v) => corners1.includes(v))) return false;
  const [a, b] = [mesh.origin(h), mesh.origin(t)];
  const [afterH, afterT, beforeH, beforeT] = [mesh.next(h), mesh.next(t), mesh.prev(h), mesh.prev(t)];
  for (const g of loop(t)) if (g !== t) mesh.setFace(g, f0);
  mesh.setNext(beforeH, afterT);
  mesh.setNext(beforeT, afterH);
  if (mesh.faceHalfedge(f0) === h) mesh.setFaceHalfedge(f0, afterH);
  mesh.deleteEdge(e);
  mesh.deleteFace(f1);
  return true;

  // the boundary edge's face f becomes part of the hole
  function makeHole(f) {
    const sides = loop(mesh.faceHalfedge(f));
    const onBoundary = (v) => outgoing(v).some((g) => mesh.isBoundary(g));
    const cornerOnBoundary = sides.map((g) => onBoundary(mesh.origin(g)));
    const alongHole = sides.map((g) => mesh.isBoundary(mesh.twin(g)));
    for (let i = 0; i < sides.length; i++) {
      const before = alongHole[(i + sides.length - 1) % sides.length];
      // a pinch: a corner on the boundary where neither of f's edges is
      if (!before && !alongHole[i] && cornerOnBoundary[i]) return false;
    }
    if (alongHole.every(Boolean)) return false; // a lone face: nothing would be left
    for (const g of sides) mesh.setFace(g, -1);
    for (let i = 0; i < sides.length; i++) if (!cornerOnBoundary[i]) mesh.setVertexHalfedge(mesh.origin(sides[i]), sides[i]);
    for (let i = 0; i < sides.length; i++) if (alongHole[i]) removeEdgeBetweenHoles(sides[i]);
    mesh.deleteFace(f);
    return true;
  }

  // an edge with the hole on both sides goes; the loops join where it was
  function removeEdgeBetweenHoles(g) {
    const gt = mesh.twin(g);
    const [a, b] = [mesh.origin(g), mesh.origin(gt)];
    const [n, p, nt, pt] = [mesh.next(g), mesh.prev(g), mesh.next(gt), mesh.prev(gt)];
    if (n === gt && nt === g) {
      mesh.deleteVertex(a);
      mesh.deleteVertex(b);
    } else if (n === gt) {
      mesh.setNext(p, nt);
      if (mesh.vertexHalfedge(a) === g) mesh.setVertexHalfedge(a, nt);
      mesh.deleteVertex(b);
    } else if (nt === g) {
      mesh.setNext(pt, n);
      if (mesh.vertexHalfedge(b) === gt) mesh.setVertexHalfedge(b, n);
      mesh.deleteVertex(a);
    } else {
      mesh.setNext(p, nt);
      mesh.setNext(pt, n);
      if (mesh.vertexHalfedge(a) === g) mesh.setVertexHalfedge(a, nt);
      if (mesh.vertexHalfedge(b) === gt) mesh.setVertexHalfedge(b, n);
    }
    mesh.deleteEdge(mesh.edge(g));
  }
}
