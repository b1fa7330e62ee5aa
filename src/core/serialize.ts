/**
 * A mesh as a plain object of typed arrays, and back: the form it takes to cross a worker
 * boundary. `serializeMesh` copies (the mesh stays usable) and lists the buffers, so the copy can
 * be *transferred* rather than cloned a second time; `deserializeMesh` adopts the arrays as they
 * are, without copying.
 */
import { type AttributeArray, type AttributeSet, type AttributeType, attributeTypeOf, type Interpolation } from './attributes.js';
import { InvalidInputError } from './errors.js';
import { HalfedgeMesh } from './mesh.js';

export interface SerializedAttribute {
  name: string;
  type: AttributeType;
  itemSize: number;
  interpolation: Interpolation;
  data: AttributeArray;
}

export interface SerializedMesh {
  heNext: Int32Array;
  hePrev: Int32Array;
  heVertex: Int32Array;
  heFace: Int32Array;
  vHalfedge: Int32Array;
  fHalfedge: Int32Array;
  vDeleted: Uint8Array;
  eDeleted: Uint8Array;
  fDeleted: Uint8Array;
  attributes: {
    vertex: SerializedAttribute[];
    halfedge: SerializedAttribute[];
    edge: SerializedAttribute[];
    face: SerializedAttribute[];
  };
}

export function serializeMesh(mesh: HalfedgeMesh): SerializedMesh {
  const nH = mesh.halfedgeSlots;
  const attributes = (set: AttributeSet, count: number): SerializedAttribute[] =>
    [...set].map(({ name, type, itemSize, interpolation, data }) => ({
      name,
      type,
      itemSize,
      interpolation,
      data: data.slice(0, count * itemSize),
    }));
  return {
    heNext: mesh.heNext.slice(0, nH),
    hePrev: mesh.hePrev.slice(0, nH),
    heVertex: mesh.heVertex.slice(0, nH),
    heFace: mesh.heFace.slice(0, nH),
    vHalfedge: mesh.vHalfedge.slice(0, mesh.vertexSlots),
    fHalfedge: mesh.fHalfedge.slice(0, mesh.faceSlots),
    vDeleted: mesh.vDeleted.slice(0, mesh.vertexSlots),
    eDeleted: mesh.eDeleted.slice(0, mesh.edgeSlots),
    fDeleted: mesh.fDeleted.slice(0, mesh.faceSlots),
    attributes: {
      vertex: attributes(mesh.vertexAttributes, mesh.vertexSlots),
      halfedge: attributes(mesh.halfedgeAttributes, nH),
      edge: attributes(mesh.edgeAttributes, mesh.edgeSlots),
      face: attributes(mesh.faceAttributes, mesh.faceSlots),
    },
  };
}

/** The buffers of a serialized mesh, for a transfer list. */
export function meshBuffers(serialized: SerializedMesh): ArrayBuffer[] {
  const { attributes, ...arrays } = serialized;
  const all = [
    ...Object.values(arrays),
    ...Object.values(attributes).flatMap((list) => list.map((a) => a.data)),
  ];
  return all.map((a) => a.buffer as ArrayBuffer);
}

/**
 * Rebuilds a mesh around the serialized arrays (no copy: the mesh owns them afterwards).
 * @throws InvalidInputError when the arrays' lengths disagree.
 */
export function deserializeMesh(serialized: SerializedMesh): HalfedgeMesh {
  const nH = serialized.heNext.length;
  const nV = serialized.vHalfedge.length;
  const nF = serialized.fHalfedge.length;
  const sizes: Array<[string, number, number]> = [
    ['hePrev', serialized.hePrev.length, nH],
    ['heVertex', serialized.heVertex.length, nH],
    ['heFace', serialized.heFace.length, nH],
    ['vDeleted', serialized.vDeleted.length, nV],
    ['eDeleted', serialized.eDeleted.length, nH / 2],
    ['fDeleted', serialized.fDeleted.length, nF],
  ];
  for (const [name, length, expected] of sizes) {
    if (length !== expected) throw new InvalidInputError(`serialized mesh: ${name} has ${length} entries, ${expected} expected`);
  }
  const mesh = new HalfedgeMesh();
  Object.assign(mesh, {
    heNext: serialized.heNext,
    hePrev: serialized.hePrev,
    heVertex: serialized.heVertex,
    heFace: serialized.heFace,
    vHalfedge: serialized.vHalfedge,
    fHalfedge: serialized.fHalfedge,
    vDeleted: serialized.vDeleted,
    eDeleted: serialized.eDeleted,
    fDeleted: serialized.fDeleted,
    vertexSlots: nV,
    edgeSlots: nH / 2,
    faceSlots: nF,
  });
  mesh.recountDeleted();
  const adopt = (set: AttributeSet, list: SerializedAttribute[], count: number) => {
    set.resize(count, 0);
    for (const { name, itemSize, interpolation, data } of list) {
      if (data.length !== count * itemSize) {
        throw new InvalidInputError(`serialized mesh: attribute '${name}' has ${data.length} numbers, ${count * itemSize} expected`);
      }
      set.add(name, attributeTypeOf(data), itemSize, interpolation).data = data;
    }
  };
  adopt(mesh.vertexAttributes, serialized.attributes.vertex, nV);
  adopt(mesh.halfedgeAttributes, serialized.attributes.halfedge, nH);
  adopt(mesh.edgeAttributes, serialized.attributes.edge, nH / 2);
  adopt(mesh.faceAttributes, serialized.attributes.face, nF);
  return mesh;
}
