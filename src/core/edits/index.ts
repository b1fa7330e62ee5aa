/**
 * The local edits of every halfedge lecture, each beside a predicate that says why it does not
 * apply (pmp's `is_flip_ok` then `flip`):
 *
 * | predicate                  | edit                     |                                              |
 * |----------------------------|--------------------------|----------------------------------------------|
 * | `canFlipEdge`              | `flipEdge`               | turn the edge between two triangles          |
 * | `canSplitEdge`             | `splitEdge`              | a vertex on an edge; the faces gain a side   |
 * | `canSplitEdgeTriangulated` | `splitEdgeTriangulated`  | the same, and the triangles split through it |
 * | `canCollapseEdge`          | `collapseEdge`           | an edge shrinks to a point (link condition)  |
 * | `canSplitFace`             | `splitFace`              | an edge between two corners of a face        |
 * | `canPokeFace`              | `pokeFace`               | a fan of triangles around the centroid       |
 * | `canMergeFaces`            | `mergeFaces`             | erase an edge, joining its two faces         |
 * | `canDissolveEdge`          | `dissolveEdge`           | the same, or a boundary edge's face → a hole |
 * | `canDissolveVertex`        | `dissolveVertex`         | a vertex goes, its faces merge into one      |
 * | `canMakeBoundary`          | `makeBoundary`           | a face becomes a hole (merging with holes)   |
 * | `canWeldEdges`             | `weldEdges`              | two boundary edges glued into one edge       |
 * | `canTriangulateFace`       | `triangulateFace`        | ear clipping (non-convex faces too)          |
 * |                            | `triangulateMesh`        | every face                                   |
 * | `canExtrudeFace`           | `extrudeFace`            | a ring of quads around a face, moved, inset  |
 * | `canBevelVertex`           | `bevelVertex`            | a face replaces a vertex                     |
 * | `canBevelEdge`             | `bevelEdge`              | a face replaces an edge                      |
 * | `canCollapseFace`          | `collapseFace`           | a face shrinks to a vertex at its centroid   |
 *
 * A predicate returns null when the edit applies, else a sentence naming the elements; the edit
 * throws a `TopologyError` with that sentence if called anyway. Each edit returns an
 * `EditResult`: the pointer fields it changed (as `diffPointers` would list them) and the ids it
 * created and removed. Removed elements are marked deleted, not compacted, so ids stay stable.
 *
 * @example
 *   const why = canCollapseEdge(mesh, e);
 *   if (why) showMessage(why);
 *   else highlight(collapseEdge(mesh, e).changes);
 */
export { bevelEdge, bevelVertex, type BevelOptions, canBevelEdge, canBevelVertex } from './bevel.js';
export { collapseEdge, canCollapseEdge, type CollapseOptions } from './collapse.js';
export { canCollapseFace, collapseFace } from './collapse-face.js';
export { canDissolveEdge, canDissolveVertex, dissolveEdge, dissolveVertex } from './dissolve.js';
export { canExtrudeFace, extrudeFace, type ExtrudeOptions, type ExtrudePlacement } from './extrude.js';
export { halfedgeFromTo } from './find.js';
export { canFlipEdge, flipEdge, flipEdgeAt } from './flip.js';
export { canMakeBoundary, makeBoundary } from './make-boundary.js';
export { canMergeFaces, mergeFaces, type MergeResult } from './merge.js';
export { canPokeFace, pokeFace } from './poke.js';
export {
  canSplitEdge,
  canSplitEdgeTriangulated,
  splitEdge,
  splitEdgeAt,
  splitEdgeTriangulated,
  type SplitEdgeOptions,
} from './split-edge.js';
export { canSplitFace, type FaceSplitResult, splitFace, splitFaceAt } from './split-face.js';
export {
  canTriangulateFace,
  fillRings,
  planeBasis,
  triangulateFace,
  triangulateMesh,
  type TriangulateMeshResult,
  triangulatePolygon,
} from './triangulate.js';
export { canWeldEdges, weldEdges } from './weld.js';
export {
  type EdgeEditResult,
  type EditOptions,
  type EditResult,
  type FaceEditResult,
  type HalfedgeEditResult,
  PointerWriter,
  type VertexEditResult,
} from '../change/writer.js';
