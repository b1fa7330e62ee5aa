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
 * with their types in `attributes`.
 *
 * JSON has no NaN or infinity (`JSON.stringify` turns them into null), so a mesh holding one is
 * refused by the writer, and a null or an out-of-range number by the reader, naming the field:
 * the library reads back everything it writes, and writes nothing it could not read.
 */
import {
  type Attribute,
  type AttributeArray,
  attributeArrayTypes,
  type AttributeSet,
  type AttributeType,
  type Interpolation,
} from '../attributes.js';
import { InvalidInputError, ParseError } from '../errors.js';
import { HalfedgeMesh } from '../mesh.js';
import { plural } from '../report.js';
import { type JsonPath, type JsonText, jsonLocation, syntaxErrorLocation } from './json-location.js';
import { encodeText } from './text.js';

export type MeshElementKind = 'vertex' | 'halfedge' | 'edge' | 'face';

export interface AttributeDescription {
  element: MeshElementKind;
  name: string;
  type: AttributeType;
  itemSize: number;
  interpolation: Interpolation;
}

/** Values of the attributes of one element, by name. */
export type AttributeValues = Record<string, number[]>;

export interface VertexRecord {
  id: number;
  /** An outgoing halfedge (the boundary one on the boundary), -1 when isolated. */
  halfedge: number;
  position: number[];
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
 * @throws InvalidInputError naming the element and field when a position or attribute value is NaN
 *   or infinite, which JSON cannot hold.
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
    const position = finiteItem(positions, 3, `vertex ${v}`, v, "'position'");
    const record = { id: v, halfedge: mesh.vHalfedge[v], position };
    vertices.push(withExtras(record, 'vertex', mesh.vDeleted[v], vertexAttributes, v));
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
    halfedges.push(withExtras(record, 'halfedge', mesh.eDeleted[h >> 1], halfedgeAttributes, h));
  }
  const edges: EdgeRecord[] = [];
  for (let e = 0; e < mesh.edgeSlots; e++) {
    edges.push(withExtras({ id: e, halfedges: [2 * e, 2 * e + 1] }, 'edge', mesh.eDeleted[e], edgeAttributes, e));
  }
  const faces: FaceRecord[] = [];
  for (let f = 0; f < mesh.faceSlots; f++) {
    faces.push(withExtras({ id: f, halfedge: mesh.fHalfedge[f] }, 'face', mesh.fDeleted[f], faceAttributes, f));
  }
  return { format: 'halfedge-json', version: 1, vertices, halfedges, edges, faces, attributes };
}

function withExtras<T extends object>(
  record: T,
  kind: MeshElementKind,
  deleted: number,
  attributes: Attribute[],
  id: number,
): T {
  const extras: { deleted?: true; attributes?: AttributeValues } = {};
  if (deleted) extras.deleted = true;
  if (attributes.length > 0) {
    // entries, not assignments: an attribute may be called `__proto__`, which an assignment to a
    // plain object would take for its prototype instead of a key
    const item = ({ name, itemSize, data }: Attribute) => finiteItem(data, itemSize, `${kind} ${id}`, id, `attribute '${name}'`);
    extras.attributes = Object.fromEntries(attributes.map((attribute) => [attribute.name, item(attribute)]));
  }
  return { ...record, ...extras };
}

/**
 * Item `id` of `data` (`itemSize` numbers) as a list.
 * @throws InvalidInputError naming the element (`where`) and `field` when a number is not finite.
 */
function finiteItem(data: ArrayLike<number>, itemSize: number, where: string, id: number, field: string): number[] {
  const item: number[] = [];
  for (let k = 0; k < itemSize; k++) {
    const x = data[itemSize * id + k];
    if (!Number.isFinite(x)) {
      const why = 'JSON has no NaN or infinity, so halfedge JSON cannot hold it';
      throw new InvalidInputError(`${where}: item ${k} of ${field} is ${x}; ${why}`);
    }
    item.push(x);
  }
  return item;
}

/**
 * Reads halfedge tables (an object, or its JSON text) back into the identical mesh: the same
 * slots, the same pointers, the same deleted flags and attributes.
 * @example
 *   const copy = meshFromHalfedgeJSON(JSON.stringify(meshToHalfedgeJSON(mesh)));
 * @throws ParseError (format 'halfedge-json') naming the record and field that is malformed, with
 *   its path (`vertices[3].position[1]`), and its line and column when the document is text.
 */
