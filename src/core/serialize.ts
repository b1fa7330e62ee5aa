/**
 * A mesh as a plain object of typed arrays, and back: the form it takes to cross a worker
 * boundary. `serializeMesh` copies (the mesh stays usable) and lists the buffers, so the copy can
 * be *transferred* rather than cloned a second time; `deserializeMesh` adopts the arrays as they
 * are, without copying.
 */
import { type AttributeArray, type AttributeType, attributeTypeOf, type Interpolation } from './attributes.js';
import { InvalidInputError } from './errors.js';
import { HalfedgeMesh } from './mesh.js';
import { newArrayLike } from './memory.js';
import { attributeSetOf, type ElementKind, elementKinds, lengthsByKind, type MeshArrayName, meshArrays, roomByKind, setMeshArray, slotCount } from './mesh-arrays.js';

export interface SerializedAttribute {
  name: string;
  type: AttributeType;
  itemSize: number;
  interpolation: Interpolation;
  data: AttributeArray;
}

/** The version of the serialized form; a reader refuses another. */
export const SERIALIZED_MESH_FORMAT = 1;

export type SerializedMesh = {
  format: number;
  /** Slots in use; the arrays may hold room for more (the same room for every array of a kind). */
  slots: { vertices: number; edges: number; faces: number };
} & { [name in MeshArrayName]: MeshArrayType<name> } & {
  attributes: Record<ElementKind, SerializedAttribute[]>;
};

type MeshArrayType<name extends MeshArrayName> = name extends 'vDeleted' | 'eDeleted' | 'fDeleted' ? Uint8Array : Int32Array;

/**
 * A copy of the mesh's arrays, sized to its slots plus `spare` more of each kind (room for the
 * elements the next edits add, so that whoever adopts the copy need not grow it at once).
 */
export function serializeMesh(mesh: HalfedgeMesh, spare = 0): SerializedMesh {
  const extra = lengthsByKind({ vertices: spare, edges: spare, faces: spare });
  return serializedForm(mesh, (array, kind, itemSize) => {
    const used = slotCount(mesh, kind) * itemSize;
    const next = newArrayLike(array, used + extra[kind] * itemSize);
    (next as Int32Array).set(array.subarray(0, used) as Int32Array);
    return next;
  });
}

/**
 * The mesh's own arrays in the serialized form, not copied: for a thread that shares their memory
 * (see `subdivision/helper-thread.ts`), which adopts them with `deserializeMesh`.
 */
export function shareMesh(mesh: HalfedgeMesh): SerializedMesh {
  return serializedForm(mesh, (array) => array);
}

/** The serialized form, each array as `take` gives it (`itemSize` numbers per element of `kind`). */
function serializedForm(mesh: HalfedgeMesh, take: <T extends AttributeArray | Int32Array | Uint8Array>(array: T, kind: ElementKind, itemSize: number) => T): SerializedMesh {
  const arrays = Object.fromEntries(meshArrays.map(({ name, owner }) => [name, take(mesh[name], owner, 1)]));
  const attributes = Object.fromEntries(
    elementKinds.map((kind) => {
      const list = [...attributeSetOf(mesh, kind)].map(({ name, type, itemSize, interpolation, data }) => ({
        name,
        type,
        itemSize,
        interpolation,
        data: take(data, kind, itemSize),
      }));
      return [kind, list];
    }),
  );
  const slots = { vertices: mesh.vertexSlots, edges: mesh.edgeSlots, faces: mesh.faceSlots };
  return { format: SERIALIZED_MESH_FORMAT, slots, ...arrays, attributes } as SerializedMesh;
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
  const room = roomByKind(serialized);
  const slots = lengthsByKind(serialized.slots ?? { vertices: NaN, edges: NaN, faces: NaN });
  for (const kind of elementKinds) {
    if (!Number.isInteger(slots[kind]) || slots[kind] < 0 || slots[kind] > room[kind]) {
      throw new InvalidInputError(`serialized mesh: ${slots[kind]} ${kind} slots do not fit arrays of ${room[kind]}`);
    }
  }
  if (room.halfedge !== 2 * room.edge) throw new InvalidInputError(`serialized mesh: heNext has ${room.halfedge} entries, ${2 * room.edge} expected`);
  const mesh = new HalfedgeMesh();
  for (const { name, owner, type } of meshArrays) {
    const array = serialized[name];
    if (!(array instanceof type) || array.length !== room[owner]) {
      throw new InvalidInputError(`serialized mesh: ${name} has ${array?.length} entries, ${room[owner]} expected`);
    }
    setMeshArray(mesh, name, array);
  }
  mesh.vertexSlots = slots.vertex;
  mesh.edgeSlots = slots.edge;
  mesh.faceSlots = slots.face;
  mesh.recountDeleted();
  for (const kind of elementKinds) {
    const set = attributeSetOf(mesh, kind);
    const count = room[kind];
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
