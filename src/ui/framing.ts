/**
 * Where a selection lies, for the camera: the faces at it, the way they face, and the corners
 * that framing shows whole.
 */
import { Box3, Vector3 } from 'three';
import { boundaryLoops, boundingBox, boundingSphere, faceVectorArea, faceVertices, type HalfedgeMesh, loopHalfedges, vertexAdjacentFaces } from '../core/index.js';
import type { BoundaryLoop } from './panels/hud.js';
import { selectionHighlight } from './highlights.js';
import type { Convention } from './records.js';
import type { Selection } from './selection.js';

/** What the camera fits into the view: a box, and the radius of a sphere around it. */
export interface Bounds {
  box: Box3;
  radius: number;
}

/** The whole mesh. */
export function meshBounds(mesh: HalfedgeMesh): Bounds {
  const box = boundingBox(mesh);
  if (!box) return { box: new Box3(), radius: 0 };
  return { box: new Box3(new Vector3(...box.min), new Vector3(...box.max)), radius: boundingSphere(mesh, box)!.radius };
}

/** An element, the faces around it and everything its highlight draws (the arrows of its pointers). */
export function selectionBounds(mesh: HalfedgeMesh, s: Selection, convention: Convention): Bounds {
  const points = neighbourhoodPoints(mesh, s);
  const spec = selectionHighlight(mesh, s, convention);
  for (const { id } of spec.vertices) points.push(new Vector3(...mesh.position(id)));
  for (const { id } of spec.halfedges) points.push(new Vector3(...mesh.position(mesh.origin(id))), new Vector3(...mesh.position(mesh.target(id))));
  const box = new Box3().setFromPoints(points);
  const centre = box.getCenter(new Vector3());
  // a sphere around the points, with a margin for the arrows and labels at the rim
  const radius = 1.1 * Math.max(1e-9, ...points.map((p) => p.distanceTo(centre)));
  return { box, radius };
}

/** Each boundary loop of the mesh: one of its halfedges and its number of edges, in the order of the halfedge ids. */
export function boundaryLoopList(mesh: HalfedgeMesh): BoundaryLoop[] {
  return [...boundaryLoops(mesh)].map((halfedge) => ({ halfedge, length: [...loopHalfedges(mesh, halfedge)].length }));
}

/**
 * A boundary loop's corners, and the way to look at it: along the loop's axis (its vector area,
 * which for the rim of a tube points down the tube) from the side its faces face, so the whole
 * rim shows as a ring rather than edge-on.
 */
export function loopBounds(mesh: HalfedgeMesh, h: number): Bounds & { facing: Vector3 | null } {
  const points: Vector3[] = [];
  const axis = new Vector3();
  const faces = new Vector3();
  const area = [0, 0, 0];
  for (const g of loopHalfedges(mesh, h)) {
    const a = new Vector3(...mesh.position(mesh.origin(g)));
    points.push(a);
    axis.add(a.clone().cross(new Vector3(...mesh.position(mesh.target(g)))));
    const f = mesh.face(mesh.twin(g));
    if (f >= 0) faces.add(new Vector3(...faceVectorArea(mesh, f, area)));
  }
  if (axis.dot(faces) < 0) axis.negate();
  const facing = axis.lengthSq() > 0 ? axis.normalize() : faces.lengthSq() > 0 ? faces.normalize() : null;
  const box = new Box3().setFromPoints(points);
  const centre = box.getCenter(new Vector3());
  // a loop may run around a whole cut: too many points to spread into Math.max
  const radius = 1.1 * points.reduce((r, p) => Math.max(r, p.distanceTo(centre)), 1e-9);
  return { box, radius, facing };
}

/** The faces at a selection: the face itself, the two beside a halfedge or edge, the fan of a vertex. */
export function facesAt(mesh: HalfedgeMesh, s: Selection): number[] {
  if (s.kind === 'face') return [s.id];
  if (s.kind === 'halfedge' || s.kind === 'edge') {
    const h = s.kind === 'edge' ? mesh.edgeHalfedge(s.id) : s.id;
    return [mesh.face(h), mesh.face(mesh.twin(h))].filter((f) => f >= 0);
  }
  return [...vertexAdjacentFaces(mesh, s.id)];
}

/** The way the faces at a selection face (the sum of their vector areas), or null when it has none. */
export function selectionFacing(mesh: HalfedgeMesh, s: Selection): Vector3 | null {
  const sum = new Vector3();
  const area = [0, 0, 0];
  for (const f of facesAt(mesh, s)) sum.add(new Vector3(...faceVectorArea(mesh, f, area)));
  return sum.lengthSq() > 0 ? sum.normalize() : null;
}

/** The corners of the faces at a selection (its neighbourhood, which framing shows whole). */
export function neighbourhoodPoints(mesh: HalfedgeMesh, s: Selection): Vector3[] {
  const points: Vector3[] = [];
  for (const f of facesAt(mesh, s)) for (const v of faceVertices(mesh, f)) points.push(new Vector3(...mesh.position(v)));
  return points;
}
