/**
 * The halfedge structure itself as textbook tables, one record per element with every pointer
 * spelled out, for assignments ("fill in the `next` column"), for debugging and for bug reports:
 *
 * ```
 * halfedges: [{ id: 0, origin: 0, twin: 1, next: 2, prev: 4, face: 0, edge: 0 }, …]
 * vertices:  [{ id: 0, halfedge: 0, position: [0, 0, 0] }, …]
 * edges:     [{ id: 0, halfedges: [0, 1] }, …]
 * faces:     [{ id: 0, halfedge: 0 }, …]
 * ```
 *
 * Every slot gets a record, deleted ones included (`deleted: true`), so reading a document back
 * gives the identical mesh, ids and all, even a broken one: the reader checks that the document
 * is well formed (types, ids in order, pointers in range, `twin = id ^ 1`, `edge = id >> 1`) but
 * not the mesh invariants, which is `validate()`'s job. Attributes appear in each record by name,
 * with their types in `attributes`. JSON has no NaN or infinity: they are written as null (NaN).
 */
import {
  type Attribute,
  attributeArrayTypes,
  type AttributeSet,
  type AttributeType,
  type Interpolation,
} from '../attributes.js';
import { ParseError } from '../errors.js';
import { HalfedgeMesh } from '../mesh.js';
import { plural } from '../report.js';

export type MeshElementKind = 'vertex' | 'halfedge' | 'edge' | 'face';

export interface AttributeDescription {
  element: MeshElementKind;
  name: string;
  type: AttributeType;
  itemSize: number;
  interpolation: Interpolation;
}

/** Values of the attributes of one element, by name. */
export type AttributeValues = Record<string, Array<number | null>>;

export interface VertexRecord {
  id: number;
  /** An outgoing halfedge (the boundary one on the boundary), -1 when isolated. */
  halfedge: number;
  position: Array<number | null>;
  deleted?: true;
  attributes?: AttributeValues;
}

export interface HalfedgeRecord {
  id: number;
  /** The vertex it starts from. */
  origin: number;
  twin: number;
  next: number;
  prev: number;
  /** The face on its left, -1 on the boundary. */
  face: number;
  edge: number;
  deleted?: true;
  attributes?: AttributeValues;
}

export interface EdgeRecord {
  id: number;
  halfedges: [number, number];
  deleted?: true;
  attributes?: AttributeValues;
}

export interface FaceRecord {
  id: number;
  halfedge: number;
  deleted?: true;
  attributes?: AttributeValues;
}

export interface HalfedgeDocument {
  format: 'halfedge-json';
  version: 1;
  vertices: VertexRecord[];
  halfedges: HalfedgeRecord[];
  edges: EdgeRecord[];
  faces: FaceRecord[];
  attributes: AttributeDescription[];
}

/**
 * The mesh as halfedge tables (a plain object: `JSON.stringify` it to save).
 * @example
 *   const doc = meshToHalfedgeJSON(mesh);
 *   doc.halfedges[0]; // { id: 0, origin: 0, twin: 1, next: 2, prev: 4, face: 0, edge: 0 }
 */
