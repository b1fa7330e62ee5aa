/**
 * Save and reload: what the library writes, it reads back to the same mesh. Written as OFF and
 * as binary PLY, read and built again, a mesh must keep its counts (V, E, F, boundary loops,
 * components, χ), need no repair, and have the same faces — compared as cyclic lists of corner
 * positions, since a file renumbers what it writes. Written as halfedge JSON, it must come back
 * identical, array by array. The fuzzers run this after every step; the tests use it too.
 */
import { buildMesh } from '../src/core/build.js';
import { meshFromHalfedgeJSON, meshToHalfedgeJSON } from '../src/core/io/halfedge-json.js';
import { readMesh } from '../src/core/io/read.js';
import { writeMesh } from '../src/core/io/write.js';
import type { HalfedgeMesh } from '../src/core/mesh.js';
import { meshStats } from '../src/core/stats.js';
import { validate } from '../src/core/validate.js';

/** The counts a save and reload keeps, as one line. */
function countsOf(mesh: HalfedgeMesh): string {
  const s = meshStats(mesh);
  return `V ${s.vertices} E ${s.edges} F ${s.faces} loops ${s.boundaryLoops} components ${s.components} χ ${s.eulerCharacteristic}`;
}

/** Each live face as its corners' positions, starting at the smallest, sorted: ids do not matter. */
function faceCycles(mesh: HalfedgeMesh): string[] {
  const cycles: string[] = [];
  for (const f of mesh.faces()) {
    const corners: string[] = [];
    let h = mesh.fHalfedge[f];
    for (let steps = 0; steps === 0 || h !== mesh.fHalfedge[f]; steps++) {
      if (steps > mesh.halfedgeSlots) return [`f${f}'s cycle does not close`];
      const v = mesh.heVertex[h];
      corners.push(`${mesh.positions[3 * v]} ${mesh.positions[3 * v + 1]} ${mesh.positions[3 * v + 2]}`);
      h = mesh.heNext[h];
    }
    let first = 0;
    for (let i = 1; i < corners.length; i++) if (corners[i] < corners[first]) first = i;
    cycles.push([...corners.slice(first), ...corners.slice(0, first)].join(' | '));
  }
  return cycles.sort();
}

/** The mesh's arrays, with how many of their numbers are in use. */
const arrays: Array<[keyof HalfedgeMesh & string, (mesh: HalfedgeMesh) => number]> = [
  ['heNext', (m) => m.halfedgeSlots],
  ['hePrev', (m) => m.halfedgeSlots],
  ['heVertex', (m) => m.halfedgeSlots],
  ['heFace', (m) => m.halfedgeSlots],
  ['vHalfedge', (m) => m.vertexSlots],
  ['positions', (m) => 3 * m.vertexSlots],
  ['vDeleted', (m) => m.vertexSlots],
  ['eDeleted', (m) => m.edgeSlots],
  ['fHalfedge', (m) => m.faceSlots],
  ['fDeleted', (m) => m.faceSlots],
];

/**
 * How `mesh` differs from itself saved and read back, or null when it does not. `mesh` must be
 * valid (check `validate()` first).
 */
export function reloadDifference(mesh: HalfedgeMesh): string | null {
  const counts = countsOf(mesh);
  const cycles = faceCycles(mesh).join('\n');
  for (const format of ['off', 'ply-binary'] as const) {
    const file = readMesh(writeMesh(mesh, format), { fileName: `reload.${format === 'off' ? 'off' : 'ply'}` });
    const { mesh: reloaded, report } = buildMesh(file.soup);
    const problems = validate(reloaded);
    if (problems.length > 0) return `${format}: read back, it is invalid: ${problems[0].message}`;
    const repairs = report.repairs.filter((r) => r.kind !== 'isolated-vertex');
    if (repairs.length > 0) return `${format}: read back, it needed repairs: ${repairs.map((r) => r.message).join('; ')}`;
    const reloadedCounts = countsOf(reloaded);
    if (reloadedCounts !== counts) return `${format}: ${counts} became ${reloadedCounts}`;
    if (faceCycles(reloaded).join('\n') !== cycles) return `${format}: the faces, as cycles of corner positions, changed`;
  }
  const copy = meshFromHalfedgeJSON(JSON.parse(JSON.stringify(meshToHalfedgeJSON(mesh))));
  for (const [name, used] of arrays) {
    const a = mesh[name] as ArrayLike<number>;
    const b = copy[name] as ArrayLike<number>;
    for (let i = 0; i < used(mesh); i++) {
      if (a[i] !== b[i]) return `halfedge JSON: ${name}[${i}] was ${a[i]}, read back ${b[i]}`;
    }
  }
  return null;
}
