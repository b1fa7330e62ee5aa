/**
 * A repair of the builder told over the view: what the file had (three faces on one edge, one
 * vertex where separate fans of faces met) and what the repair made of it (a face detached with its
 * own copies of the edge's vertices; the vertex split, one copy per fan). What the file had is
 * marked in the problem colour, what the repair made in the colour of what is created, and each
 * gets at most one label, in words. Plain numbers are the file's (its vertices counted from 0, as
 * the repair report counts them); `v…` and `f…` are the ids of the mesh, as the tables show them.
 * Pure: it returns a description the highlight layer draws.
 */
import { faceVertices, halfedgeFromTo, type HalfedgeMesh, type RepairIncident, type RepairKind, vertexAdjacentFaces } from '../core/index.js';
import { colors, phaseColors } from './colors.js';
import { emptyHighlight, type HighlightSpec } from './scene/highlight.js';
import type { Selection } from './selection.js';

/** What the repair made (copies, and the faces that took them), in the colour of what a phase creates. */
const MADE = phaseColors.created;

export function repairStory(mesh: HalfedgeMesh, incident: RepairIncident, kind: RepairKind): HighlightSpec {
  const spec = emptyHighlight();
  // an element the mesh no longer has (after an edit) is left out
  const vertices = (incident.vertices ?? []).filter((v) => v < mesh.vertexSlots && !mesh.vDeleted[v]);
  const faces = (incident.faces ?? []).filter((f) => f < mesh.faceSlots && !mesh.fDeleted[f]);
  const mark = (color: string, ids: { vertices: number[]; faces: number[] }) => {
    for (const id of ids.vertices) spec.vertices.push({ id, color });
    for (const id of ids.faces) spec.faces.push({ id, color });
  };
  const say = (text: string, on: Selection, color: string) => spec.labels.push({ text, on, color, sentence: true });
  const [a, b] = incident.inputVertices ?? [];

  if ((kind === 'non-manifold-edge' || kind === 'non-orientable') && vertices[0] === a && vertices[1] === b) {
    // the vertices after the edge's two are the copies the detached faces took
    const copies = vertices.slice(2);
    const copiesOf = (f: number) => [...faceVertices(mesh, f)].filter((v) => copies.includes(v));
    const detached = faces.filter((f) => copiesOf(f).length > 0);
    const kept = faces.filter((f) => !detached.includes(f));
    mark(colors.problem, { vertices: [a, b], faces: kept });
    mark(MADE, { vertices: copies, faces: detached });
    const had = kind === 'non-manifold-edge' ? `had ${incident.faces?.length} faces` : 'had its 2 faces run the same way along it';
    const keep = kept.length === 0 ? '' : `: ${listed(kept.map((f) => `f${f}`))} ${kept.length === 1 ? 'keeps' : 'keep'} it`;
    const edge = halfedgeFromTo(mesh, a, b);
    say(`file edge ${a}–${b} ${had}${keep}`, edge === -1 ? { kind: 'vertex', id: a } : { kind: 'edge', id: edge >> 1 }, colors.problem);
    for (const f of detached) say(`f${f} detached, with its own copies ${listed(copiesOf(f).map((v) => `v${v}`))}`, { kind: 'face', id: f }, MADE);
  } else if (kind === 'non-manifold-vertex' && vertices[0] === a) {
    // the copies sit on one point: each fan is tinted, and each label anchored in its own fan
    const fan = (v: number) => ({ vertices: [v], faces: [...vertexAdjacentFaces(mesh, v)] });
    mark(colors.problem, fan(a));
    say(`file vertex ${a} joined ${vertices.length} fans: this one keeps v${a}`, inFan(mesh, a), colors.problem);
    for (const v of vertices.slice(1)) {
      mark(MADE, fan(v));
      say(`this fan got its own copy, v${v}`, inFan(mesh, v), MADE);
    }
  } else {
    mark(colors.problem, { vertices, faces });
    if (faces.length > 0) say(`f${faces[0]}: ${incident.message}`, { kind: 'face', id: faces[0] }, colors.problem);
    else if (vertices.length > 0) say(`v${vertices[0]}: ${incident.message}`, { kind: 'vertex', id: vertices[0] }, colors.problem);
  }
  return spec;
}

/** `v0 and v12`, `f2, f3 and f5`. */
function listed(names: string[]): string {
  return names.length < 2 ? names.join('') : `${names.slice(0, -1).join(', ')} and ${names.at(-1)}`;
}

/** Where the label of vertex v's fan goes: on a face of the fan (the copies share one point), else on v. */
function inFan(mesh: HalfedgeMesh, v: number): Selection {
  for (const f of vertexAdjacentFaces(mesh, v)) return { kind: 'face', id: f };
  return { kind: 'vertex', id: v };
}
