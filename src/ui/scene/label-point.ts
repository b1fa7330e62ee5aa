/**
 * Where the label of an element goes: a vertex's position, a face's centre, an edge's middle, the
 * middle of a halfedge's arrow. A highlight names the elements its labels are on, and the layer
 * that draws it finds the points here, on the mesh it draws: so a label stays on its element
 * wherever the view draws that element (in the exploded view, moved with its part).
 */
import { faceCentroid, type HalfedgeMesh } from '../../core/index.js';
import type { Selection } from '../selection.js';

type Point = [number, number, number];

export function labelPoint(mesh: HalfedgeMesh, s: Selection): Point {
  if (s.kind === 'halfedge') return arrowMiddle(mesh, s.id);
  if (s.kind === 'vertex') return mesh.position(s.id) as Point;
  if (s.kind === 'face') return faceCentroid(mesh, s.id) as Point;
  const a = mesh.position(mesh.origin(mesh.edgeHalfedge(s.id)));
  const b = mesh.position(mesh.origin(mesh.twin(mesh.edgeHalfedge(s.id))));
  return [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2];
}

/** The middle of halfedge h's edge, moved a quarter of the way towards its face's centre, so the labels of twins do not overlap. */
function arrowMiddle(mesh: HalfedgeMesh, h: number): Point {
  const a = mesh.position(mesh.origin(h));
  const b = mesh.position(mesh.target(h));
  const side = mesh.face(h) !== -1 ? faceCentroid(mesh, mesh.face(h)) : null;
  const mid: Point = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2];
  if (!side) return mid;
  return [mid[0] + 0.25 * (side[0] - mid[0]), mid[1] + 0.25 * (side[1] - mid[1]), mid[2] + 0.25 * (side[2] - mid[2])];
}
