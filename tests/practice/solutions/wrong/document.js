export default function (mesh, v) {
  document.title = 'hello';
  return 3;
}
