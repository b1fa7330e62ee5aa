export default function (mesh, v) {
  let i = 0;
  while (true) i++;
}
