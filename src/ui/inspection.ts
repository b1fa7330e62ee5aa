/**
 * What the student is looking at, apart from the camera: the selection and the walk that led to
 * it, the element under the pointer, the naming of a halfedge's vertex, and the marks laid over
 * the mesh (a quiz's path, a repair, the seams, a practice run's writes, a traversal). Pure, like
 * `selection.ts`: it reads a `HalfedgeMesh` and answers with data, and the app draws what it says.
 */
import type { HalfedgeMesh } from '../core/index.js';
import { combineHighlights, selectionHighlight } from './highlights.js';
import type { Convention } from './records.js';
import { emptyHighlight, type HighlightSpec } from './scene/highlight.js';
import { elementName, exists, type Move, type Selection, walk, type WalkStep } from './selection.js';

/** Highlights laid over the selection's, each set and cleared by the part of the app that owns it. */
export interface Marks {
  /** A quiz question's path (shown instead of the selection). */
  quiz: HighlightSpec | null;
  /** A traversal being played (shown instead of the selection). */
  traversal: HighlightSpec | null;
  /** A repair from the build report being shown. */
  problem: HighlightSpec | null;
  /** The seams of a file with per-corner values. */
  seams: HighlightSpec | null;
  /** The last writes, or the reads so far, of the practice run shown. */
  practice: HighlightSpec | null;
}

export class Inspection {
  selection: Selection | null = null;
  /** The walk to the selection: its first step has no move. */
  path: WalkStep[] = [];
  hovered: Selection | null = null;
  convention: Convention = 'origin';
  readonly marks: Marks = { quiz: null, traversal: null, problem: null, seams: null, practice: null };

  /** Selects an element (null: nothing), starting a new walk; or says why it cannot. */
  select(mesh: HalfedgeMesh | null, selection: Selection | null): string | null {
    if (selection && mesh && !exists(mesh, selection)) return `${elementName(selection)} does not exist in this mesh.`;
    this.selection = selection;
    this.path = selection ? [{ move: null, to: selection }] : [];
    this.marks.problem = null;
    return null;
  }

  /** Follows a pointer from the selection, extending the walk; or says why it leads nowhere. */
  walk(mesh: HalfedgeMesh | null, move: Move): string | null {
    if (!mesh || !this.selection) return 'Select an element first: click an arrow, a vertex or a face.';
    const to = walk(mesh, this.selection, move);
    if (typeof to === 'string') return to;
    this.selection = to;
    this.path.push({ move, to });
    return null;
  }

  /** One step back along the walk; false at its start. */
  back(): boolean {
    if (this.path.length <= 1) return false;
    this.path.pop();
    this.selection = this.path[this.path.length - 1].to;
    return true;
  }

  /** The element under the pointer, if it exists. */
  hover(mesh: HalfedgeMesh | null, selection: Selection | null): Selection | null {
    this.hovered = mesh && selection && exists(mesh, selection) ? selection : null;
    return this.hovered;
  }

  /**
   * After the mesh changed: what no longer exists is let go, and the marks whose ids named elements
   * of the mesh before are dropped (a quiz and a traversal are ended by their panels). A new model
   * starts with nothing selected.
   */
  meshChanged(mesh: HalfedgeMesh, newModel: boolean): void {
    if (newModel || (this.selection && !exists(mesh, this.selection))) this.selection = null;
    if (this.hovered && !exists(mesh, this.hovered)) this.hovered = null;
    this.path = newModel ? [] : this.path.filter((step) => exists(mesh, step.to));
    this.marks.problem = this.marks.practice = this.marks.seams = null;
  }

  /**
   * What to highlight: a quiz's path or a traversal alone, else the selection under the other marks.
   * A repair's story (see repair-story.ts) is the whole picture at the element it selected: that
   * element's own marks (its id, its halfedge, its fan in the legend's colours) would tell a second
   * story over it. They come back as the walk leaves it.
   */
  highlight(mesh: HalfedgeMesh): HighlightSpec {
    const { quiz, traversal, problem, seams, practice } = this.marks;
    if (quiz ?? traversal) return (quiz ?? traversal)!;
    const told = problem !== null && this.path.length === 1;
    const selected = this.selection && !told ? selectionHighlight(mesh, this.selection, this.convention) : emptyHighlight();
    return [seams, problem, practice].filter((spec) => spec !== null).reduce(combineHighlights, selected);
  }

  /**
   * The face the selection lies on (a halfedge's, else its twin's; an edge's; one of a vertex's),
   * which a big mesh's arrows grow from; -1 with no selection or none at hand (an isolated vertex).
   */
  focusFace(mesh: HalfedgeMesh): number {
    const s = this.selection;
    if (!s || !exists(mesh, s)) return -1;
    const faceBeside = (h: number) => (mesh.face(h) >= 0 ? mesh.face(h) : mesh.face(mesh.twin(h)));
    switch (s.kind) {
      case 'face':
        return s.id;
      case 'halfedge':
        return faceBeside(s.id);
      case 'edge':
        return faceBeside(mesh.edgeHalfedge(s.id));
      case 'vertex': {
        const h = mesh.vertexHalfedge(s.id);
        // a boundary vertex's halfedge may lie on the boundary: the face is then before it
        return h < 0 ? -1 : mesh.face(h) >= 0 ? mesh.face(h) : mesh.face(mesh.twin(mesh.prev(h)));
      }
    }
  }
}
