/**
 * A mesh as a plain object of typed arrays, and back: the form it takes to cross a worker
 * boundary. `serializeMesh` copies (the mesh stays usable) and lists the buffers, so the copy can
 * be *transferred* rather than cloned a second time; `deserializeMesh` adopts the arrays as they
 * are, without copying.
 */
import { type AttributeArray, type AttributeType, attributeTypeOf, type Interpolation } from './attributes.js';
import { InvalidInputError } from './errors.js';
import { HalfedgeMesh } from './mesh.js';
import { attributeSetOf, type ElementKind, elementKinds, type MeshArrayName, meshArrays, setMeshArray, slotCount } from './mesh-arrays.js';

export interface SerializedAttribute {
  name: string;
  type: AttributeType;
  itemSize: number;
  interpolation: Interpolation;
  data: AttributeArray;
}

/** The version of the serialized form; a reader refuses another. */
export const SERIALIZED_MESH_FORMAT = 1;

export type SerializedMesh = { format: number } & { [name in MeshArrayName]: MeshArrayType<name> } & {
  attributes: Record<ElementKind, SerializedAttribute[]>;
};

type MeshArrayType<name extends MeshArrayName> = name extends 'vDeleted' | 'eDeleted' | 'fDeleted' ? Uint8Array : Int32Array;

export function serializeMesh(mesh: HalfedgeMesh): SerializedMesh {
  const arrays = Object.fromEntries(meshArrays.map(({ name, owner }) => [name, mesh[name].slice(0, slotCount(mesh, owner))]));
  const attributes = Object.fromEntries(
    elementKinds.map((kind) => {
      const count = slotCount(mesh, kind);
      const list = [...attributeSetOf(mesh, kind)].map(({ name, type, itemSize, interpolation, data }) => ({
        name,
        type,
        itemSize,
        interpolation,
        data: data.slice(0, count * itemSize),
      }));
      return [kind, list];
    }),
  );
  return { format: SERIALIZED_MESH_FORMAT, ...arrays, attributes } as SerializedMesh;
}

/** The buffers of a serialized mesh, for a transfer list. */
export function meshBuffers(serialized: SerializedMesh): ArrayBuffer[] {
  const all = [
    ...meshArrays.map(({ name }) => serialized[name]),
    ...elementKinds.flatMap((kind) => serialized.attributes[kind].map((a) => a.data)),
  ];
  return all.map((a) => a.buffer as ArrayBuffer);
}

/**
 * Rebuilds a mesh around the serialized arrays (no copy: the mesh owns them afterwards).
 * @throws InvalidInputError when the format is another version or the arrays' lengths disagree.
 */
export function deserializeMesh(serialized: SerializedMesh): HalfedgeMesh {
  if (serialized.format !== SERIALIZED_MESH_FORMAT) {
    throw new InvalidInputError(`serialized mesh: format ${String(serialized.format)}, this library reads format ${SERIALIZED_MESH_FORMAT}`);
  }
  const nH = serialized.heNext.length;
  const slots: Record<ElementKind, number> = {
    vertex: serialized.vHalfedge.length,
    halfedge: nH,
    edge: nH >> 1,
    face: serialized.fHalfedge.length,
  };
  if (nH % 2 !== 0) throw new InvalidInputError(`serialized mesh: heNext has ${nH} entries, an even number expected`);
  const mesh = new HalfedgeMesh();
  for (const { name, owner, type } of meshArrays) {
    const array = serialized[name];
    if (!(array instanceof type) || array.length !== slots[owner]) {
      throw new InvalidInputError(`serialized mesh: ${name} has ${array?.length} entries, ${slots[owner]} expected`);
    }
    setMeshArray(mesh, name, array);
  }
  mesh.vertexSlots = slots.vertex;
  mesh.edgeSlots = slots.edge;
  mesh.faceSlots = slots.face;
  mesh.recountDeleted();
  for (const kind of elementKinds) {
    const set = attributeSetOf(mesh, kind);
    const count = slots[kind];
    set.resize(count, 0);
    for (const { name, itemSize, interpolation, data } of serialized.attributes[kind]) {
      if (data.length !== count * itemSize) {
        throw new InvalidInputError(`serialized mesh: attribute '${name}' has ${data.length} numbers, ${count * itemSize} expected`);
      }
      set.add(name, attributeTypeOf(data), itemSize, interpolation).data = data;
    }
  }
  return mesh;
}
