/** A mesh as plain numbers (slot counts, every array up to its slots, every attribute): meshes compare with `toEqual`. */
import { attributeSetOf, elementKinds, meshArrays, slotCount } from '../../src/core/mesh-arrays.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';

export function meshContents(mesh: HalfedgeMesh): Record<string, unknown> {
  const contents: Record<string, unknown> = { slots: mesh.slotState };
  for (const { name, owner } of meshArrays) contents[name] = Array.from(mesh[name].subarray(0, slotCount(mesh, owner)));
  for (const kind of elementKinds) {
    const slots = slotCount(mesh, kind);
    for (const { name, data, itemSize } of attributeSetOf(mesh, kind)) contents[`${kind}:${name}`] = Array.from(data.subarray(0, slots * itemSize));
  }
  return contents;
}
