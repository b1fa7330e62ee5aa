/**
 * Seams: the edges where the two faces beside an edge disagree on a corner value (a texture
 * coordinate, a normal) at one of its ends. A file that keeps such values per vertex (glTF) splits
 * a vertex wherever they differ; welded, the halfedge mesh keeps them per corner (halfedge
 * attributes), and the seams are where the file had cut the surface open.
 *
 *            b
 *        ↑ h   t ↓        at b: corner next(h) (in face(h)) against corner t (in face(t))
 *            a            at a: corner h (in face(h)) against corner next(t) (in face(t))
 *
 * A halfedge attribute is the value of the corner at its origin, in its face.
 */
import type { HalfedgeMesh } from './mesh.js';

/** The live interior edges whose corner values differ across them, in id order (none without halfedge attributes). */
export function seamEdges(mesh: HalfedgeMesh): Int32Array {
  const attributes = [...mesh.halfedgeAttributes];
  const seams: number[] = [];
  if (attributes.length === 0) return new Int32Array(0);
  const { heNext, heFace, eDeleted } = mesh;
  const differ = (p: number, q: number) =>
    attributes.some(({ data, itemSize }) => {
      for (let k = 0; k < itemSize; k++) if (data[p * itemSize + k] !== data[q * itemSize + k]) return true;
      return false;
    });
  for (let e = 0; e < mesh.edgeSlots; e++) {
    const h = 2 * e;
    const t = h + 1;
    if (eDeleted[e] || heFace[h] < 0 || heFace[t] < 0) continue;
    if (differ(h, heNext[t]) || differ(heNext[h], t)) seams.push(e);
  }
  return Int32Array.from(seams);
}
