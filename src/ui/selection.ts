/**
 * What the student has selected, and the walks from it: `next`, `prev`, `twin`, its face, its
 * origin, and the compound moves of every lecture (`twin.next` and `prev.twin` rotate around the
 * origin vertex). Pure: it reads a `HalfedgeMesh` and never draws, so the tests drive it directly.
 */
import type { HalfedgeMesh } from '../core/index.js';

export type ElementKind = 'vertex' | 'edge' | 'face' | 'halfedge';

export interface Selection {
  kind: ElementKind;
  id: number;
}

const prefixes: Record<ElementKind, string> = { vertex: 'v', edge: 'e', face: 'f', halfedge: 'h' };

/** `h17`, `v4`, `f5`, `e8`. */
export function elementName(selection: Selection): string {
  return `${prefixes[selection.kind]}${selection.id}`;
}

/** Parses `h17` / `v4` / `f5` / `e8` (what the tables and the inspector links carry). */
export function parseElementName(name: string): Selection | null {
  const match = /^([hvfe])(\d+)$/.exec(name.trim());
  if (!match) return null;
  const kind = (Object.keys(prefixes) as ElementKind[]).find((k) => prefixes[k] === match[1])!;
  return { kind, id: Number(match[2]) };
}

export type Move = 'next' | 'prev' | 'twin' | 'face' | 'origin' | 'target' | 'edge' | 'halfedge' | 'twin.next' | 'prev.twin';

export const moveKeys: Record<string, Move> = {
  n: 'next',
  p: 'prev',
  t: 'twin',
  f: 'face',
  e: 'edge',
  h: 'halfedge',
  r: 'twin.next',
  l: 'prev.twin',
};

/** True when the element exists in the mesh (in range and not deleted). */
export function exists(mesh: HalfedgeMesh, s: Selection): boolean {
  if (!Number.isInteger(s.id) || s.id < 0) return false;
  switch (s.kind) {
    case 'vertex':
      return s.id < mesh.vertexSlots && !mesh.vDeleted[s.id];
    case 'edge':
      return s.id < mesh.edgeSlots && !mesh.eDeleted[s.id];
    case 'face':
      return s.id < mesh.faceSlots && !mesh.fDeleted[s.id];
    case 'halfedge':
      return s.id < mesh.halfedgeSlots && !mesh.eDeleted[s.id >> 1];
  }
}

/**
 * Where `move` leads from `from`, or a sentence saying why it leads nowhere (a boundary halfedge
 * has no face; a vertex has no `next`).
 */
export function walk(mesh: HalfedgeMesh, from: Selection, move: Move): Selection | string {
  const name = elementName(from);
  if (move === 'halfedge') {
    switch (from.kind) {
      case 'vertex': {
        const h = mesh.vertexHalfedge(from.id);
        return h < 0 ? `${name} is isolated: it has no halfedge` : { kind: 'halfedge', id: h };
      }
      case 'face':
        return { kind: 'halfedge', id: mesh.faceHalfedge(from.id) };
      case 'edge':
        return { kind: 'halfedge', id: mesh.edgeHalfedge(from.id) };
      case 'halfedge':
        return from;
    }
  }
  if (from.kind !== 'halfedge') {
    return `${move} is a pointer of halfedges; ${name} is a ${from.kind} (press H to take its halfedge)`;
  }
  const h = from.id;
  switch (move) {
    case 'next':
      return { kind: 'halfedge', id: mesh.next(h) };
    case 'prev':
      return { kind: 'halfedge', id: mesh.prev(h) };
    case 'twin':
      return { kind: 'halfedge', id: mesh.twin(h) };
    case 'face': {
      const f = mesh.face(h);
      return f < 0 ? `${name} is a boundary halfedge: it runs along a boundary loop and has no face` : { kind: 'face', id: f };
    }
    case 'origin':
      return { kind: 'vertex', id: mesh.origin(h) };
    case 'target':
      return { kind: 'vertex', id: mesh.target(h) };
    case 'edge':
      return { kind: 'edge', id: h >> 1 };
    case 'twin.next':
      return { kind: 'halfedge', id: mesh.next(mesh.twin(h)) };
    case 'prev.twin':
      return { kind: 'halfedge', id: mesh.twin(mesh.prev(h)) };
  }
}

/** One step of a walk, for the breadcrumb `h17 → next → h18 → twin → h40`. */
export interface WalkStep {
  move: Move | null;
  to: Selection;
}

/** Steps the breadcrumb shows; a longer walk shows its start, how many steps it leaves out, and its last ones. */
export const MAX_BREADCRUMB_STEPS = 8;

/** `h17 → next → h18 → twin → h40`, at most `maxSteps` of it (a single step is never left out: it says itself as briefly). */
export function breadcrumbText(path: WalkStep[], maxSteps = MAX_BREADCRUMB_STEPS): string {
  const text = (step: WalkStep) => (step.move ? `${step.move} → ${elementName(step.to)}` : elementName(step.to));
  if (path.length <= maxSteps + 1) return path.map(text).join(' → ');
  const tail = path.slice(-(maxSteps - 1));
  return [text(path[0]), `… ${path.length - 1 - tail.length} steps …`, ...tail.map(text)].join(' → ');
}

/** True when a record's field names a pointer the walk can follow (`next`, `origin`, `halfedge`, …). */
export function isMove(field: string): field is Move {
  return (['next', 'prev', 'twin', 'face', 'origin', 'target', 'edge', 'halfedge', 'twin.next', 'prev.twin'] as string[]).includes(field);
}
