// An extrusion that never gives its new corners a halfedge.
export default function (mesh, { face: f, offset, inset }) {
  if (!(inset >= 0 && inset <= 1) || !Number.isFinite(offset)) return -1;
  const sides = [];
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    sides.push(h);
    h = mesh.next(h);
  } while (h !== start);
  const k = sides.length;
  const corners = sides.map((s) => mesh.origin(s));
  const points = corners.map((v) => mesh.position(v));

  // the centroid, and the normal (Newell: half the sum of p_i × p_i+1)
  const c = [0, 0, 0];
  const n = [0, 0, 0];
  for (let i = 0; i < k; i++) {
    const [p, q] = [points[i], points[(i + 1) % k]];
    for (let a = 0; a < 3; a++) c[a] += p[a] / k;
    n[0] += (p[1] * q[2] - p[2] * q[1]) / 2;
    n[1] += (p[2] * q[0] - p[0] * q[2]) / 2;
    n[2] += (p[0] * q[1] - p[1] * q[0]) / 2;
  }
  const length = Math.hypot(n[0], n[1], n[2]);
  if (offset !== 0 && length === 0) return -1; // no area: no normal to move along
  const unit = offset === 0 ? [0, 0, 0] : n.map((x) => x / length);

  // u_i, the moved copy of corner i
  const inner = points.map((p) => mesh.newVertex(p.map((x, a) => (1 - inset) * x + inset * c[a] + offset * unit[a])));
  const rims = sides.map(() => mesh.newEdge()); // rim i: u_i → u_i+1 in f, its twin in quad i
  const rungs = sides.map(() => mesh.newEdge()); // rung i: v_i → u_i, its twin back
  const quads = sides.map(() => mesh.newFace());

  for (let i = 0; i < k; i++) {
    const j = (i + 1) % k;
    const side = sides[i]; // v_i → v_j: stays, now the outer side of quad i
    const rim = rims[i];
    const rimOut = mesh.twin(rim); // u_j → u_i
    const up = rungs[j]; // v_j → u_j
    const down = mesh.twin(rungs[i]); // u_i → v_i
    mesh.setOrigin(rungs[i], corners[i]);
    mesh.setOrigin(mesh.twin(rungs[i]), inner[i]);
    mesh.setOrigin(rim, inner[i]);
    mesh.setOrigin(rimOut, inner[j]);
    // quad i: v_i → v_j → u_j → u_i
    mesh.setNext(side, up);
    mesh.setNext(up, rimOut);
    mesh.setNext(rimOut, down);
    mesh.setNext(down, side);
    for (const g of [side, up, rimOut, down]) mesh.setFace(g, quads[i]);
    mesh.setFaceHalfedge(quads[i], side);
  }
  // f runs round the new corners
  for (let i = 0; i < k; i++) {
    mesh.setNext(rims[i], rims[(i + 1) % k]);
    mesh.setFace(rims[i], f);
  }
  mesh.setFaceHalfedge(f, rims[0]);
  return f;
}
