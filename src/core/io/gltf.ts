/**
 * glTF 2.0 in (`.glb`, or `.gltf` with its buffers) and out (`.glb`), through glTF-Transform.
 *
 * Reading takes every triangle primitive of every mesh node of the default scene, with the node's
 * transform applied (strips and fans decoded; points and lines noted and skipped). glTF splits a
 * vertex wherever its normal or texture coordinate differs, so each mesh's vertices are welded by
 * position (`weld.ts`) and the normals and texture coordinates kept per face corner: the halfedge
 * mesh is the surface, not a surface cut open along every seam. Writing splits them again.
 *
 * Compressed files (Draco, meshopt) load their decoder only when they need it. Before glTF-Transform
 * sees a file, every buffer, buffer view and accessor is checked against the bytes there are, so a
 * short or lying file gets a `ParseError` naming the accessor or the buffer: by its path in the
 * JSON (`accessors[2].count`), with the line and column of a `.gltf`'s text or the byte offset of
 * a `.glb`'s (see `json-location.ts`).
 *
 * Values are checked as they are read, where their accessor is known: a position that is NaN or
 * infinite (or that a node's transform takes to infinity) refuses the file; a normal or texture
 * coordinate that is dropped, as the other readers drop theirs (`finite.ts`): zeros, with a note.
 */
import { Document, type JSONDocument, type Logger, Primitive, WebIO } from '@gltf-transform/core';
import { EXTMeshoptCompression, KHRDracoMeshCompression, KHRMeshQuantization } from '@gltf-transform/extensions';
import { type FileLocation, ParseError } from '../errors.js';
import { faceHalfedges } from '../circulators.js';
import { faceCornerTriangles } from '../face-triangles.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { SoupAttribute } from '../soup.js';
import { isGlb } from './detect.js';
import { dataUriBytes } from './data-uri.js';
import { droppedValuesNote, nonFiniteWords } from './finite.js';
import { type JsonPath, type JsonText, jsonLocation, pathText, syntaxErrorLocation } from './json-location.js';
import type { MeshFile, ReadOptions } from './mesh-file.js';
import { decodeText } from './text.js';
import { weldPositions } from './weld.js';

export interface GltfReadOptions extends Pick<ReadOptions, 'fileName' | 'weldTolerance'> {
  /** The files a `.gltf` refers to (its `.bin` buffers), by name. */
  resources?: ReadonlyMap<string, Uint8Array<ArrayBuffer>>;
  /**
   * Makes the Draco decoder module (`createDecoderModule()` of `draco3dgltf`), for a file that
   * needs it. By default the package is loaded as Node loads it; a page's worker, where it
   * cannot be, gives its own (the app's loader worker does: `src/ui/draco.ts`).
   */
  dracoDecoder?: () => Promise<unknown>;
}

const FORMAT = 'glTF';
/** What glTF-Transform calls the buffer a `.glb` holds in its BIN chunk. */
const GLB_BUFFER = '@glb.bin';
const JSON_CHUNK = 0x4e4f534a;
const BIN_CHUNK = 0x004e4942;
/** Elements an accessor without data (all zeros, or filled by a decoder) may claim: more is a bomb. */
const MAX_ACCESSOR_COUNT = 1 << 27;
const GEOMETRY_EXTENSIONS = [KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization];

/** The place of the value at a path in the file's JSON. */
type Place = (path: JsonPath) => FileLocation;

/**
 * Reads a `.glb`, or a `.gltf` whose external buffers are in `options.resources`.
 * @throws ParseError naming the byte, or the path to the value in the JSON, that is wrong.
 */
