/**
 * Mesh files in and out: pure functions on bytes, so they run the same in Node, a Web Worker and
 * a page.
 *
 * - `readMesh(bytes)` reads PLY (ascii and both binary byte orders), OFF (text and binary), OBJ
 *   and STL (ascii and binary) into a polygon soup, faces kept as polygons, attributes attached
 *   under the names `normal`, `color` and `texcoord` (per vertex, face or face corner).
 * - `writeMesh(mesh, format)` writes PLY, binary PLY, OFF or OBJ; reading the result back gives
 *   the same soup.
 * - `meshToHalfedgeJSON` / `meshFromHalfedgeJSON` write and read the halfedge tables themselves.
 *
 * Every malformed file raises `ParseError` with the place: line and column, or byte offset.
 */
export { detectFormat, formatFromFileName } from './detect.js';
export * from './halfedge-json.js';
export type { Encoding, MeshFile, MeshFormat, ReadOptions } from './mesh-file.js';
export { readMesh } from './read.js';
export { meshToSoup, type WriteFormat, writeFormatFromFileName, writeMesh, writeSoup } from './write.js';