export function meshToHalfedgeJSON(mesh: HalfedgeMesh): HalfedgeDocument {
  const attributes: AttributeDescription[] = [];
  const describe = (element: MeshElementKind, set: AttributeSet) => {
    const list = [...set].filter((a) => !(element === 'vertex' && a.name === 'position'));
    for (const { name, type, itemSize, interpolation } of list) {
      attributes.push({ element, name, type, itemSize, interpolation });
    }
    return list;
  };
  const vertexAttributes = describe('vertex', mesh.vertexAttributes);
  const halfedgeAttributes = describe('halfedge', mesh.halfedgeAttributes);
  const edgeAttributes = describe('edge', mesh.edgeAttributes);
  const faceAttributes = describe('face', mesh.faceAttributes);
  const positions = mesh.positions;

  const vertices: VertexRecord[] = [];
  for (let v = 0; v < mesh.vertexSlots; v++) {
    const position = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]].map(jsonNumber);
    vertices.push(withExtras({ id: v, halfedge: mesh.vHalfedge[v], position }, mesh.vDeleted[v], vertexAttributes, v));
  }
  const halfedges: HalfedgeRecord[] = [];
  for (let h = 0; h < mesh.halfedgeSlots; h++) {
    const record = {
      id: h,
      origin: mesh.heVertex[h],
      twin: h ^ 1,
      next: mesh.heNext[h],
      prev: mesh.hePrev[h],
      face: mesh.heFace[h],
      edge: h >> 1,
    };
    halfedges.push(withExtras(record, mesh.eDeleted[h >> 1], halfedgeAttributes, h));
  }
  const edges: EdgeRecord[] = [];
  for (let e = 0; e < mesh.edgeSlots; e++) {
    edges.push(withExtras({ id: e, halfedges: [2 * e, 2 * e + 1] }, mesh.eDeleted[e], edgeAttributes, e));
  }
  const faces: FaceRecord[] = [];
  for (let f = 0; f < mesh.faceSlots; f++) {
    faces.push(withExtras({ id: f, halfedge: mesh.fHalfedge[f] }, mesh.fDeleted[f], faceAttributes, f));
  }
  return { format: 'halfedge-json', version: 1, vertices, halfedges, edges, faces, attributes };
}

function withExtras<T extends object>(record: T, deleted: number, attributes: Attribute[], id: number): T {
  const extras: { deleted?: true; attributes?: AttributeValues } = {};
  if (deleted) extras.deleted = true;
  if (attributes.length > 0) {
    extras.attributes = {};
    for (const { name, itemSize, data } of attributes) {
      extras.attributes[name] = Array.from(data.subarray(itemSize * id, itemSize * (id + 1)), jsonNumber);
    }
  }
  return { ...record, ...extras };
}

function jsonNumber(x: number): number | null {
  return Number.isFinite(x) ? x : null;
}

/**
 * Reads halfedge tables (an object, or its JSON text) back into the identical mesh: the same
 * slots, the same pointers, the same deleted flags and attributes.
 * @example
 *   const copy = meshFromHalfedgeJSON(JSON.stringify(meshToHalfedgeJSON(mesh)));
 * @throws ParseError (format 'halfedge-json') naming the record and field that is malformed.
 */
