/**
 * Turning a click into the element the student meant. The ray finds the face under the pointer;
 * then distances *on screen* decide: close to a vertex or an arrow picks the nearer of the two,
 * otherwise the face. A filter restricts picking to one kind. Clicks just outside
 * the surface can still pick the dashed arrows of boundary halfedges.
 */
import type { HalfedgeMesh } from '../../core/index.js';
import type { Selection } from '../selection.js';
import { newPlacement, placeArrow } from './arrow-placement.js';
import type { SurfaceLayer } from './surface.js';
import type { Viewer } from './viewer.js';

export type PickFilter = 'auto' | 'halfedge' | 'vertex' | 'edge' | 'face';

export interface PickContext {
  viewer: Viewer;
  surface: SurfaceLayer;
  mesh: HalfedgeMesh;
  /** Halfedges whose arrows are drawn. */
  shown: Int32Array;
  /** 1, or more in presentation mode (bigger targets). */
  scale: number;
}

/** How near (CSS pixels) the pointer must be to a vertex or an arrow in `auto` mode. */
const VERTEX_RADIUS = 12;
const ARROW_RADIUS = 14;

export async function pick(context: PickContext, x: number, y: number, filter: PickFilter): Promise<Selection | null> {
  const { viewer, surface, mesh, scale } = context;
  const hit = await surface.raycast(viewer.ray(x, y));
  const placement = newPlacement();
  const screenDistanceToArrow = (h: number) => {
    placeArrow(mesh, h, placement, scale);
    const a = viewer.project(placement.start);
    const b = viewer.project(placement.end);
    return segmentDistance(x, y, a, b);
  };
  const screenDistanceToVertex = (v: number) => {
    const p = viewer.project(mesh.position(v) as [number, number, number]);
    return Math.hypot(p.x - x, p.y - y);
  };

  // candidates: the halfedges of the face under the pointer and across its edges, or else the
  // boundary halfedges drawn on screen
  const halfedges: number[] = [];
  if (hit) {
    const start = mesh.faceHalfedge(hit.face);
    let h = start;
    do {
      halfedges.push(h, mesh.twin(h));
      h = mesh.next(h);
    } while (h !== start);
  } else {
    for (const h of context.shown) if (mesh.face(h) === -1) halfedges.push(h);
  }
  const nearestHalfedge = nearest(halfedges, screenDistanceToArrow);
  const vertices = [...new Set(halfedges.map((h) => mesh.origin(h)))];
  const nearestVertex = nearest(vertices, screenDistanceToVertex);

  switch (filter) {
    case 'face':
      return hit ? { kind: 'face', id: hit.face } : null;
    case 'vertex':
      return nearestVertex && (hit || nearestVertex.distance < 3 * VERTEX_RADIUS * scale) ? { kind: 'vertex', id: nearestVertex.id } : null;
    case 'halfedge':
      return nearestHalfedge && (hit || nearestHalfedge.distance < 3 * ARROW_RADIUS * scale) ? { kind: 'halfedge', id: nearestHalfedge.id } : null;
    case 'edge': {
      const edge = nearest(
        halfedges.filter((h) => (h & 1) === 0),
        (h) => segmentDistance(x, y, viewer.project(mesh.position(mesh.origin(h)) as [number, number, number]), viewer.project(mesh.position(mesh.origin(mesh.twin(h))) as [number, number, number])),
      );
      return edge && (hit || edge.distance < 3 * ARROW_RADIUS * scale) ? { kind: 'edge', id: edge.id >> 1 } : null;
    }
    case 'auto': {
      // the nearer of the two wins: where faces are seen at a glancing angle (a torus's inner
      // wall) their arrows lie within a vertex's radius, and a click on an arrow means the arrow
      const vertex = nearestVertex && nearestVertex.distance <= VERTEX_RADIUS * scale ? nearestVertex : null;
      const arrow = nearestHalfedge && nearestHalfedge.distance <= ARROW_RADIUS * scale ? nearestHalfedge : null;
      if (vertex && (!arrow || vertex.distance <= arrow.distance)) return { kind: 'vertex', id: vertex.id };
      if (arrow) return { kind: 'halfedge', id: arrow.id };
      return hit ? { kind: 'face', id: hit.face } : null;
    }
  }
}

function nearest(ids: number[], distance: (id: number) => number): { id: number; distance: number } | null {
  let best: { id: number; distance: number } | null = null;
  for (const id of ids) {
    const d = distance(id);
    if (!best || d < best.distance) best = { id, distance: d };
  }
  return best;
}

/** Distance from (x, y) to the segment a–b on screen. */
function segmentDistance(x: number, y: number, a: { x: number; y: number }, b: { x: number; y: number }): number {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const lengthSq = dx * dx + dy * dy;
  const t = lengthSq === 0 ? 0 : Math.max(0, Math.min(1, ((x - a.x) * dx + (y - a.y) * dy) / lengthSq));
  return Math.hypot(x - (a.x + t * dx), y - (a.y + t * dy));
}