export async function readGltf(bytes: Uint8Array, options: GltfReadOptions = {}): Promise<MeshFile> {
  const notes: string[] = [];
  const binary = isGlb(bytes);
  const io = new WebIO().setLogger(noteLogger(notes)).setStrictResources(false).registerExtensions(GEOMETRY_EXTENSIONS);
  const text: JsonText = binary ? glbJsonText(bytes) : { bytes, start: 0, end: bytes.length, byteOffsets: false };
  const at: Place = (path) => jsonLocation(text, path);
  let json: unknown;
  try {
    json = JSON.parse(decodeText(bytes, text.start, text.end));
  } catch (error) {
    throw new ParseError(FORMAT, syntaxErrorLocation(text), `broken JSON: ${(error as Error).message}`);
  }
  checkShape(json, at);
  // (glTF-Transform reads version 2.0 only)
  if (json.asset?.version !== '2.0') {
    throw new ParseError(FORMAT, at(['asset', 'version']), `asset.version is ${JSON.stringify(json.asset?.version ?? null)?.slice(0, 40)}; only glTF 2.0 is read`);
  }
  const resources = { ...(binary ? glbBinChunk(bytes, text.end) : {}), ...resourcesOf(json, options.resources ?? new Map(), at, notes) };
  const jsonDocument: JSONDocument = { json, resources };
  // the mesh needs geometry only: a required extension for materials or textures does not stop it
  const geometry = new Set<string>(GEOMETRY_EXTENSIONS.map((e) => e.EXTENSION_NAME));
  const ignored = (json.extensionsRequired ?? []).filter((name) => !geometry.has(name));
  if (ignored.length) notes.push(`required extensions ignored (they do not change the geometry): ${ignored.join(', ')}`);
  json.extensionsRequired = (json.extensionsRequired ?? []).filter((name) => geometry.has(name));
  checkData(jsonDocument, at);
  checkReferences(json, at);
  await registerDecoders(io, json.extensionsUsed ?? [], options.dracoDecoder ?? (() => nodeDracoDecoder(at(['extensionsUsed']))));
  let gltf: Document;
  try {
    gltf = await io.readJSON(jsonDocument);
  } catch (error) {
    throw new ParseError(FORMAT, at([]), `cannot read the document: ${(error as Error).message}`);
  }
  return gatherMeshes(gltf, binary, notes, options.weldTolerance ?? 0, at);
}

// -------------------------------------------------------------------------------------------------
// Containers

/**
 * Where a `.glb`'s JSON is: its header and first chunk checked against the file, which the
 * errors after name by byte offset.
 */
function glbJsonText(bytes: Uint8Array): JsonText {
  if (bytes.length < 20) throw new ParseError(FORMAT, { byteOffset: bytes.length }, `a GLB needs a 20-byte header; the file has ${bytes.length} bytes`);
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const version = view.getUint32(4, true);
  if (version !== 2) throw new ParseError(FORMAT, { byteOffset: 4 }, `GLB version ${version}; only version 2 is read`);
  const length = view.getUint32(8, true);
  if (length > bytes.length) throw new ParseError(FORMAT, { byteOffset: 8 }, `the header says the file has ${length} bytes; it has ${bytes.length} (cut short?)`);
  const jsonLength = view.getUint32(12, true);
  if (20 + jsonLength > length) throw new ParseError(FORMAT, { byteOffset: 12 }, `the JSON chunk claims ${jsonLength} bytes; the file has ${length - 20} after the header`);
  if (view.getUint32(16, true) !== JSON_CHUNK) throw new ParseError(FORMAT, { byteOffset: 16 }, 'the first chunk is not JSON: a GLB starts with its JSON chunk');
  return { bytes: bytes.subarray(0, length), start: 20, end: 20 + jsonLength, byteOffsets: true };
}

/** The `.glb`'s BIN chunk after its JSON (which ends at `jsonEnd`), if it has one. */
function glbBinChunk(bytes: Uint8Array, jsonEnd: number): JSONDocument['resources'] {
  const length = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(8, true);
  if (jsonEnd >= length) return {};
  if (jsonEnd + 8 > length) throw new ParseError(FORMAT, { byteOffset: jsonEnd }, `a chunk after the JSON needs an 8-byte header; ${length - jsonEnd} bytes are left`);
  const view = new DataView(bytes.buffer, bytes.byteOffset + jsonEnd, 8);
  // a chunk of another type is an extension's, which the geometry does not need
  if (view.getUint32(4, true) !== BIN_CHUNK) return {};
  const binLength = view.getUint32(0, true);
  if (jsonEnd + 8 + binLength > length) {
    throw new ParseError(FORMAT, { byteOffset: jsonEnd }, `the BIN chunk claims ${binLength} bytes; the file has ${length - jsonEnd - 8} after its header`);
  }
  // a view, not a copy (glTF-Transform's type asks for an ArrayBuffer's bytes; it reads shared ones alike)
  return { [GLB_BUFFER]: bytes.subarray(jsonEnd + 8, jsonEnd + 8 + binLength) as Uint8Array<ArrayBuffer> };
}

