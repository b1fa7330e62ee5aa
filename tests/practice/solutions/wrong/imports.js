import { readFileSync } from 'node:fs';
export default function (mesh, v) {
  return readFileSync('/etc/passwd').length;
}
