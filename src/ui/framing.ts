/**
 * Where a selection lies, for the camera: the faces at it, the way they face, and the corners
 * that framing shows whole.
 */
import { Box3, Vector3 } from 'three';
import {
  boundaryLoops,
  faceCentroid,
  faceVectorArea,
  faceVertices,
  type HalfedgeMesh,
  loopHalfedges,
  type RepairIncident,
  type RepairKind,
  vertexAdjacentFaces,
} from '../core/index.js';
import type { BoundaryLoop } from './panels/hud.js';
import { selectionHighlight } from './highlights.js';
import type { Convention } from './records.js';
import type { Selection } from './selection.js';

/** What the camera fits into the view: a box, and the radius of a sphere around it. */
export interface Bounds {
  box: Box3;
  radius: number;
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

/**
 * How far towards their edge the camera turns from straight across it, looking at faces that meet
 * along one (0: across it, 90: along it). Straight across, two of three pages 120° apart lie one
 * behind the other; turned a little, they come apart on screen, each page still seen from more
 * than 25° off edge-on.
 */
const BOOK_TILT_DEGREES = 30;

/**
 * A repair's faces (those it names, and the fans around the vertices it names), and the way to
 * look at them so that none is seen edge-on; `from` is the way the camera looks from now, whose
 * side is kept. Faces that meet along one edge (three on an edge, two cut apart along a seam)
 * stand around it like the pages of an open book: the camera looks from between two pages, as far
 * from every page as it can, turned a little along the edge, so each page shows beside the others
 * rather than behind them. The fans of a pinched vertex are seen from where they face, or from
 * the side when they face opposite ways (see `fansView`).
 */
export function incidentBounds(mesh: HalfedgeMesh, incident: RepairIncident, kind: RepairKind, from: Vector3): Bounds & { facing: Vector3 | null } {
  const vertices = (incident.vertices ?? []).filter((v) => v < mesh.vertexSlots && !mesh.vDeleted[v]);
  const faces = new Set((incident.faces ?? []).filter((f) => f < mesh.faceSlots && !mesh.fDeleted[f]));
  for (const v of vertices) for (const f of vertexAdjacentFaces(mesh, v)) faces.add(f);
  const points: Vector3[] = vertices.map((v) => new Vector3(...mesh.position(v)));
  for (const f of faces) for (const v of faceVertices(mesh, f)) points.push(new Vector3(...mesh.position(v)));
  const box = new Box3().setFromPoints(points);
  const centre = box.getCenter(new Vector3());
  const radius = 1.1 * points.reduce((r, p) => Math.max(r, p.distanceTo(centre)), 1e-9);
  const edge = (kind === 'non-manifold-edge' || kind === 'non-orientable') && vertices.length >= 2 ? vertices.slice(0, 2) : null;
  // a pinch's fans one by one, any other repair's faces together
  const groups = kind === 'non-manifold-vertex' ? vertices.map((v) => [...vertexAdjacentFaces(mesh, v)]) : [[...faces]];
  return { box, radius, facing: edge ? bookView(mesh, edge, [...faces], from) : fansView(mesh, groups, from) };
}

/** Looking at pages standing around the edge a–b, from between two of them (see `incidentBounds`). */
function bookView(mesh: HalfedgeMesh, [a, b]: number[], faces: number[], from: Vector3): Vector3 | null {
  const start = new Vector3(...mesh.position(a));
  const along = new Vector3(...mesh.position(b)).sub(start).normalize();
  if (along.lengthSq() === 0) return null;
  // each page's way out from the edge, square to it
  const pages = faces.map((f) => new Vector3(...faceCentroid(mesh, f)).sub(start).projectOnPlane(along).normalize());
  const across = new Vector3(1, 0, 0).cross(along).lengthSq() > 0.1 ? new Vector3(1, 0, 0).cross(along) : new Vector3(0, 1, 0).cross(along);
  across.normalize();
  const up = along.clone().cross(across);
  // the way across the edge furthest from the nearest page (in steps of 5°, either side alike)
  let best = across;
  let bestSine = -1;
  for (let degrees = 0; degrees < 180; degrees += 5) {
    const angle = (degrees * Math.PI) / 180;
    const side = across.clone().multiplyScalar(Math.cos(angle)).addScaledVector(up, Math.sin(angle));
    const sine = Math.min(...pages.map((page) => page.clone().cross(side).length()));
    if (sine > bestSine) [best, bestSine] = [side, sine];
  }
  // keep the side of the edge, and the end of it, the camera is on
  if (best.dot(from) < 0) best.negate();
  if (along.dot(from) < 0) along.negate();
  const tilt = (BOOK_TILT_DEGREES * Math.PI) / 180;
  return best.multiplyScalar(Math.cos(tilt)).addScaledVector(along, Math.sin(tilt)).normalize();
}

/**
 * Looking at groups of faces (the fans of a pinched vertex, a group a fan): square to the line
 * through the centres of the first two fans, so that one never hides the other (two fans side by
 * side, like a bowtie, are then seen face on; two cones tip to tip from the side); and of those
 * ways, the one nearest the way the faces face together (the sum of their vector areas), else the
 * camera's.
 */
function fansView(mesh: HalfedgeMesh, fans: number[][], from: Vector3): Vector3 {
  const area = [0, 0, 0];
  const faceward = new Vector3();
  let total = 0;
  const centres = fans.map((faces) => {
    const centre = new Vector3();
    for (const f of faces) {
      const a = new Vector3(...faceVectorArea(mesh, f, area));
      faceward.add(a);
      total += a.length();
      centre.add(new Vector3(...faceCentroid(mesh, f)));
    }
    return centre.divideScalar(Math.max(1, faces.length));
  });
  // one group (any other repair's faces) has no such line: a zero normal leaves a vector as it is
  const line = centres.length > 1 ? centres[1].clone().sub(centres[0]).normalize() : new Vector3();
  const facing = faceward.projectOnPlane(line);
  if (facing.length() > 0.1 * total) return facing.normalize();
  const across = from.clone().projectOnPlane(line);
  return across.lengthSq() > 0 ? across.normalize() : from.clone();
}