/**
 * The bytes of the document's buffers and images, under the names glTF-Transform looks them up
 * by: a `data:` URI decoded here (the URI then replaced by a name), a file found among `files`.
 * Images are not needed for the geometry: one that cannot be had is left out, with a note.
 */
function resourcesOf(json: JSONDocument['json'], files: ReadonlyMap<string, Uint8Array<ArrayBuffer>>, at: Place, notes: string[]): JSONDocument['resources'] {
  const resources: JSONDocument['resources'] = {};
  const byName = new Map([...files].map(([name, data]) => [baseName(name), data]));
  // by the name as written, or by its file name (what a picked or dropped file is called)
  const find = (uri: string) => (uri.startsWith('data:') ? dataUriBytes(uri) : (files.get(uri) ?? byName.get(baseName(safeDecode(uri))) ?? null));
  (json.buffers ?? []).forEach((buffer, i) => {
    const uri = buffer.uri;
    if (uri === undefined) return;
    const data = find(uri);
    if (!data) {
      const why = uri.startsWith('data:') ? 'a data URI whose data is not base64' : `the file '${uri}', which was not given: open it together with this file`;
      throw new ParseError(FORMAT, at(['buffers', i, 'uri']), `buffer ${i} is ${why}`);
    }
    buffer.uri = resourceName('buffer', i, uri);
    resources[buffer.uri] = data;
  });
  (json.images ?? []).forEach((image, i) => {
    const uri = image.uri;
    if (uri === undefined) return;
    const data = find(uri);
    if (data) {
      image.uri = resourceName('image', i, uri);
      resources[image.uri] = data;
    } else if (uri.includes('data:')) {
      // (glTF-Transform would decode any URI that says `data:`, and fail on this one)
      image.uri = `image ${i}, left out`;
      notes.push(`image ${i} is a data URI that cannot be read: left out (it is not needed for the geometry)`);
    }
  });
  return resources;
}

/** The name a resource is found by: a file's URI as written; for a data URI, one of its own. */
function resourceName(kind: string, i: number, uri: string): string {
  return uri.startsWith('data:') ? `@${kind} ${i} (data URI)` : uri;
}

const baseName = (path: string) => path.slice(path.lastIndexOf('/') + 1);

function safeDecode(uri: string): string {
  try {
    return decodeURIComponent(uri);
  } catch {
    return uri;
  }
}

// -------------------------------------------------------------------------------------------------
// Checking the data against the bytes, before anything is allocated from it

const componentBytes: Record<number, number> = { 5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4 };
const typeItems: Record<string, number> = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT2: 4, MAT3: 9, MAT4: 16 };

/** The top-level lists are lists of objects, and every `uri` is text: a hostile document may say otherwise. */
function checkShape(value: unknown, at: Place): asserts value is JSONDocument['json'] {
  if (value === null || typeof value !== 'object' || Array.isArray(value)) throw new ParseError(FORMAT, at([]), 'the JSON is not an object');
  const json = value as Record<string, unknown>;
  const lists = ['buffers', 'bufferViews', 'accessors', 'meshes', 'nodes', 'scenes', 'images', 'materials', 'textures', 'extensionsUsed', 'extensionsRequired'] as const;
  for (const list of lists) {
    const items = json[list];
    if (items === undefined) continue;
    if (!Array.isArray(items)) throw new ParseError(FORMAT, at([list]), `${list} is ${JSON.stringify(items)?.slice(0, 40)}, not a list`);
    items.forEach((item: unknown, i) => {
      const text = list === 'extensionsUsed' || list === 'extensionsRequired';
      if (text ? typeof item !== 'string' : item === null || typeof item !== 'object' || Array.isArray(item)) {
        throw new ParseError(FORMAT, at([list, i]), `${list}[${i}] is ${JSON.stringify(item)?.slice(0, 40)}, not ${text ? 'a name' : 'an object'}`);
      }
      const uri = (item as { uri?: unknown }).uri;
      if (!text && uri !== undefined && typeof uri !== 'string') throw new ParseError(FORMAT, at([list, i, 'uri']), `${list}[${i}].uri is ${JSON.stringify(uri)?.slice(0, 40)}, not text`);
    });
  }
}

