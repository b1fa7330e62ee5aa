// Simplification by quadric error (Garland & Heckbert), with the collapse of the exercise before:
// the cheapest edge that can collapse goes first, to the point its two ends' quadrics place best.
// with: collapse-edge as collapseEdge
export default function (mesh, input) {
  const sub = (p, q) => p.map((x, i) => x - q[i]);
  const dot = (p, q) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  const cross = (p, q) => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
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

  // a quadric as its 4 × 4 matrix, row by row: the sum of area · [n, d][n, d]ᵀ over a vertex's triangles
  const quadric = new Map(mesh.vertices().map((v) => [v, new Array(16).fill(0)]));
  for (const f of mesh.faces()) {
    const h = mesh.faceHalfedge(f);
    const [a, b, c] = [h, mesh.next(h), mesh.prev(h)].map((g) => mesh.origin(g));
    const [pa, pb, pc] = [a, b, c].map((v) => mesh.position(v));
    const normal = cross(sub(pb, pa), sub(pc, pa));
    const twiceArea = Math.sqrt(dot(normal, normal));
    if (twiceArea === 0) continue;
    const plane = [...normal.map((x) => x / twiceArea), -dot(normal, pa) / twiceArea];
    for (const v of [a, b, c]) {
      const q = quadric.get(v);
      for (let i = 0; i < 16; i++) q[i] += (twiceArea / 2) * plane[i >> 2] * plane[i & 3];
    }
  }
  // a boundary edge adds the plane through it at right angles to its face, weighted heavily, so
  // that collapses keep the boundary's shape (its corners above all)
  for (const h of mesh.halfedges()) {
    if (!mesh.isBoundary(mesh.twin(h)) || mesh.isBoundary(h)) continue;
    const [a, b] = [mesh.origin(h), mesh.target(h)];
    const [pa, pb, pc] = [a, b, mesh.origin(mesh.prev(h))].map((v) => mesh.position(v));
    const along = sub(pb, pa);
    const normal = cross(along, cross(along, sub(pc, pa)));
    const size = Math.sqrt(dot(normal, normal));
    const plane = [...normal.map((x) => x / size), -dot(normal, pa) / size];
    for (const v of [a, b]) {
      const q = quadric.get(v);
      for (let i = 0; i < 16; i++) q[i] += 100 * dot(along, along) * plane[i >> 2] * plane[i & 3];
    }
  }
  const error = (q, p) => {
    const x = [...p, 1];
    let sum = 0;
    for (let i = 0; i < 16; i++) sum += x[i >> 2] * q[i] * x[i & 3];
    return sum;
  };
  // where the collapse of e puts its vertex, and what it costs (a boundary vertex stays put)
  const plan = (e) => {
    const h = mesh.edgeHalfedge(e);
    const [a, b] = [mesh.origin(h), mesh.target(h)];
    const q = quadric.get(a).map((x, i) => x + quadric.get(b)[i]);
    const [pa, pb] = [mesh.position(a), mesh.position(b)];
    const [boundaryA, boundaryB] = [onBoundary(a), onBoundary(b)];
    let point = best(q) ?? pa.map((x, i) => (x + pb[i]) / 2);
    if (boundaryA && !boundaryB) point = pa;
    else if (boundaryB && !boundaryA) point = pb;
    return { point, cost: error(q, point), quadric: q };
  };

  const costs = new Map(mesh.edges().map((e) => [e, plan(e)]));
  while (mesh.faceCount() > input.faces) {
    let cheapest = -1;
    for (const [e, { cost }] of costs) if (cost < Infinity && (cheapest === -1 || cost < costs.get(cheapest).cost)) cheapest = e;
    if (cheapest === -1) return; // nothing left that can collapse
    const { point, quadric: q } = costs.get(cheapest);
    const kept = collapseEdge(mesh, cheapest);
    if (kept === -1) {
      costs.get(cheapest).cost = Infinity; // until something near it changes
      continue;
    }
    mesh.setPosition(kept, point);
    quadric.set(kept, q);
    const live = new Set(mesh.edges());
    for (const e of costs.keys()) if (!live.has(e)) costs.delete(e);
    for (const g of outgoing(kept)) {
      costs.set(mesh.edge(g), plan(mesh.edge(g)));
      // the edges across also lose their refusal: their neighbourhood changed
      const across = mesh.edge(mesh.next(g));
      if (live.has(across)) costs.set(across, plan(across));
    }
  }
}

/** The point where quadric q is least: the solution of its upper 3 × 3 part, or null where that is singular (Cramer's rule). */
function best(q) {
  const [a, b, c, d, e, f, g, h, i] = [q[0], q[1], q[2], q[4], q[5], q[6], q[8], q[9], q[10]];
  const det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  if (Math.abs(det) < 1e-12) return null;
  const [r0, r1, r2] = [-q[3], -q[7], -q[11]];
  return [
    (r0 * (e * i - f * h) - b * (r1 * i - f * r2) + c * (r1 * h - e * r2)) / det,
    (a * (r1 * i - f * r2) - r0 * (d * i - f * g) + c * (d * r2 - r1 * g)) / det,
    (a * (e * r2 - r1 * h) - b * (d * r2 - r1 * g) + r0 * (d * h - e * g)) / det,
  ];
}
