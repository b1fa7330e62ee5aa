export default function (mesh, v) {
  fetch('/secret');
  return 3;
}