function checkData({ json, resources }: JSONDocument, at: Place): void {
  const bufferLengths = (json.buffers ?? []).map((buffer, i) => {
    if (!Number.isInteger(buffer.byteLength) || buffer.byteLength < 0) throw new ParseError(FORMAT, at(['buffers', i, 'byteLength']), `buffer ${i} has no valid byteLength`);
    const uri = buffer.uri;
    if (uri === undefined) {
      // a fallback buffer of EXT_meshopt_compression holds no bytes: its views are decoded
      if (buffer.extensions?.EXT_meshopt_compression) return Infinity;
      return resources[GLB_BUFFER]?.byteLength ?? 0;
    }
    // every buffer's bytes are among the resources (see resourcesOf)
    const length = resources[uri]!.byteLength;
    if (length < buffer.byteLength) throw new ParseError(FORMAT, at(['buffers', i, 'byteLength']), `buffer ${i} is ${length} bytes, shorter than its byteLength ${buffer.byteLength}`);
    return buffer.byteLength;
  });
  const viewLengths = (json.bufferViews ?? []).map((view, i) => {
    const offset = view.byteOffset ?? 0;
    const meshopt = view.extensions?.EXT_meshopt_compression as { buffer: number; byteOffset?: number; byteLength: number } | undefined;
    const source = meshopt ? { buffer: meshopt.buffer, offset: meshopt.byteOffset ?? 0, length: meshopt.byteLength } : { buffer: view.buffer, offset, length: view.byteLength };
    const available = bufferLengths[source.buffer];
    const path = meshopt ? ['bufferViews', i, 'extensions', 'EXT_meshopt_compression'] : ['bufferViews', i];
    if (available === undefined) throw new ParseError(FORMAT, at([...path, 'buffer']), `bufferView ${i} refers to buffer ${source.buffer}, which does not exist (there are ${bufferLengths.length})`);
    if (!(source.offset >= 0 && source.length >= 0 && source.offset + source.length <= available)) {
      throw new ParseError(FORMAT, at(path), `bufferView ${i} needs bytes ${source.offset}…${source.offset + source.length} of buffer ${source.buffer}, which has ${available}`);
    }
    return view.byteLength;
  });
  (json.accessors ?? []).forEach((accessor, i) => {
    const size = componentBytes[accessor.componentType];
    const items = typeItems[accessor.type];
    if (!size || !items) throw new ParseError(FORMAT, at(['accessors', i]), `accessor ${i} has componentType ${accessor.componentType} and type ${accessor.type}, which glTF does not define`);
    if (!(Number.isInteger(accessor.count) && accessor.count >= 0 && accessor.count <= MAX_ACCESSOR_COUNT)) {
      throw new ParseError(FORMAT, at(['accessors', i, 'count']), `accessor ${i} claims ${accessor.count} elements (at most ${MAX_ACCESSOR_COUNT} are read)`);
    }
    if (accessor.bufferView === undefined) return;
    const length = viewLengths[accessor.bufferView];
    if (length === undefined) throw new ParseError(FORMAT, at(['accessors', i, 'bufferView']), `accessor ${i} refers to bufferView ${accessor.bufferView}, which does not exist`);
    const stride = json.bufferViews![accessor.bufferView].byteStride ?? size * items;
    const end = (accessor.byteOffset ?? 0) + (accessor.count === 0 ? 0 : (accessor.count - 1) * stride + size * items);
    if (end > length) throw new ParseError(FORMAT, at(['accessors', i]), `accessor ${i} needs ${end} bytes of bufferView ${accessor.bufferView}, which has ${length}`);
  });
}

/**
 * Every index a scene, node or mesh primitive gives names an element there is, and the lists they
 * are in are lists: glTF-Transform fails on any other without saying where.
 */
