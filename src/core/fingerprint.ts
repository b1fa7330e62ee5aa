/**
 * A hash of everything a mesh holds: slot and deletion counts, every array of the schema up to its
 * slots, and every attribute (by kind and name). Two meshes with the same fingerprint are, for any
 * practical purpose, identical; tests use it to check that a copy (the page's mirror, a mesh
 * rebuilt by undo) equals the original without shipping the arrays.
 */
import type { HalfedgeMesh } from './mesh.js';
import { attributeSetOf, elementKinds, meshArrays, slotCount } from './mesh-arrays.js';

/** 64 bits of FNV-1a over the bytes (two 32-bit lanes), as 16 hex digits. */
export function meshFingerprint(mesh: HalfedgeMesh): string {
  let a = 0x811c9dc5;
  let b = 0x01000193 ^ 0x9e3779b9;
  const eat = (bytes: Uint8Array) => {
    for (let i = 0; i < bytes.length; i++) {
      a = Math.imul(a ^ bytes[i], 0x01000193);
      b = Math.imul(b ^ bytes[i], 0x01000193) ^ (a >>> 15);
    }
  };
  const view = (array: ArrayBufferView) => new Uint8Array(array.buffer, array.byteOffset, array.byteLength);
  eat(view(Float64Array.from(Object.values(mesh.slotState))));
  for (const { name, owner } of meshArrays) eat(view(mesh[name].subarray(0, slotCount(mesh, owner))));
  for (const kind of elementKinds) {
    const slots = slotCount(mesh, kind);
    const attributes = [...attributeSetOf(mesh, kind)].sort((p, q) => (p.name < q.name ? -1 : 1));
    for (const { name, data, itemSize } of attributes) {
      eat(Uint8Array.from(`${kind}:${name}`, (c) => c.charCodeAt(0) & 0xff));
      eat(view(data.subarray(0, slots * itemSize)));
    }
  }
  const hex = (x: number) => (x >>> 0).toString(16).padStart(8, '0');
  return hex(a) + hex(b);
}
