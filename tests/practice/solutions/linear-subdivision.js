// One level of linear subdivision, in place: Catmull-Clark's quads, with face points at centroids,
// edge points at midpoints, and the old vertices left where they are.
export default function (mesh) {
  const edges = mesh.edges();
  const faces = mesh.faces();
  const add = (p, q, w = 1) => [p[0] + w * q[0], p[1] + w * q[1], p[2] + w * q[2]];
  const scale = (p, w) => [p[0] * w, p[1] * w, p[2] * w];
  const loopOf = (h) => {
    const out = [];
    let x = h;
    do {
      out.push(x);
      x = mesh.next(x);
    } while (x !== h);
    return out;
  };
  // every new position from the old mesh
  const facePoint = new Map();
  for (const f of faces) {
    const corners = loopOf(mesh.faceHalfedge(f)).map((h) => mesh.position(mesh.origin(h)));
    facePoint.set(f, scale(corners.reduce((s, p) => add(s, p), [0, 0, 0]), 1 / corners.length));
  }
  const edgePoint = new Map();
  for (const e of edges) {
    const h = mesh.edgeHalfedge(e);
    edgePoint.set(e, scale(add(mesh.position(mesh.origin(h)), mesh.position(mesh.target(h))), 1 / 2));
  }

  // split every edge at its edge point: h (a → b) becomes a → m, and a new edge m → b follows it
  const isEdgePoint = new Set();
  for (const e of edges) {
    const h = mesh.edgeHalfedge(e);
    const t = mesh.twin(h);
    const b = mesh.origin(t);
    const m = mesh.newVertex(edgePoint.get(e));
    isEdgePoint.add(m);
    const g = mesh.newEdge();
    const gt = mesh.twin(g);
    const [afterH, beforeT] = [mesh.next(h), mesh.prev(t)];
    mesh.setOrigin(g, m);
    mesh.setOrigin(gt, b);
    mesh.setOrigin(t, m);
    mesh.setNext(h, g);
    mesh.setNext(g, afterH);
    mesh.setNext(beforeT, gt);
    mesh.setNext(gt, t);
    mesh.setFace(g, mesh.face(h));
    mesh.setFace(gt, mesh.face(t));
    if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, gt);
    mesh.setVertexHalfedge(m, mesh.isBoundary(h) ? g : t);
  }

  // connect each face point to the edge points around its face: n quads
  for (const f of faces) {
    let start = mesh.faceHalfedge(f);
    if (isEdgePoint.has(mesh.origin(start))) start = mesh.next(start);
    const loop = loopOf(start); // x0 (corner → edge point), y0 (edge point → corner), x1, y1, …
    const n = loop.length / 2;
    const x = (i) => loop[2 * ((i + n) % n)];
    const y = (i) => loop[2 * ((i + n) % n) + 1];
    const c = mesh.newVertex(facePoint.get(f));
    const spokes = []; // spoke i: edge point i → face point, its twin back
    for (let i = 0; i < n; i++) {
      const s = mesh.newEdge();
      mesh.setOrigin(s, mesh.origin(y(i)));
      mesh.setOrigin(mesh.twin(s), c);
      spokes.push(s);
    }
    for (let i = 0; i < n; i++) {
      // quad i: edge point i−1 → corner i → edge point i → face point
      const quad = i === 0 ? f : mesh.newFace();
      const around = [y(i - 1), x(i), spokes[i], mesh.twin(spokes[(i + n - 1) % n])];
      around.forEach((g, j) => {
        mesh.setNext(g, around[(j + 1) % 4]);
        mesh.setFace(g, quad);
      });
      mesh.setFaceHalfedge(quad, x(i));
    }
    mesh.setVertexHalfedge(c, mesh.twin(spokes[0]));
  }
}