function checkReferences(json: JSONDocument['json'], at: Place): void {
  const counts = { scenes: json.scenes?.length ?? 0, nodes: json.nodes?.length ?? 0, meshes: json.meshes?.length ?? 0, accessors: json.accessors?.length ?? 0 };
  const index = (value: unknown, path: JsonPath, list: keyof typeof counts) => {
    if (value === undefined || (Number.isInteger(value) && (value as number) >= 0 && (value as number) < counts[list])) return;
    throw new ParseError(FORMAT, at(path), `${pathText(path)} is ${JSON.stringify(value)?.slice(0, 40)}, which names none of the ${counts[list]} ${list}`);
  };
  const indices = (value: unknown, path: JsonPath, list: keyof typeof counts) => {
    if (value === undefined) return;
    if (!Array.isArray(value)) throw new ParseError(FORMAT, at(path), `${pathText(path)} is ${JSON.stringify(value)?.slice(0, 40)}, not a list`);
    value.forEach((item: unknown, k) => index(item, [...path, k], list));
  };
  index(json.scene, ['scene'], 'scenes');
  (json.scenes ?? []).forEach((scene, i) => indices(scene.nodes, ['scenes', i, 'nodes'], 'nodes'));
  (json.nodes ?? []).forEach((node, i) => {
    indices(node.children, ['nodes', i, 'children'], 'nodes');
    index(node.mesh, ['nodes', i, 'mesh'], 'meshes');
  });
  (json.meshes ?? []).forEach((mesh, m) => {
    const primitives: unknown = mesh.primitives;
    if (!Array.isArray(primitives)) throw new ParseError(FORMAT, at(['meshes', m, 'primitives']), `mesh ${m} has no list of primitives`);
    primitives.forEach((primitive: unknown, p) => {
      const path = ['meshes', m, 'primitives', p];
      const { attributes, indices: indexAccessor } = (primitive ?? {}) as { attributes?: unknown; indices?: unknown };
      if (primitive === null || typeof primitive !== 'object' || attributes === null || typeof attributes !== 'object') {
        throw new ParseError(FORMAT, at(path), `mesh ${m}'s primitive ${p} is not an object with attributes`);
      }
      index(indexAccessor, [...path, 'indices'], 'accessors');
      for (const [semantic, accessor] of Object.entries(attributes)) index(accessor, [...path, 'attributes', semantic], 'accessors');
    });
  });
}

/** Decoders are loaded only for a file that is compressed with them. */
async function registerDecoders(io: WebIO, used: string[], dracoDecoder: () => Promise<unknown>): Promise<void> {
  if (used.includes('EXT_meshopt_compression')) {
    const { MeshoptDecoder } = await import('meshoptimizer/decoder');
    await MeshoptDecoder.ready;
    io.registerDependencies({ 'meshopt.decoder': MeshoptDecoder });
  }
  if (used.includes('KHR_draco_mesh_compression')) io.registerDependencies({ 'draco3d.decoder': await dracoDecoder() });
}

/** The Draco decoder as Node loads it, from the `draco3dgltf` package; `usedAt`: where the file says it needs it. */
async function nodeDracoDecoder(usedAt: FileLocation): Promise<unknown> {
  // a name the page's bundler does not follow: the package's script is for Node (a page gives its own, see GltfReadOptions)
  const name = 'draco3dgltf';
  let draco: { default?: DracoModule } & DracoModule;
  try {
    draco = (await import(/* @vite-ignore */ name)) as typeof draco;
  } catch {
    throw new ParseError(FORMAT, usedAt, 'the file is Draco-compressed, and no Draco decoder could be loaded here: `halfedge-lab convert FILE.glb OUT.glb` writes it uncompressed');
  }
  return (draco.default ?? draco).createDecoderModule();
}

interface DracoModule {
  createDecoderModule(): Promise<unknown>;
}

/** glTF-Transform's warnings become notes for the report (an unresolved image, an unknown extension). */
function noteLogger(notes: string[]): Logger {
  const ignore = () => {};
  return { debug: ignore, info: ignore, warn: (text: string) => notes.push(text), error: (text: string) => notes.push(text) } as unknown as Logger;
}

// -------------------------------------------------------------------------------------------------
// Meshes to a soup

const MODE_NAMES = ['points', 'lines', 'line loops', 'line strips'];