export function meshFromHalfedgeJSON(doc: unknown): HalfedgeMesh {
  // the text is placed only for an error: encoded then, never on the way of a good document
  const source = typeof doc === 'string' ? doc : null;
  const text = (): JsonText | null => {
    if (source === null) return null;
    const bytes = encodeText(source);
    return { bytes, start: 0, end: bytes.length, byteOffsets: false };
  };
  const fail: Fail = (path, reason) => {
    throw new ParseError('halfedge-json', jsonLocation(text(), path), reason);
  };
  if (source !== null) {
    try {
      doc = JSON.parse(source) as unknown;
    } catch (error) {
      throw new ParseError('halfedge-json', syntaxErrorLocation(text()!), `not valid JSON: ${(error as Error).message}`);
    }
  }
  if (!isObject(doc)) return fail([], 'the document must be an object with vertices, halfedges, edges and faces');
  if (doc.format !== 'halfedge-json') fail(['format'], `'format' must be 'halfedge-json', not ${JSON.stringify(doc.format)}`);
  if (doc.version !== 1) fail(['version'], `version ${JSON.stringify(doc.version)} is not known (this reader reads version 1)`);
  const vertices = table(doc, 'vertices', fail);
  const halfedges = table(doc, 'halfedges', fail);
  const edges = table(doc, 'edges', fail);
  const faces = table(doc, 'faces', fail);
  const descriptions = table(doc, 'attributes', fail);
  if (halfedges.length !== 2 * edges.length) {
    fail(['halfedges'], `there are ${halfedges.length} halfedges for ${edges.length} edges; every edge has exactly 2`);
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
  /** A pointer field of record `id` of `kind`: the id of an element of kind `points`, or -1 for none. */
  const field = (record: JsonObject, kind: MeshElementKind, id: number, key: string, points: MeshElementKind): number => {
    const value = record[key];
    const what = `${kind} ${id}`;
    const path = [tables[kind], id, key];
    if (!Number.isInteger(value)) fail(path, `${what}: '${key}' must be an integer, not ${JSON.stringify(value)}`);
    const pointer = value as number;
    if (!(pointer === -1 || (pointer >= 0 && pointer < counts[points]))) {
      fail(path, `${what}: '${key}' is ${pointer}, but ${points} ids run from 0 to ${counts[points] - 1} (or -1 for none)`);
    }
    return pointer;
  };
  const recordAt = (list: unknown[], i: number, kind: MeshElementKind): JsonObject => {
    const record = list[i];
    if (!isObject(record)) return fail([tables[kind], i], `${kind} ${i}: the record must be an object`);
    if (record.id !== i) {
      fail([tables[kind], i, 'id'], `${kind} record ${i} has id ${JSON.stringify(record.id)}; records must be listed by id, from 0`);
    }
    return record;
  };

  const records: Record<MeshElementKind, unknown[]> = { vertex: vertices, halfedge: halfedges, edge: edges, face: faces };
  const attributes = readDescriptions(descriptions, records, mesh, fail);
  const deleted: Record<MeshElementKind, Uint8Array> = {
    vertex: new Uint8Array(vertices.length),
    halfedge: new Uint8Array(halfedges.length),
    edge: new Uint8Array(edges.length),
    face: new Uint8Array(faces.length),
  };
  const readExtras = (record: JsonObject, kind: MeshElementKind, id: number) => {
    if (record.deleted === true) deleted[kind][id] = 1;
    else if (record.deleted !== undefined) fail([tables[kind], id, 'deleted'], `${kind} ${id}: 'deleted' must be true or absent`);
    readAttributeValues(record, kind, id, attributes, fail);
  };

  vertices.forEach((_, v) => {
    const record = recordAt(vertices, v, 'vertex');
    mesh.vHalfedge[v] = field(record, 'vertex', v, 'halfedge', 'halfedge');
    readNumbers(record.position, mesh.positions, 'float64', 3, v, ['vertices', v, 'position'], `vertex ${v}`, "'position'", fail);
    readExtras(record, 'vertex', v);
  });
  halfedges.forEach((_, h) => {
    const record = recordAt(halfedges, h, 'halfedge');
    const what = `halfedge ${h}`;
    mesh.heVertex[h] = field(record, 'halfedge', h, 'origin', 'vertex');
    mesh.heNext[h] = field(record, 'halfedge', h, 'next', 'halfedge');
    mesh.hePrev[h] = field(record, 'halfedge', h, 'prev', 'halfedge');
    mesh.heFace[h] = field(record, 'halfedge', h, 'face', 'face');
    if (field(record, 'halfedge', h, 'twin', 'halfedge') !== (h ^ 1)) {
      fail(['halfedges', h, 'twin'], `${what}: 'twin' must be ${h ^ 1} (the twins of edge e are 2e and 2e + 1)`);
    }
    if (field(record, 'halfedge', h, 'edge', 'edge') !== h >> 1) {
      fail(['halfedges', h, 'edge'], `${what}: 'edge' must be ${h >> 1} (halfedge h lies on edge h >> 1)`);
    }
    readExtras(record, 'halfedge', h);
  });
  edges.forEach((_, e) => {
    const record = recordAt(edges, e, 'edge');
    const pair = record.halfedges;
    if (!Array.isArray(pair) || pair[0] !== 2 * e || pair[1] !== 2 * e + 1 || pair.length !== 2) {
      fail(['edges', e, 'halfedges'], `edge ${e}: 'halfedges' must be [${2 * e}, ${2 * e + 1}]`);
    }
    readExtras(record, 'edge', e);
  });
  faces.forEach((_, f) => {
    const record = recordAt(faces, f, 'face');
    mesh.fHalfedge[f] = field(record, 'face', f, 'halfedge', 'halfedge');
    readExtras(record, 'face', f);
  });
  // a halfedge is deleted with its edge, and only then
  for (let h = 0; h < halfedges.length; h++) {
    if (deleted.halfedge[h] !== deleted.edge[h >> 1]) {
      fail(['halfedges', h, 'deleted'], `halfedge ${h}: 'deleted' must match its edge ${h >> 1}`);
    }
  }
  deleted.vertex.forEach((flag, v) => flag && mesh.deleteVertex(v));
  deleted.edge.forEach((flag, e) => flag && mesh.deleteEdge(e));
  deleted.face.forEach((flag, f) => flag && mesh.deleteFace(f));
  return mesh;
}

/** Refuses the document, naming the value at `path`. */
type Fail = (path: JsonPath, reason: string) => never;

type JsonObject = Record<string, unknown>;

/** The table of the document that holds the records of each kind. */
const tables: Record<MeshElementKind, string> = { vertex: 'vertices', halfedge: 'halfedges', edge: 'edges', face: 'faces' };

function isObject(value: unknown): value is JsonObject {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/**
 * Stores `value`, a list of `itemSize` numbers (at `path`), as item `id` of `data`. Each must be a
 * number the array holds as it is: finite (JSON writes NaN and infinity as null, and reads 1e999
 * as infinity), within the range of a float32 array, and a whole number in range for an integer
 * one (which would otherwise wrap 256 to 0 or cut 1.5 to 1 without a word).
 */
function readNumbers(
  value: unknown,
  data: Float64Array | AttributeArray,
  type: AttributeType,
  itemSize: number,
  id: number,
  path: JsonPath,
  where: string,
  field: string,
  fail: Fail,
): void {
  if (!Array.isArray(value) || value.length !== itemSize) return fail(path, `${where}: ${field} must be ${plural(itemSize, 'number')}`);
  const exact = !type.startsWith('float');
  for (let k = 0; k < itemSize; k++) {
    const x: unknown = value[k];
    const at = itemSize * id + k;
    if (typeof x !== 'number') {
      const why = x === null ? ' (JSON writes NaN and infinity as null)' : '';
      fail([...path, k], `${where}: item ${k} of ${field} is ${JSON.stringify(x) ?? String(x)}, not a number${why}`);
    }
    data[at] = x as number;
    if (!Number.isFinite(data[at]) || (exact && data[at] !== x)) {
      fail([...path, k], `${where}: item ${k} of ${field} is ${String(x)}, which ${type} cannot hold`);
    }
  }
}

function table(doc: JsonObject, key: string, fail: Fail): unknown[] {
  const list = doc[key];
  if (!Array.isArray(list)) return fail([key], `'${key}' must be a list`);
  return list;
}

/** Adds the described attributes to the mesh; returns them by element kind and name. */
function readDescriptions(
  descriptions: unknown[],
  records: Record<MeshElementKind, unknown[]>,
  mesh: HalfedgeMesh,
  fail: Fail,
): Map<string, Attribute> {
  const sets: Record<MeshElementKind, AttributeSet> = {
    vertex: mesh.vertexAttributes,
    halfedge: mesh.halfedgeAttributes,
    edge: mesh.edgeAttributes,
    face: mesh.faceAttributes,
  };
  const byKey = new Map<string, Attribute>();
  descriptions.forEach((description, i) => {
    const at = (key?: string): JsonPath => (key === undefined ? ['attributes', i] : ['attributes', i, key]);
    if (!isObject(description)) return fail(at(), `attribute ${i}: the description must be an object`);
    const { element, name, type, itemSize, interpolation } = description;
    if (typeof element !== 'string' || !Object.hasOwn(sets, element)) {
      fail(at('element'), `attribute ${i}: 'element' must be vertex, halfedge, edge or face`);
    }
    if (typeof name !== 'string' || !name || (element === 'vertex' && name === 'position')) {
      fail(at('name'), `attribute ${i}: 'name' must be a non-empty string other than the vertex 'position'`);
    }
    const what = `attribute ${i} '${String(name)}'`;
    if (typeof type !== 'string' || !Object.hasOwn(attributeArrayTypes, type)) {
      fail(at('type'), `${what}: unknown type ${JSON.stringify(type)}`);
    }
    if (!Number.isInteger(itemSize) || (itemSize as number) < 1) fail(at('itemSize'), `${what}: 'itemSize' must be a positive integer`);
    const kind = element as MeshElementKind;
    checkItemSize(records[kind], kind, name as string, itemSize as number, i, fail);
    if (interpolation !== 'linear' && interpolation !== 'copy') {
      fail(at('interpolation'), `${what}: 'interpolation' must be 'linear' or 'copy'`);
    }
    const key = `${element}:${name}`;
    if (byKey.has(key)) fail(at(), `attribute ${i}: ${element} attribute '${name}' is described twice`);
    const set = sets[kind];
    byKey.set(key, set.add(name as string, type as AttributeType, itemSize as number, interpolation as Interpolation));
  });
  return byKey;
}

/**
 * The attribute's array is allocated from `itemSize`, so before that every record must list
 * exactly `itemSize` values for it: the array then holds no more numbers than the document does.
 * When no record agrees with `itemSize`, the description is what is wrong, and the message says so.
 */
function checkItemSize(records: unknown[], kind: MeshElementKind, name: string, itemSize: number, i: number, fail: Fail): void {
  let agreeing = 0;
  let held = 0;
  let first = -1;
  for (let r = 0; r < records.length; r++) {
    const list = ownList(records[r], name);
    held += list?.length ?? 0;
    if (list?.length === itemSize) agreeing++;
    else if (first < 0) first = r;
  }
  if (first < 0) return;
  if (agreeing === 0) {
    const values = `${plural(held, 'value')} of ${kind} attribute '${name}'`;
    const elements = plural(records.length, kind, kind === 'vertex' ? 'vertices' : `${kind}s`);
    fail(['attributes', i, 'itemSize'], `attributes[${i}].itemSize is ${itemSize}; the document holds ${values} for ${elements}`);
  }
  const wrong = ownList(records[first], name) ? `must be ${plural(itemSize, 'number')}` : 'is missing';
  fail([tables[kind], first, 'attributes', name], `${kind} ${first}: attribute '${name}' ${wrong}`);
}

/** The record's own list of values for attribute `name` (never one found on a prototype), if it has one. */
function ownList(record: unknown, name: string): unknown[] | undefined {
  const values = isObject(record) ? record.attributes : undefined;
  if (!isObject(values) || !Object.hasOwn(values, name)) return undefined;
  const list = values[name];
  return Array.isArray(list) ? list : undefined;
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
  const path = [tables[kind], id, 'attributes'];
  if (!isObject(values)) return fail(path, `${kind} ${id}: 'attributes' must be an object`);
  for (const [key, attribute] of attributes) {
    if (!key.startsWith(`${kind}:`)) continue;
    const { name, type, itemSize, data } = attribute;
    // an own list of itemSize values: checkItemSize made sure of it before allocating the array
    readNumbers(values[name], data, type, itemSize, id, [...path, name], `${kind} ${id}`, `attribute '${name}'`, fail);
  }
  for (const name of Object.keys(values)) {
    if (!attributes.has(`${kind}:${name}`)) fail([...path, name], `${kind} ${id}: attribute '${name}' is not described in 'attributes'`);
  }
}
