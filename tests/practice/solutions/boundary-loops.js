export default function (mesh) {
  const seen = new Set();
  let loops = 0;
  for (const h of mesh.halfedges()) {
    if (!mesh.isBoundary(h) || seen.has(h)) continue;
    loops++;
    let g = h;
    do {
      seen.add(g);
      g = mesh.next(g);
    } while (g !== h);
  }
  return loops;
}
