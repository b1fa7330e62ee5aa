/**
 * What a subdivision level needs before it starts: the faces its scheme can split (the predicate
 * `cannotSubdivide`, beside the operations that throw its sentence) and a compact mesh.
 */
import { InvalidInputError, TopologyError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { needsTriangles } from '../triangles.js';

export type SubdivisionScheme = 'loop' | 'catmull-clark' | 'butterfly' | 'sqrt3' | 'linear';

export const subdivisionSchemes: readonly SubdivisionScheme[] = ['loop', 'catmull-clark', 'butterfly', 'sqrt3', 'linear'];

const schemeNames: Record<SubdivisionScheme, string> = {
  loop: 'Loop subdivision',
  'catmull-clark': 'Catmull-Clark subdivision',
  butterfly: 'Butterfly subdivision',
  sqrt3: '√3 subdivision',
  linear: 'linear subdivision',
};

/**
 * Null when `scheme` applies to `mesh`, else a sentence saying why not. Catmull-Clark and linear
 * subdivision take any polygons; Loop, Butterfly and √3 need triangles, no two of them sharing two edges (see
 * `twoTrianglesOnTwoEdges`).
 * @example cannotSubdivide(buildMesh(cube()).mesh, 'loop')
 *   // "Loop subdivision needs triangles; f0 is a quad. Triangulate the mesh first."
 * @throws InvalidInputError for an unknown scheme.
 */
export function cannotSubdivide(mesh: HalfedgeMesh, scheme: SubdivisionScheme): string | null {
  if (!Object.hasOwn(schemeNames, scheme)) unknownScheme(scheme);
  if (scheme === 'catmull-clark' || scheme === 'linear') return null;
  const reason = needsTriangles(mesh, schemeNames[scheme]);
  if (reason) return `${reason} Triangulate the mesh first.`;
  return twoTrianglesOnTwoEdges(mesh, schemeNames[scheme]);
}

/**
 * Two triangles that share two edges (so all three corners, as in a pillow of two triangles)
 * cannot be split by Loop, Butterfly or √3: Loop and Butterfly join the midpoints of the two
 * shared edges inside each triangle, and √3 joins the two triangles' centres across each shared
 * edge, twice over — a second edge between the same two vertices, which no file can hold. One
 * pass over the faces, looking across each one's three edges.
 */
function twoTrianglesOnTwoEdges(mesh: HalfedgeMesh, scheme: string): string | null {
  const { heNext, heFace, fHalfedge, fDeleted } = mesh;
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (fDeleted[f]) continue;
    const h = fHalfedge[f];
    const a = heFace[h ^ 1];
    const b = heFace[heNext[h] ^ 1];
    const c = heFace[heNext[heNext[h]] ^ 1];
    const g = a !== -1 && (a === b || a === c) ? a : b !== -1 && b === c ? b : -1;
    if (g !== -1) {
      return `${scheme} cannot split f${f} and f${g}: they share two edges (the same three corners), so it would join two new vertices twice.`;
    }
  }
  return null;
}

/** Throws the error for a scheme name outside `SubdivisionScheme` (from untyped callers). */
export function unknownScheme(scheme: string): never {
  throw new InvalidInputError(`unknown subdivision scheme '${scheme}': use ${subdivisionSchemes.join(', ')}`);
}

/** Throws the `cannotSubdivide` sentence as a `TopologyError` when `scheme` does not apply. */
export function requireApplicable(mesh: HalfedgeMesh, scheme: SubdivisionScheme): void {
  const reason = cannotSubdivide(mesh, scheme);
  if (reason !== null) throw new TopologyError(reason);
}

/**
 * Compacts the mesh when a stepped level is set up, before its first phase runs: that phase's
 * pointer diff is then its own work, not the renumbering (`startLevel` finds the mesh compact).
 */
export function compactAtOnce(mesh: HalfedgeMesh): void {
  if (!mesh.isCompact) mesh.compact();
}

/**
 * Readies the mesh for one level: compacts it (new elements are numbered after the old ones by
 * arithmetic, which needs ids without gaps) and removes its halfedge and edge attributes, which
 * the schemes do not define on the corners and edges they create.
 */
export function startLevel(mesh: HalfedgeMesh): void {
  compactAtOnce(mesh);
  for (const set of [mesh.halfedgeAttributes, mesh.edgeAttributes]) {
    for (const { name } of [...set]) set.remove(name);
  }
}
