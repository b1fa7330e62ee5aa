/**
 * The record of an element, as a debugger would print it: `h17 { next: h18, prev: h19, twin: h16,
 * origin: v4, face: f5, edge: e8 }`. Values that are elements become links in the inspector.
 */
import type { HalfedgeMesh } from '../core/index.js';
import { type ElementKind, type Selection } from './selection.js';

/** `origin` (de Berg et al., Scotty3D, geometry-central) or `target` (pmp, OpenMesh, CGAL). */
export type Convention = 'origin' | 'target';

export const conventionNote: Record<Convention, string> = {
  origin:
    'Each halfedge stores the vertex it starts from: de Berg et al., Scotty3D and geometry-central do this. target(h) = origin(next(h)).',
  target:
    'Each halfedge names the vertex it points to: pmp, OpenMesh and CGAL do this. origin(h) = target(prev(h)).',
};

export type FieldValue = { element: Selection } | { text: string };

export interface RecordField {
  field: string;
  value: FieldValue;
}

const element = (kind: ElementKind, id: number): FieldValue =>
  id < 0 ? { text: 'none (-1)' } : { element: { kind, id } };
const text = (value: string | number): FieldValue => ({ text: String(value) });

export function recordOf(mesh: HalfedgeMesh, s: Selection, convention: Convention = 'origin'): RecordField[] {
  const id = s.id;
  switch (s.kind) {
    case 'halfedge': {
      const vertexField: RecordField =
        convention === 'origin'
          ? { field: 'origin', value: element('vertex', mesh.origin(id)) }
          : { field: 'target', value: element('vertex', mesh.target(id)) };
      return [
        { field: 'next', value: element('halfedge', mesh.next(id)) },
        { field: 'prev', value: element('halfedge', mesh.prev(id)) },
        { field: 'twin', value: element('halfedge', mesh.twin(id)) },
        vertexField,
        { field: 'face', value: mesh.face(id) < 0 ? text('none (-1): boundary') : element('face', mesh.face(id)) },
        { field: 'edge', value: element('edge', id >> 1) },
      ];
    }
    case 'vertex': {
      const p = mesh.position(id).map((x) => round(x));
      return [
        { field: 'position', value: text(`(${p.join(', ')})`) },
        { field: 'halfedge', value: element('halfedge', mesh.vertexHalfedge(id)) },
        { field: 'degree', value: text(mesh.vertexDegree(id)) },
        { field: 'boundary', value: text(mesh.isBoundaryVertex(id) ? 'yes' : 'no') },
      ];
    }
    case 'face':
      return [
        { field: 'halfedge', value: element('halfedge', mesh.faceHalfedge(id)) },
        { field: 'degree', value: text(mesh.faceDegree(id)) },
      ];
    case 'edge':
      return [
        { field: 'halfedges', value: element('halfedge', mesh.edgeHalfedge(id)) },
        { field: '', value: element('halfedge', mesh.twin(mesh.edgeHalfedge(id))) },
        { field: 'vertices', value: element('vertex', mesh.origin(mesh.edgeHalfedge(id))) },
        { field: '', value: element('vertex', mesh.origin(mesh.twin(mesh.edgeHalfedge(id)))) },
        { field: 'boundary', value: text(mesh.isBoundaryEdge(id) ? 'yes' : 'no') },
      ];
  }
}

/** A number short enough to read on a projector. */
export function round(x: number): number {
  return Math.round(x * 1e4) / 1e4;
}
