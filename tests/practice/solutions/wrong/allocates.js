export default function (mesh, v) {
  const all = [];
  for (;;) all.push(new Array(1e5).fill(v));
}
