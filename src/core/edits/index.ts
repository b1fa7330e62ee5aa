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
 * | `canTriangulateFace`       | `triangulateFace`        | ear clipping (non-convex faces too)          |
 * |                            | `triangulateMesh`        | every face                                   |
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
export { collapseEdge, canCollapseEdge, type CollapseOptions } from './collapse.js';
export { halfedgeFromTo } from './find.js';
export { canFlipEdge, flipEdge, flipEdgeAt } from './flip.js';
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
export { type EditOptions, type EditResult, PointerWriter, type VertexEditResult } from './writer.js';
