/**
 * What the view marks for a state of a practice run: the pointer a write stored (the element
 * written in orange, labelled `next(h4) = h9`, and the element it now points to in the pointer's
 * colour), and, for a query, the halfedges the code has read so far. Pure, like `highlights.ts`.
 *
 * A state half-way through a rewiring cannot be drawn (see `whyNotDrawable`); the view then shows
 * the last state that can, and these marks show every write made since, on it.
 */
import type { HalfedgeMesh } from '../core/index.js';
import { describeWrite, type PracticeWrite } from '../core/practice/writes.js';
import { colors, hollowRoles } from './colors.js';
import { emptyHighlight, type HighlightSpec } from './scene/highlight.js';
import { elementName, exists, type Selection } from './selection.js';

/** Writes given a label: more would cover the mesh (the rest are still drawn, unlabelled). */
const LABELLED_WRITES = 4;

/** The colour of the element a write points to, by the pointer written. */
const targetColour: Record<string, string> = {
  next: colors.next,
  prev: colors.prev,
  origin: colors.origin,
  face: colors.face,
  vertexHalfedge: colors.next,
  faceHalfedge: colors.next,
};

/** `writes` (the last ones before the state shown, in order) marked on `mesh`; elements `mesh` lacks are skipped. */
export function writeMarks(mesh: HalfedgeMesh, writes: readonly PracticeWrite[]): HighlightSpec {
  const spec = emptyHighlight();
  const alive = (selection: Selection) => exists(mesh, selection);
  const mark = (s: Selection, color: string, label: string | null, hollow = false) => {
    if (!alive(s)) return;
    if (s.kind === 'halfedge') spec.halfedges.push({ id: s.id, color, hollow });
    if (s.kind === 'vertex') spec.vertices.push({ id: s.id, color });
    if (s.kind === 'face') spec.faces.push({ id: s.id, color });
    if (s.kind === 'edge') spec.edges.push({ id: s.id, color });
    if (label) spec.labels.push({ text: label, on: s, color });
  };
  writes.forEach((write, i) => {
    const labelled = i >= writes.length - LABELLED_WRITES;
    const written = writtenElement(write);
    mark(written, colors.selected, labelled ? describeWrite(write) : null);
    const target = pointedTo(write);
    if (target) mark(target, targetColour[write.field], labelled ? elementName(target) : null, write.field === 'prev' && hollowRoles.has('prev'));
  });
  return spec;
}

/** The halfedges a query read up to read `step` (a zero-based index into `visits`): the current one labelled. */
export function readMarks(mesh: HalfedgeMesh, visits: readonly number[], step: number): HighlightSpec {
  const spec = emptyHighlight();
  const alive = (selection: Selection) => exists(mesh, selection);
  const seen = new Set<number>();
  for (let i = 0; i < step; i++) {
    const h = visits[i];
    if (seen.has(h) || !alive({ kind: 'halfedge', id: h })) continue;
    seen.add(h);
    spec.halfedges.push({ id: h, color: colors.next });
  }
  const current = visits[step];
  if (current !== undefined && alive({ kind: 'halfedge', id: current })) {
    spec.halfedges.push({ id: current, color: colors.selected });
    spec.labels.push({ text: `read ${step + 1}: h${current}`, on: { kind: 'halfedge', id: current }, color: colors.selected });
  }
  return spec;
}

/** The element whose field a write stored. */
function writtenElement(write: PracticeWrite): Selection {
  switch (write.field) {
    case 'vertexHalfedge':
    case 'position':
    case 'newVertex':
    case 'deleteVertex':
      return { kind: 'vertex', id: write.index };
    case 'faceHalfedge':
    case 'newFace':
    case 'deleteFace':
      return { kind: 'face', id: write.index };
    case 'newEdge':
    case 'deleteEdge':
      return { kind: 'edge', id: write.index };
    default:
      return { kind: 'halfedge', id: write.index };
  }
}

/** The element a pointer write made the field point to (null for other writes, and for -1). */
function pointedTo(write: PracticeWrite): Selection | null {
  switch (write.field) {
    case 'next':
    case 'prev':
    case 'vertexHalfedge':
    case 'faceHalfedge':
      return write.new === -1 ? null : { kind: 'halfedge', id: write.new };
    case 'origin':
      return { kind: 'vertex', id: write.new };
    case 'face':
      return write.new === -1 ? null : { kind: 'face', id: write.new };
    default:
      return null;
  }
}