function gatherMeshes(gltf: Document, binary: boolean, notes: string[], tolerance: number, at: Place): MeshFile {
  const root = gltf.getRoot();
  const scene = root.getDefaultScene() ?? root.listScenes()[0];
  if (!scene) throw new ParseError(FORMAT, at(['scenes']), 'the file has no scene, so no mesh is placed');
  /** Normals and texture coordinates that were NaN or infinite, by semantic: how many, and the first. */
  const dropped = new Map<string, { count: number; first: string; location: FileLocation }>();
  // every node's welded vertices, and per corner: its vertex, texture coordinate and normal
  const out = { positions: [] as number[], corners: [] as number[], texcoords: [] as number[], normals: [] as number[], hasTexcoords: false, hasNormals: false };
  let fileVertices = 0;
  let welded = 0;
  let skipped = 0;
  const faceStarts = [0];
  scene.traverse((node) => {
    const mesh = node.getMesh();
    if (!mesh) return;
    const nodeIndex = root.listNodes().indexOf(node);
    const meshIndex = root.listMeshes().indexOf(mesh);
    const name = node.getName() || mesh.getName() || `node ${nodeIndex}`;
    const matrix = node.getWorldMatrix();
    const normalMatrix = cofactor3(matrix);
    const mirrored = determinant3(matrix) < 0;
    // this node's vertices, then its triangles as indices into them
    const local = { positions: [] as number[], corners: [] as number[] };
    const localTexcoord: (number[] | null)[] = [];
    const localNormal: (number[] | null)[] = [];
    for (const [primitiveIndex, primitive] of mesh.listPrimitives().entries()) {
      const primitivePath = ['meshes', meshIndex, 'primitives', primitiveIndex];
      const attributePath = (semantic: string) => [...primitivePath, 'attributes', semantic];
      const mode = primitive.getMode();
      if (mode < Primitive.Mode.TRIANGLES) {
        notes.push(`${name}: a primitive of ${MODE_NAMES[mode] ?? `mode ${mode}`} was skipped (only triangles make faces)`);
        continue;
      }
      const position = primitive.getAttribute('POSITION');
      if (!position) {
        notes.push(`${name}: a primitive without POSITION was skipped`);
        continue;
      }
      const base = local.positions.length / 3;
      const count = position.getCount();
      const texcoord = primitive.getAttribute('TEXCOORD_0');
      const normal = primitive.getAttribute('NORMAL');
      for (const [semantic, accessor, type] of [['POSITION', position, 'VEC3'], ['NORMAL', normal, 'VEC3'], ['TEXCOORD_0', texcoord, 'VEC2']] as const) {
        if (accessor && accessor.getType() !== type) throw new ParseError(FORMAT, at(attributePath(semantic)), `${name}: ${semantic} is accessor ${root.listAccessors().indexOf(accessor)} of type ${accessor.getType()}; glTF says ${type}`);
        if (accessor && accessor.getCount() !== count) throw new ParseError(FORMAT, at(attributePath(semantic)), `${name}: ${semantic} has ${accessor.getCount()} elements but POSITION has ${count}`);
      }
      /** A normal or texture coordinate that is not finite is dropped (null: zeros, as when there is none). */
      const finiteOrDropped = (values: number[] | null, semantic: string, i: number): number[] | null => {
        if (values === null || values.every(Number.isFinite)) return values;
        const entry = dropped.get(semantic);
        if (entry) entry.count++;
        else dropped.set(semantic, { count: 1, first: `vertex ${i} of ${name} (primitive ${primitiveIndex})`, location: at(attributePath(semantic)) });
        return null;
      };
      const p = [0, 0, 0];
      for (let i = 0; i < count; i++) {
        position.getElement(i, p);
        const item = p.findIndex((x) => !Number.isFinite(x));
        if (item >= 0) {
          throw new ParseError(FORMAT, at(attributePath('POSITION')), `${name}: vertex ${i}'s position (item ${item}) ${nonFiniteWords(p[item], 'float32')}`);
        }
        const point = transformPoint(matrix, p);
        if (!point.every(Number.isFinite)) {
          throw new ParseError(FORMAT, at(['nodes', nodeIndex]), `${name}: the node's transform takes vertex ${i} (${p.join(', ')}) of primitive ${primitiveIndex} beyond the range of a double`);
        }
        local.positions.push(...point);
        localTexcoord.push(finiteOrDropped(texcoord ? texcoord.getElement(i, [0, 0]) : null, 'TEXCOORD_0', i));
        localNormal.push(finiteOrDropped(normal ? transformNormal(normalMatrix, normal.getElement(i, [0, 0, 0])) : null, 'NORMAL', i));
      }
      out.hasTexcoords ||= texcoord !== null;
      out.hasNormals ||= normal !== null;
      const indices = primitive.getIndices();
      const indexCount = indices ? indices.getCount() : count;
      const index = (k: number) => {
        const value = indices ? indices.getScalar(k) : k;
        if (!(value >= 0 && value < count)) {
          throw new ParseError(FORMAT, at([...primitivePath, 'indices']), `${name}: index ${k} of accessor ${root.listAccessors().indexOf(indices!)} is ${value}, but the primitive has ${count} vertices`);
        }
        return base + value;
      };
      const triangle = (a: number, b: number, c: number) => {
        if (a === b || b === c || c === a) return void skipped++;
        if (mirrored) local.corners.push(a, c, b);
        else local.corners.push(a, b, c);
      };
      if (mode === Primitive.Mode.TRIANGLES) for (let k = 0; k + 2 < indexCount; k += 3) triangle(index(k), index(k + 1), index(k + 2));
      else if (mode === Primitive.Mode.TRIANGLE_STRIP) for (let k = 0; k + 2 < indexCount; k++) k % 2 === 0 ? triangle(index(k), index(k + 1), index(k + 2)) : triangle(index(k + 1), index(k), index(k + 2));
      else for (let k = 1; k + 1 < indexCount; k++) triangle(index(0), index(k), index(k + 1));
    }
    fileVertices += local.positions.length / 3;
    // the node's vertices welded by position: seams close, each corner keeps its own values
    const weld = weldPositions(local.positions, tolerance);
    const offset = out.positions.length / 3;
    welded += local.positions.length / 3 - weld.positions.length / 3;
    for (const x of weld.positions) out.positions.push(x);
    const firstFace = faceStarts.length - 1;
    for (let k = 0; k < local.corners.length; k++) {
      const vertex = local.corners[k];
      out.corners.push(offset + weld.remap[vertex]);
      out.texcoords.push(...(localTexcoord[vertex] ?? [0, 0]));
      out.normals.push(...(localNormal[vertex] ?? [0, 0, 0]));
      if (k % 3 === 2) faceStarts.push(out.corners.length);
    }
    notes.push(`${name}: ${weld.positions.length / 3} vertices, ${faceStarts.length - 1 - firstFace} triangles (faces ${firstFace}…${faceStarts.length - 2})`);
  });
  if (faceStarts.length === 1) throw new ParseError(FORMAT, at(['scenes', root.listScenes().indexOf(scene)]), 'the default scene has no triangles');
  for (const [semantic, { count, first, location }] of dropped) {
    const values = semantic === 'NORMAL' ? 'glTF vertex normal' : 'glTF vertex texture coordinate';
    notes.push(droppedValuesNote(count, values, 'set to zero', first, location));
  }
  if (welded > 0) {
    const how = tolerance > 0 ? `within ${tolerance}` : 'at equal positions';
    notes.unshift(`welded ${fileVertices} glTF vertices into ${out.positions.length / 3} (${welded} joined ${how}, where the file splits a vertex along a seam of normals or texture coordinates); those values are kept per face corner`);
  }
  if (skipped > 0) notes.push(`${skipped} triangles with a repeated index were skipped (strips use them as joints)`);
  const cornerAttributes: SoupAttribute[] = [];
  if (out.hasTexcoords) cornerAttributes.push({ name: 'texcoord', itemSize: 2, data: Float32Array.from(out.texcoords) });
  if (out.hasNormals) cornerAttributes.push({ name: 'normal', itemSize: 3, data: Float32Array.from(out.normals) });
  return {
    format: 'gltf',
    encoding: binary ? 'binary_little_endian' : 'ascii',
    soup: { positions: Float64Array.from(out.positions), faceStarts: Uint32Array.from(faceStarts), faceIndices: Uint32Array.from(out.corners), cornerAttributes },
    counts: { vertices: fileVertices, faces: faceStarts.length - 1 },
    comments: [],
    notes,
  };
}

