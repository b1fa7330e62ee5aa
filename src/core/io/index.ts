/**
 * Mesh files in and out: pure functions on bytes, so they run the same in Node, a Web Worker and
 * a page.
 *
 * - `readMesh(bytes)` reads PLY (ascii and both binary byte orders), OFF (text and binary), OBJ
 *   and STL (ascii and binary) into a polygon soup, faces kept as polygons, attributes attached
 *   under the names `normal`, `color` and `texcoord` (per vertex, face or face corner).
 * - `readMeshAsync(bytes)` reads those and glTF 2.0 (`.glb`, `.gltf` with its buffers), welding
 *   the vertices glTF splits along seams and keeping their normals and UVs per corner.
 * - `writeMesh(mesh, format)` writes PLY, binary PLY, OFF or OBJ; reading the result back gives
 *   the same soup; `writeMeshAsync(mesh, 'glb')` writes binary glTF too.
 * - `meshToHalfedgeJSON` / `meshFromHalfedgeJSON` write and read the halfedge tables themselves.
 *
 * Every malformed file raises `ParseError` with the place: line and column, byte offset, or the
 * path to the value in a JSON file (glTF, halfedge JSON). A position that is NaN or infinite
 * refuses the file; any other such value is dropped, with a note (`finite.ts`).
 */
export { detectFormat, formatFromFileName } from './detect.js';
export * from './halfedge-json.js';
export type { Encoding, MeshFile, MeshFormat, ReadOptions } from './mesh-file.js';
export type { GltfReadOptions } from './gltf.js';
export { gltfBufferUris } from './gltf-buffers.js';
export { readMesh, readMeshAsync } from './read.js';
export { weldPositions } from './weld.js';
export { meshToSoup, type WriteFormat, writeFormatFromFileName, writeMesh, writeMeshAsync, writeSoup } from './write.js';
