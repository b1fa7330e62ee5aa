export default function (mesh, f) {
  const start = mesh.faceHalfedge(f);
  let sides = 0;
  let h = start;
  do {
    sides++;
    h = mesh.next(h);
  } while (h !== start);
  return sides;
}