function transformPoint(m: ArrayLike<number>, [x, y, z]: number[]): number[] {
  return [m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13], m[2] * x + m[6] * y + m[10] * z + m[14]];
}

/** The cofactor matrix of the upper 3 × 3 (the inverse transpose times the determinant): it carries normals. */
function cofactor3(m: ArrayLike<number>): number[] {
  const [a, b, c, d, e, f, g, h, i] = [m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]];
  return [e * i - f * h, f * g - d * i, d * h - e * g, c * h - b * i, a * i - c * g, b * g - a * h, b * f - c * e, c * d - a * f, a * e - b * d];
}

function determinant3(m: ArrayLike<number>): number {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[4] * (m[1] * m[10] - m[2] * m[9]) + m[8] * (m[1] * m[6] - m[2] * m[5]);
}

function transformNormal(c: number[], [x, y, z]: number[]): number[] {
  const n = [c[0] * x + c[3] * y + c[6] * z, c[1] * x + c[4] * y + c[7] * z, c[2] * x + c[5] * y + c[8] * z];
  const length = Math.hypot(n[0], n[1], n[2]);
  return length > 0 ? n.map((v) => v / length) : n;
}

// -------------------------------------------------------------------------------------------------
// Writing

/**
 * The mesh as a `.glb`: one node, one triangle primitive. Faces are triangulated (glTF holds only
 * triangles); a vertex is split wherever its corners carry different normals or texture
 * coordinates (halfedge attributes `normal` and `texcoord`), as glTF needs.
 */
