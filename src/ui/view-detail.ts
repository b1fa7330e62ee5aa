/**
 * How much of the mesh the view draws: every arrow on a mesh of modest size, and on a big one
 * those near the selection or the middle of the view; edge lines and arrows only once an edge is
 * a few pixels long on screen; the backs of the faces only where one can show. And the note that
 * says which arrows are drawn when not all of them are.
 */
import type { HalfedgeMesh, MeshStats } from '../core/index.js';
import type { Inspection } from './inspection.js';
import { type ArrowLayer, halfedgesNear, MAX_ARROWS } from './scene/arrows.js';
import type { SurfaceLayer } from './scene/surface.js';
import type { Viewer } from './scene/viewer.js';

/** Edge lines are drawn while a typical edge is at least this many pixels long on screen… */
const MIN_EDGE_PIXELS = 3;
/** …and the arrows while it is at least this many. */
const MIN_ARROW_EDGE_PIXELS = 5;

/** What the detail follows: the mesh shown, its counts, what is selected, and the size of things. */
export interface DetailContext {
  mesh: HalfedgeMesh | null;
  stats: MeshStats | null;
  inspection: Inspection;
  /** Larger arrows in presentation mode. */
  scale: number;
}

export class ViewDetail {
  /** True while the arrows are hidden for being too small at this zoom (see `fit`). */
  private arrowsHidden = false;
  /** True when a change came while the arrows were hidden: they are placed again once they show. */
  private stale = false;
  /** Calls of `refresh` so far: one that waited must not undo a later one. */
  private refreshes = 0;
  /** The face last found in the middle of the view (-1: none yet), which arrows grow from without a selection. */
  private viewFocus = -1;

  constructor(
    private readonly viewer: Viewer,
    private readonly surface: SurfaceLayer,
    private readonly arrows: ArrowLayer,
    private readonly note: HTMLElement,
    private readonly context: () => DetailContext,
    /** Called when the note comes up, which may cover part of the mesh. */
    private readonly noteShown: () => void,
  ) {}

  /**
   * Draws the arrows again: all of them, or on a big mesh those around the focus (with
   * `sameView`, the face in the middle of the view found last time, while it lives).
   */
  async refresh(sameView = false): Promise<void> {
    const { mesh, scale } = this.context();
    if (!mesh) return;
    const call = ++this.refreshes;
    // another view: the face found in the middle of the last one says nothing of it
    if (!sameView) this.viewFocus = -1;
    if (this.edgePixels() < MIN_ARROW_EDGE_PIXELS) {
      // too small to see at this zoom: placing up to MAX_ARROWS of them would be wasted, on every
      // edit and on a large mesh just opened and framed whole (where finding the face in the
      // middle of the view is a ray cast through every triangle); none are kept (picking must not
      // find an arrow of the mesh before), and `fit` places them once they show
      this.arrows.update(mesh, new Int32Array(0), scale);
      this.stale = true;
      return;
    }
    this.stale = false;
    if (mesh.nHalfedges <= MAX_ARROWS) {
      this.arrows.update(mesh, null, scale);
    } else {
      // finding the face in the middle of the view may wait for the picking worker's hierarchy
      const focus = await this.focusFace(mesh, sameView);
      if (call !== this.refreshes) return; // a later refresh (a selection, a new mesh) has run
      this.arrows.update(mesh, focus < 0 ? new Int32Array(0) : halfedgesNear(mesh, focus), scale);
    }
    this.showNote();
    this.viewer.requestRender();
  }

  /** On a big mesh, the arrows around the new selection or view. */
  refreshIfPartial(): void {
    const { mesh } = this.context();
    if (mesh && mesh.nHalfedges > MAX_ARROWS) void this.refresh();
  }

  /**
   * Before each frame: edge lines and arrows only a few pixels long blur into a dark mass that
   * hides the surface, so they wait until the view zooms in (the selection stays highlighted).
   * And the backs of the faces are not drawn where none can show (one closed surface facing out).
   */
  fit(): void {
    const { stats } = this.context();
    this.surface.cullBackFaces(stats?.closed === true && stats.components === 1 && (stats.volume ?? 0) > 0, this.viewer.camera.position);
    const pixels = this.edgePixels();
    this.surface.showEdges(pixels >= MIN_EDGE_PIXELS);
    const arrowsHidden = pixels < MIN_ARROW_EDGE_PIXELS;
    this.arrows.group.visible = !arrowsHidden;
    if (arrowsHidden !== this.arrowsHidden) {
      this.arrowsHidden = arrowsHidden;
      this.showNote();
    }
    if (!arrowsHidden && this.stale) void this.refresh(true);
  }

  /** How long a typical edge is on screen, in pixels, from the camera as it is now. */
  private edgePixels(): number {
    // no edges (a point set), or only edges of no length: nothing that could crowd the view
    return this.surface.edgeLength > 0 ? this.surface.edgeLength * this.viewer.pixelsPerUnit() : Infinity;
  }

  /** Says which arrows are drawn when not all of them are. */
  private showNote(): void {
    const { mesh, inspection } = this.context();
    const wasHidden = this.note.hidden;
    this.note.hidden = !mesh || (!this.arrowsHidden && mesh.nHalfedges <= MAX_ARROWS);
    if (!mesh || this.note.hidden) return;
    this.note.textContent = this.arrowsHidden
      ? `Zoom in to see the halfedge arrows: at this zoom an edge is under ${MIN_ARROW_EDGE_PIXELS} pixels long.`
      : `Large mesh: arrows drawn for ${this.arrows.shown.length.toLocaleString('en')} of ${mesh.nHalfedges.toLocaleString('en')} halfedges, around the ${inspection.selection ? 'selection' : 'centre of the view'}.`;
    if (wasHidden) this.noteShown();
  }

  /** The face to grow the drawn arrows from: the selection's, or the one where the view is centred (the point it orbits). */
  private async focusFace(mesh: HalfedgeMesh, sameView: boolean): Promise<number> {
    const selected = this.context().inspection.focusFace(mesh);
    if (selected >= 0) return selected;
    const last = this.viewFocus;
    if (sameView && last >= 0 && last < mesh.faceSlots && !mesh.isFaceDeleted(last)) return last;
    const { x, y } = this.viewer.targetPoint();
    const hit = await this.surface.raycast(this.viewer.ray(x, y));
    this.viewFocus = hit ? hit.face : -1;
    if (hit) return hit.face;
    for (const f of mesh.faces()) return f;
    return -1;
  }
}
