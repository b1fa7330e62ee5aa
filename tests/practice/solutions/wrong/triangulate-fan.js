// Triangulates every face as a fan from the corner its halfedge starts at: right for a convex
// face, wrong for one that is not, or that has a corner on a straight side.
export default function (mesh) {
  for (const f of mesh.faces()) {
    const sides = [];
    const start = mesh.faceHalfedge(f);
    let h = start;
    do {
      sides.push(h);
      h = mesh.next(h);
    } while (h !== start);
    const k = sides.length;
    if (k <= 3) continue;
    // diagonal i joins corner 0 to corner i + 2
    const diagonals = [];
    for (let i = 2; i < k - 1; i++) {
      const d = mesh.newEdge();
      mesh.setOrigin(d, mesh.origin(sides[0]));
      mesh.setOrigin(mesh.twin(d), mesh.origin(sides[i]));
      diagonals.push(d);
    }
    // triangle i: corner 0, corner i, corner i + 1
    for (let i = 1; i <= k - 2; i++) {
      const first = i === 1 ? sides[0] : diagonals[i - 2];
      const last = i === k - 2 ? sides[k - 1] : mesh.twin(diagonals[i - 1]);
      const face = i === 1 ? f : mesh.newFace();
      const loop = [first, sides[i], last];
      loop.forEach((g, j) => {
        mesh.setNext(g, loop[(j + 1) % 3]);
        mesh.setFace(g, face);
      });
      mesh.setFaceHalfedge(face, first);
    }
  }
}