export async function writeGlb(mesh: HalfedgeMesh): Promise<Uint8Array> {
  const { heVertex, positions } = mesh;
  const texcoord = mesh.halfedgeAttributes.get('texcoord');
  const normal = mesh.halfedgeAttributes.get('normal');
  const vertexOf = new Map<string, number>();
  const outPositions: number[] = [];
  const outTexcoords: number[] = [];
  const outNormals: number[] = [];
  const indices: number[] = [];
  const cornerVertex = (h: number): number => {
    const v = heVertex[h];
    const uv = texcoord ? Array.from(texcoord.data.subarray(2 * h, 2 * h + 2)) : [];
    const n = normal ? Array.from(normal.data.subarray(3 * h, 3 * h + 3)) : [];
    const key = texcoord || normal ? `${v} ${uv.join(' ')} ${n.join(' ')}` : String(v);
    let out = vertexOf.get(key);
    if (out === undefined) {
      out = outPositions.length / 3;
      vertexOf.set(key, out);
      outPositions.push(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      outTexcoords.push(...uv);
      outNormals.push(...n);
    }
    return out;
  };
  for (const f of mesh.faces()) {
    const loop = [...faceHalfedges(mesh, f)];
    for (const corner of faceCornerTriangles(mesh, f, loop.map((h) => heVertex[h]))) indices.push(cornerVertex(loop[corner]));
  }
  // a vertex no face uses is written too (no triangle names it), so reading back keeps it
  const used = new Uint8Array(mesh.vertexSlots);
  for (const h of mesh.halfedges()) if (mesh.heFace[h] !== -1) used[heVertex[h]] = 1;
  for (const v of mesh.vertices()) {
    if (used[v]) continue;
    outPositions.push(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    if (texcoord) outTexcoords.push(0, 0);
    if (normal) outNormals.push(0, 0, 0);
  }
  const gltf = new Document();
  const buffer = gltf.createBuffer();
  const primitive = gltf
    .createPrimitive()
    .setAttribute('POSITION', gltf.createAccessor().setType('VEC3').setArray(Float32Array.from(outPositions)).setBuffer(buffer))
    .setIndices(gltf.createAccessor().setType('SCALAR').setArray(Uint32Array.from(indices)).setBuffer(buffer));
  if (texcoord) primitive.setAttribute('TEXCOORD_0', gltf.createAccessor().setType('VEC2').setArray(Float32Array.from(outTexcoords)).setBuffer(buffer));
  if (normal) primitive.setAttribute('NORMAL', gltf.createAccessor().setType('VEC3').setArray(Float32Array.from(outNormals)).setBuffer(buffer));
  const node = gltf.createNode('mesh').setMesh(gltf.createMesh('mesh').addPrimitive(primitive));
  gltf.getRoot().setDefaultScene(gltf.createScene('scene').addChild(node));
  return new WebIO().writeBinary(gltf);
}
