export default function (mesh, f) {
  const sides = [];
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    sides.push(h);
    h = mesh.next(h);
  } while (h !== start);
  const k = sides.length;
  const centre = [0, 0, 0];
  for (const s of sides) {
    const p = mesh.position(mesh.origin(s));
    for (let i = 0; i < 3; i++) centre[i] += p[i] / k;
  }
  const m = mesh.newVertex(centre);
  // spoke i runs m → corner i (the origin of side i); its twin runs back
  const spokes = sides.map((s) => {
    const spoke = mesh.newEdge();
    mesh.setOrigin(spoke, m);
    mesh.setOrigin(mesh.twin(spoke), mesh.origin(s));
    return spoke;
  });
  sides.forEach((s, i) => {
    const face = i === 0 ? f : mesh.newFace();
    const back = mesh.twin(spokes[(i + 1) % k]);
    mesh.setNext(s, back);
    mesh.setNext(back, spokes[i]);
    mesh.setNext(spokes[i], s);
    for (const x of [s, back, spokes[i]]) mesh.setFace(x, face);
    mesh.setFaceHalfedge(face, s);
  });
  mesh.setVertexHalfedge(m, spokes[0]);
  return m;
}
