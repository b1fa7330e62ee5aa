/**
 * What the student is looking at, driven as the app drives it: selecting, walking and going back,
 * what is let go when the mesh changes, which highlight is shown, and where a big mesh's arrows
 * grow from.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, collapseEdge, disk, torus } from '../../src/index.js';
import { Inspection } from '../../src/ui/inspection.js';
import { emptyHighlight } from '../../src/ui/scene/highlight.js';

describe('Inspection', () => {
  it('walks from the selection, step by step, and back along the same path', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const view = new Inspection();
    expect(view.walk(mesh, 'next')).toMatch(/Select an element first/);
    expect(view.select(mesh, { kind: 'halfedge', id: 8 })).toBeNull();
    expect(view.walk(mesh, 'next')).toBeNull();
    expect(view.walk(mesh, 'twin')).toBeNull();
    expect(view.walk(mesh, 'origin')).toBeNull();
    const twinOfNext = mesh.twin(mesh.next(8));
    expect(view.selection).toEqual({ kind: 'vertex', id: mesh.origin(twinOfNext) });
    expect(view.path.map((step) => step.move)).toEqual([null, 'next', 'twin', 'origin']);
    // a vertex has no next: the walk stays where it is and says why
    expect(view.walk(mesh, 'next')).toMatch(/next is a pointer of halfedges; v\d+ is a vertex/);
    expect(view.path).toHaveLength(4);
    expect(view.back()).toBe(true);
    expect(view.selection).toEqual({ kind: 'halfedge', id: twinOfNext });
    expect(view.back()).toBe(true);
    expect(view.back()).toBe(true);
    expect(view.back()).toBe(false);
    expect(view.selection).toEqual({ kind: 'halfedge', id: 8 });
  });

  it('refuses to select what the mesh does not have, keeping the selection', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const view = new Inspection();
    view.select(mesh, { kind: 'face', id: 2 });
    expect(view.select(mesh, { kind: 'vertex', id: mesh.vertexSlots })).toBe(`v${mesh.vertexSlots} does not exist in this mesh.`);
    expect(view.selection).toEqual({ kind: 'face', id: 2 });
  });

  it('lets go, after an edit, of what it deleted, and keeps the rest of the walk', () => {
    const { mesh } = buildMesh(disk(3));
    const view = new Inspection();
    const v = [...mesh.vertices()].find((u) => !mesh.isBoundaryVertex(u))!;
    view.select(mesh, { kind: 'vertex', id: v });
    view.walk(mesh, 'halfedge');
    const e = mesh.edge(mesh.vertexHalfedge(v));
    view.hover(mesh, { kind: 'edge', id: e });
    view.marks.problem = view.marks.seams = view.marks.practice = emptyHighlight();
    collapseEdge(mesh, e);
    view.meshChanged(mesh, false);
    expect(view.selection, 'the selected halfedge went with its edge').toBeNull();
    expect(view.path.some((step) => step.to.kind === 'halfedge')).toBe(false);
    expect(view.hovered).toBeNull();
    expect(view.marks).toEqual({ quiz: null, traversal: null, problem: null, seams: null, practice: null });
    for (const step of view.path) expect(step.to.kind === 'vertex' ? !mesh.isVertexDeleted(step.to.id) : !mesh.isHalfedgeDeleted(step.to.id)).toBe(true);
    // a new model starts with nothing selected
    view.select(mesh, { kind: 'face', id: [...mesh.faces()][0]! });
    view.meshChanged(mesh, true);
    expect(view.selection).toBeNull();
    expect(view.path).toEqual([]);
  });

  it("draws a repair's story alone at the element it selected, and the selection again once the walk leaves it", () => {
    const { mesh } = buildMesh(torus(6, 5));
    const view = new Inspection();
    view.select(mesh, { kind: 'vertex', id: 4 });
    const story = { ...emptyHighlight(), labels: [{ text: 'file vertex 4 joined 2 fans: this one keeps v4', on: { kind: 'vertex' as const, id: 4 }, color: '#D55E00' }] };
    view.marks.problem = story;
    expect(view.highlight(mesh)).toEqual(story);
    view.walk(mesh, 'halfedge');
    expect(view.highlight(mesh).labels.map((label) => label.text)).toContain(story.labels[0]!.text);
    expect(view.highlight(mesh).halfedges.length).toBeGreaterThan(0);
    view.back();
    expect(view.highlight(mesh)).toEqual(story);
  });

  it("shows a quiz's path or a traversal alone, else the selection under the marks", () => {
    const { mesh } = buildMesh(torus(6, 5));
    const view = new Inspection();
    view.select(mesh, { kind: 'halfedge', id: 3 });
    const selected = view.highlight(mesh);
    expect(selected.halfedges.map((h) => h.id)).toContain(3);
    view.marks.seams = { ...emptyHighlight(), edges: [{ id: 9, color: '#ff0000' }] };
    expect(view.highlight(mesh).edges).toContainEqual({ id: 9, color: '#ff0000' });
    expect(view.highlight(mesh).halfedges.map((h) => h.id)).toContain(3);
    const traversal = { ...emptyHighlight(), halfedges: [{ id: 12, color: '#00ff00' }] };
    view.marks.traversal = traversal;
    expect(view.highlight(mesh)).toBe(traversal);
    const quiz = { ...emptyHighlight(), halfedges: [{ id: 14, color: '#0000ff' }] };
    view.marks.quiz = quiz;
    expect(view.highlight(mesh)).toBe(quiz);
  });

  it("grows a big mesh's arrows from the face the selection lies on", () => {
    const { mesh } = buildMesh(disk(2));
    const view = new Inspection();
    expect(view.focusFace(mesh)).toBe(-1);
    const boundary = [...mesh.halfedges()].find((h) => mesh.face(h) === -1)!;
    view.select(mesh, { kind: 'halfedge', id: boundary });
    expect(view.focusFace(mesh)).toBe(mesh.face(mesh.twin(boundary)));
    view.select(mesh, { kind: 'edge', id: mesh.edge(boundary) });
    expect(view.focusFace(mesh)).toBe(mesh.face(mesh.twin(boundary)));
    view.select(mesh, { kind: 'face', id: 4 });
    expect(view.focusFace(mesh)).toBe(4);
    for (const v of mesh.vertices()) {
      view.select(mesh, { kind: 'vertex', id: v });
      const f = view.focusFace(mesh);
      expect([...mesh.faces()]).toContain(f);
      // a face of the vertex's fan
      let touches = false;
      let h = mesh.faceHalfedge(f);
      do {
        touches ||= mesh.origin(h) === v;
        h = mesh.next(h);
      } while (h !== mesh.faceHalfedge(f));
      expect(touches).toBe(true);
    }
  });
});
