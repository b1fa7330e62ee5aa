// Isotropic remeshing (Botsch & Kobbelt): split long edges, collapse short ones, flip toward
// valence 6, smooth within the tangent plane; with the solutions of the exercises before.
// with: split-edge as splitEdge, collapse-edge as collapseEdge, flip-edge as flipEdge
export default function (mesh, input) {
  const L = input.targetEdgeLength;
  const [low, high] = [(4 / 5) * L, (4 / 3) * L];
  const sub = (p, q) => p.map((x, i) => x - q[i]);
  const dot = (p, q) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  const cross = (p, q) => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
  const distance = (p, q) => Math.sqrt(dot(sub(p, q), sub(p, q)));
  const ends = (e) => [mesh.origin(mesh.edgeHalfedge(e)), mesh.target(mesh.edgeHalfedge(e))];
  const length = (e) => distance(...ends(e).map((v) => mesh.position(v)));
  const outgoing = (v) => {
    const out = [];
    const first = mesh.vertexHalfedge(v);
    let g = first;
    do {
      out.push(g);
      g = mesh.twin(mesh.prev(g));
    } while (g !== first);
    return out;
  };
  const onBoundary = (v) => outgoing(v).some((g) => mesh.isBoundary(g));

  for (let round = 0; round < input.iterations; round++) {
    // 1. split every edge longer than 4/3 L, until none is
    for (let pass = 0, split = true; split && pass < 10; pass++) {
      split = false;
      for (const e of mesh.edges()) {
        if (length(e) > high) {
          splitEdge(mesh, e);
          split = true;
        }
      }
    }
    // 2. collapse edges shorter than 4/5 L where no edge of the result is longer than 4/3 L; the
    //    boundary stays as it is
    let live = new Set(mesh.edges());
    for (const e of mesh.edges()) {
      if (!live.has(e) || length(e) >= low) continue;
      const [a, b] = ends(e);
      if (onBoundary(a) || onBoundary(b)) continue;
      const [pa, pb] = [mesh.position(a), mesh.position(b)];
      const m = pa.map((x, i) => (x + pb[i]) / 2);
      const tooLong = [a, b].some((v) => outgoing(v).some((g) => distance(m, mesh.position(mesh.target(g))) > high));
      if (!tooLong && collapseEdge(mesh, e) !== -1) live = new Set(mesh.edges());
    }
    // 3. flip where the four corners come nearer valence 6 (4 on the boundary)
    const valence = (v) => outgoing(v).length;
    const deviation = (v, change) => Math.abs(valence(v) + change - (onBoundary(v) ? 4 : 6));
    for (const e of mesh.edges()) {
      const h = mesh.edgeHalfedge(e);
      const t = mesh.twin(h);
      if (mesh.isBoundary(h) || mesh.isBoundary(t)) continue;
      const [a, b, c, d] = [mesh.origin(h), mesh.origin(t), mesh.origin(mesh.prev(h)), mesh.origin(mesh.prev(t))];
      const before = deviation(a, 0) + deviation(b, 0) + deviation(c, 0) + deviation(d, 0);
      const after = deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1);
      if (after < before) flipEdge(mesh, e);
    }
    // 4. move each inner vertex halfway to the centroid of its neighbours, within its tangent plane
    const moves = [];
    for (const v of mesh.vertices()) {
      if (onBoundary(v)) continue;
      const p = mesh.position(v);
      const around = outgoing(v);
      const centroid = [0, 0, 0];
      let normal = [0, 0, 0];
      for (const g of around) {
        const q = mesh.position(mesh.target(g));
        const r = mesh.position(mesh.target(mesh.next(g)));
        centroid.forEach((_, i) => (centroid[i] += q[i] / around.length));
        normal = normal.map((x, i) => x + cross(sub(q, p), sub(r, p))[i]);
      }
      const n = normal.map((x) => x / Math.sqrt(dot(normal, normal)));
      const step = sub(centroid, p);
      const along = dot(step, n);
      moves.push([v, p.map((x, i) => x + 0.5 * (step[i] - along * n[i]))]);
    }
    for (const [v, p] of moves) mesh.setPosition(v, p);
  }
}
