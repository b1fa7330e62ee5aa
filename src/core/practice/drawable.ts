/**
 * Whether a state of a practice run can be drawn and walked by code that assumes pointers lead
 * somewhere: every pointer names a live element (or -1 where "none" is allowed), `next` and `prev`
 * are inverse, and every face has at least three sides. Then every `next` cycle and every rotation
 * around a vertex closes (they follow permutations), so no walk in the page can run away. A solution
 * half-way through rewiring often breaks this; `validate()` says exactly how.
 */
import type { HalfedgeMesh } from '../mesh.js';

/** Null when the mesh can be drawn, else the first pointer that prevents it, in words. */
export function whyNotDrawable(mesh: HalfedgeMesh): string | null {
  const { heNext, hePrev, heVertex, heFace, vHalfedge, fHalfedge, eDeleted, vDeleted, fDeleted } = mesh;
  const nH = mesh.halfedgeSlots;
  const liveH = (h: number) => h >= 0 && h < nH && eDeleted[h >> 1] === 0;
  for (let h = 0; h < nH; h++) {
    if (eDeleted[h >> 1]) continue;
    if (!liveH(heNext[h])) return `next(h${h}) is ${heNext[h]}`;
    if (!liveH(hePrev[h])) return `prev(h${h}) is ${hePrev[h]}`;
    if (hePrev[heNext[h]] !== h) return `next(h${h}) is h${heNext[h]} but prev(h${heNext[h]}) is h${hePrev[heNext[h]]}`;
    const v = heVertex[h];
    if (v < 0 || v >= mesh.vertexSlots || vDeleted[v]) return `origin(h${h}) is ${v}`;
    const f = heFace[h];
    if (f !== -1 && (f < 0 || f >= mesh.faceSlots || fDeleted[f])) return `face(h${h}) is ${f}`;
  }
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (!vDeleted[v] && vHalfedge[v] !== -1 && !liveH(vHalfedge[v])) return `the halfedge of v${v} is ${vHalfedge[v]}`;
  }
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const start = fHalfedge[f];
    if (!liveH(start)) return `the halfedge of f${f} is ${start}`;
    // next is a permutation (checked above): the cycle closes within nH steps
    let sides = 0;
    let h = start;
    do {
      sides++;
      h = heNext[h];
    } while (h !== start && sides <= nH);
    if (sides < 3) return `f${f} has ${sides} side${sides === 1 ? '' : 's'}`;
  }
  return null;
}