export function meshFromHalfedgeJSON(doc: unknown): HalfedgeMesh {
  const fail = (reason: string): never => {
    throw new ParseError('halfedge-json', {}, reason);
  };
  if (typeof doc === 'string') {
    try {
      doc = JSON.parse(doc) as unknown;
    } catch (error) {
      fail(`not valid JSON: ${(error as Error).message}`);
    }
  }
  if (!isObject(doc)) return fail('the document must be an object with vertices, halfedges, edges and faces');
  if (doc.format !== 'halfedge-json') fail(`'format' must be 'halfedge-json', not ${JSON.stringify(doc.format)}`);
  if (doc.version !== 1) fail(`version ${JSON.stringify(doc.version)} is not known (this reader reads version 1)`);
  const vertices = table(doc, 'vertices', fail);
  const halfedges = table(doc, 'halfedges', fail);
  const edges = table(doc, 'edges', fail);
  const faces = table(doc, 'faces', fail);
  const descriptions = table(doc, 'attributes', fail);
  if (halfedges.length !== 2 * edges.length) {
    fail(`there are ${halfedges.length} halfedges for ${edges.length} edges; every edge has exactly 2`);
  }

  const mesh = new HalfedgeMesh({ vertices: vertices.length, edges: edges.length, faces: faces.length });
  mesh.vertexSlots = vertices.length;
  mesh.edgeSlots = edges.length;
  mesh.faceSlots = faces.length;
  const counts: Record<MeshElementKind, number> = {
    vertex: vertices.length,
    halfedge: halfedges.length,
    edge: edges.length,
    face: faces.length,
  };
  /** A pointer field: the id of an element of kind `points`, or -1 for none. */
  const field = (record: JsonObject, what: string, key: string, points: MeshElementKind): number => {
    const value = record[key];
    if (!Number.isInteger(value)) fail(`${what}: '${key}' must be an integer, not ${JSON.stringify(value)}`);
    const id = value as number;
    if (!(id === -1 || (id >= 0 && id < counts[points]))) {
      fail(`${what}: '${key}' is ${id}, but ${points} ids run from 0 to ${counts[points] - 1} (or -1 for none)`);
    }
    return id;
  };
  const recordAt = (list: unknown[], i: number, kind: MeshElementKind): JsonObject => {
    const record = list[i];
    if (!isObject(record)) return fail(`${kind} ${i}: the record must be an object`);
    if (record.id !== i) {
      fail(`${kind} record ${i} has id ${JSON.stringify(record.id)}; records must be listed by id, from 0`);
    }
    return record;
  };

  const attributes = readDescriptions(descriptions, mesh, fail);
  const deleted: Record<MeshElementKind, Uint8Array> = {
    vertex: new Uint8Array(vertices.length),
    halfedge: new Uint8Array(halfedges.length),
    edge: new Uint8Array(edges.length),
    face: new Uint8Array(faces.length),
  };
  const readExtras = (record: JsonObject, kind: MeshElementKind, id: number) => {
    if (record.deleted === true) deleted[kind][id] = 1;
    else if (record.deleted !== undefined) fail(`${kind} ${id}: 'deleted' must be true or absent`);
    readAttributeValues(record, kind, id, attributes, fail);
  };

  vertices.forEach((_, v) => {
    const record = recordAt(vertices, v, 'vertex');
    mesh.vHalfedge[v] = field(record, `vertex ${v}`, 'halfedge', 'halfedge');
    const position = numbers(record.position, 3) ?? fail(`vertex ${v}: 'position' must be 3 numbers`);
    mesh.setPosition(v, position[0], position[1], position[2]);
    readExtras(record, 'vertex', v);
  });
  halfedges.forEach((_, h) => {
    const record = recordAt(halfedges, h, 'halfedge');
    const what = `halfedge ${h}`;
    mesh.heVertex[h] = field(record, what, 'origin', 'vertex');
    mesh.heNext[h] = field(record, what, 'next', 'halfedge');
    mesh.hePrev[h] = field(record, what, 'prev', 'halfedge');
    mesh.heFace[h] = field(record, what, 'face', 'face');
    if (field(record, what, 'twin', 'halfedge') !== (h ^ 1)) {
      fail(`${what}: 'twin' must be ${h ^ 1} (the twins of edge e are 2e and 2e + 1)`);
    }
    if (field(record, what, 'edge', 'edge') !== h >> 1) {
      fail(`${what}: 'edge' must be ${h >> 1} (halfedge h lies on edge h >> 1)`);
    }
    readExtras(record, 'halfedge', h);
  });
  edges.forEach((_, e) => {
    const record = recordAt(edges, e, 'edge');
    const pair = record.halfedges;
    if (!Array.isArray(pair) || pair[0] !== 2 * e || pair[1] !== 2 * e + 1 || pair.length !== 2) {
      fail(`edge ${e}: 'halfedges' must be [${2 * e}, ${2 * e + 1}]`);
    }
    readExtras(record, 'edge', e);
  });
  faces.forEach((_, f) => {
    const record = recordAt(faces, f, 'face');
    mesh.fHalfedge[f] = field(record, `face ${f}`, 'halfedge', 'halfedge');
    readExtras(record, 'face', f);
  });
  // a halfedge is deleted with its edge, and only then
  for (let h = 0; h < halfedges.length; h++) {
    if (deleted.halfedge[h] !== deleted.edge[h >> 1]) fail(`halfedge ${h}: 'deleted' must match its edge ${h >> 1}`);
  }
  deleted.vertex.forEach((flag, v) => flag && mesh.deleteVertex(v));
  deleted.edge.forEach((flag, e) => flag && mesh.deleteEdge(e));
  deleted.face.forEach((flag, f) => flag && mesh.deleteFace(f));
  return mesh;
}

