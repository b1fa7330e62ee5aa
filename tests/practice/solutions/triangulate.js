// Triangulate every face of more than three sides by ear clipping: cut off a corner that turns the
// face's way and has no other corner inside or on its triangle, along a diagonal that is not an
// edge already; a face with no such corner left (no area) stays as it is.
export default function (mesh) {
  for (const f of mesh.faces()) {
    const sides = [];
    const start = mesh.faceHalfedge(f);
    let h = start;
    do {
      sides.push(h);
      h = mesh.next(h);
    } while (h !== start);
    if (sides.length > 3) triangulateFace(mesh, f, sides);
  }
}

function triangulateFace(mesh, f, sides) {
  const k = sides.length;
  const corners = sides.map((s) => mesh.origin(s));
  const points = corners.map((v) => mesh.position(v));
  // lay the face flat: coordinates in its plane, seen from the side its normal points to
  const n = [0, 0, 0];
  for (let i = 0; i < k; i++) {
    const [p, q] = [points[i], points[(i + 1) % k]];
    n[0] += p[1] * q[2] - p[2] * q[1];
    n[1] += p[2] * q[0] - p[0] * q[2];
    n[2] += p[0] * q[1] - p[1] * q[0];
  }
  const length = Math.hypot(...n);
  if (length === 0) return; // no area: no plane to cut it in
  const axis = Math.abs(n[0]) <= Math.abs(n[1]) && Math.abs(n[0]) <= Math.abs(n[2]) ? [1, 0, 0] : Math.abs(n[1]) <= Math.abs(n[2]) ? [0, 1, 0] : [0, 0, 1];
  const u = normalize(cross(axis, n));
  const w = cross(n.map((x) => x / length), u);
  const flat = points.map((p) => [dot(p, u), dot(p, w)]);
  const turn = (a, b, c) => (flat[b][0] - flat[a][0]) * (flat[c][1] - flat[a][1]) - (flat[b][1] - flat[a][1]) * (flat[c][0] - flat[a][0]);
  const scale = Math.max(...flat.flat().map(Math.abs), 1);
  const eps = 1e-12 * scale * scale;
  const joined = (a, b) => {
    const first = mesh.vertexHalfedge(corners[a]);
    let g = first;
    do {
      if (mesh.target(g) === corners[b]) return true;
      g = mesh.twin(mesh.prev(g));
    } while (g !== first);
    return false;
  };

  // ear clipping, on corner indices
  const ring = corners.map((_, i) => i);
  const triangles = [];
  while (ring.length > 3) {
    let clipped = false;
    for (let r = 0; r < ring.length && !clipped; r++) {
      const [a, b, c] = [ring[(r + ring.length - 1) % ring.length], ring[r], ring[(r + 1) % ring.length]];
      if (turn(a, b, c) <= eps) continue; // a corner that turns the other way, or not at all
      if (joined(a, c)) continue; // the diagonal would be a second edge between two vertices
      const inside = ring.some((x) => x !== a && x !== b && x !== c && turn(a, b, x) >= -eps && turn(b, c, x) >= -eps && turn(c, a, x) >= -eps);
      if (inside) continue;
      triangles.push([a, b, c]);
      ring.splice(r, 1);
      clipped = true;
    }
    if (!clipped) return; // no ear: leave the face as it is
  }
  if (turn(ring[0], ring[1], ring[2]) <= eps) return;
  triangles.push(ring);

  // the halfedge from corner i to corner j: a side, or a diagonal made once for both triangles
  const diagonals = new Map();
  const halfedge = (i, j) => {
    if (j === (i + 1) % k) return sides[i];
    const key = `${Math.min(i, j)},${Math.max(i, j)}`;
    if (!diagonals.has(key)) {
      const d = mesh.newEdge();
      mesh.setOrigin(d, corners[Math.min(i, j)]);
      mesh.setOrigin(mesh.twin(d), corners[Math.max(i, j)]);
      diagonals.set(key, d);
    }
    const d = diagonals.get(key);
    return i < j ? d : mesh.twin(d);
  };
  triangles.forEach(([a, b, c], t) => {
    const face = t === 0 ? f : mesh.newFace();
    const loop = [halfedge(a, b), halfedge(b, c), halfedge(c, a)];
    loop.forEach((g, i) => {
      mesh.setNext(g, loop[(i + 1) % 3]);
      mesh.setFace(g, face);
    });
    mesh.setFaceHalfedge(face, loop[0]);
  });
}

function cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

function dot(a, b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

function normalize(v) {
  const length = Math.hypot(...v);
  return v.map((x) => x / length);
}
