// A simplification that collapses the shortest edge to its midpoint, boundary or not: it forgets
// that a boundary vertex (a corner above all) must stay where it is.
// with: collapse-edge as collapseEdge
export default function (mesh, input) {
  const length = (e) => {
    const h = mesh.edgeHalfedge(e);
    const [p, q] = [mesh.position(mesh.origin(h)), mesh.position(mesh.target(h))];
    return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  };
  const refused = new Set();
  while (mesh.faceCount() > input.faces) {
    const edges = mesh.edges().filter((e) => !refused.has(e)).sort((a, b) => length(a) - length(b));
    if (edges.length === 0) return;
    if (collapseEdge(mesh, edges[0]) === -1) refused.add(edges[0]);
    else refused.clear();
  }
}