type Fail = (reason: string) => never;

type JsonObject = Record<string, unknown>;

function isObject(value: unknown): value is JsonObject {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** `count` numbers (null read as NaN, which JSON cannot write), or null when `value` is not that. */
function numbers(value: unknown, count: number): number[] | null {
  if (!Array.isArray(value) || value.length !== count) return null;
  if (!value.every((x) => typeof x === 'number' || x === null)) return null;
  return value.map((x: number | null) => x ?? Number.NaN);
}

function table(doc: JsonObject, key: string, fail: Fail): unknown[] {
  const list = doc[key];
  if (!Array.isArray(list)) return fail(`'${key}' must be a list`);
  return list;
}

/** Adds the described attributes to the mesh; returns them by element kind and name. */
function readDescriptions(descriptions: unknown[], mesh: HalfedgeMesh, fail: Fail): Map<string, Attribute> {
  const sets: Record<MeshElementKind, AttributeSet> = {
    vertex: mesh.vertexAttributes,
    halfedge: mesh.halfedgeAttributes,
    edge: mesh.edgeAttributes,
    face: mesh.faceAttributes,
  };
  const byKey = new Map<string, Attribute>();
  descriptions.forEach((description, i) => {
    if (!isObject(description)) return fail(`attribute ${i}: the description must be an object`);
    const { element, name, type, itemSize, interpolation } = description;
    if (typeof element !== 'string' || !Object.hasOwn(sets, element)) {
      fail(`attribute ${i}: 'element' must be vertex, halfedge, edge or face`);
    }
    if (typeof name !== 'string' || !name || (element === 'vertex' && name === 'position')) {
      fail(`attribute ${i}: 'name' must be a non-empty string other than the vertex 'position'`);
    }
    const what = `attribute ${i} '${String(name)}'`;
    if (typeof type !== 'string' || !Object.hasOwn(attributeArrayTypes, type)) {
      fail(`${what}: unknown type ${JSON.stringify(type)}`);
    }
    if (!Number.isInteger(itemSize) || (itemSize as number) < 1) fail(`${what}: 'itemSize' must be a positive integer`);
    if (interpolation !== 'linear' && interpolation !== 'copy') {
      fail(`${what}: 'interpolation' must be 'linear' or 'copy'`);
    }
    const key = `${element}:${name}`;
    if (byKey.has(key)) fail(`attribute ${i}: ${element} attribute '${name}' is described twice`);
    const set = sets[element as MeshElementKind];
    byKey.set(key, set.add(name as string, type as AttributeType, itemSize as number, interpolation as Interpolation));
  });
  return byKey;
}

/** Copies one record's attribute values into the mesh's attribute arrays. */
function readAttributeValues(
  record: JsonObject,
  kind: MeshElementKind,
  id: number,
  attributes: Map<string, Attribute>,
  fail: Fail,
): void {
  const values = record.attributes ?? {};
  if (!isObject(values)) return fail(`${kind} ${id}: 'attributes' must be an object`);
  for (const [key, attribute] of attributes) {
    if (!key.startsWith(`${kind}:`)) continue;
    const { name, itemSize, data } = attribute;
    const value = numbers(values[name], itemSize);
    if (!value) return fail(`${kind} ${id}: attribute '${name}' must be ${plural(itemSize, 'number')}`);
    data.set(value, itemSize * id);
  }
  for (const name of Object.keys(values)) {
    if (!attributes.has(`${kind}:${name}`)) fail(`${kind} ${id}: attribute '${name}' is not described in 'attributes'`);
  }
}
