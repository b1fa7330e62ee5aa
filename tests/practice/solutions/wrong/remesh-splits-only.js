// A remeshing that only splits: edges too long are halved, but edges too short are never collapsed.
// with: split-edge as splitEdge
export default function (mesh, input) {
  const high = (4 / 3) * input.targetEdgeLength;
  const length = (e) => {
    const h = mesh.edgeHalfedge(e);
    const [p, q] = [mesh.position(mesh.origin(h)), mesh.position(mesh.target(h))];
    return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  };
  for (let round = 0; round < input.iterations; round++) {
    for (const e of mesh.edges()) if (length(e) > high) splitEdge(mesh, e);
  }
}
