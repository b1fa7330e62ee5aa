/**
 * What to light up for a selection, in the legend's colours: for a halfedge its `next`, `prev`,
 * `twin`, `face` and `origin` together; for a vertex its outgoing halfedge and one-ring; for a face
 * its loop of halfedges. Pure: it returns a description the highlight layer draws.
 */
import type { HalfedgeMesh } from '../core/index.js';
import type { ShownPhase } from '../workers/protocol.js';
import { colors, hollowRoles, phaseColors } from './colors.js';
import type { Convention } from './records.js';
import { elementName, type Selection } from './selection.js';
import { emptyHighlight, type HighlightSpec } from './scene/highlight.js';

export function selectionHighlight(mesh: HalfedgeMesh, s: Selection, convention: Convention): HighlightSpec {
  const spec = emptyHighlight();
  const label = (text: string, on: Selection, color: string) => spec.labels.push({ text, on, color });
  const halfedge = (id: number, color: string, text?: string, hollow = false) => {
    spec.halfedges.push({ id, color, hollow });
    if (text) label(text, { kind: 'halfedge', id }, color);
  };
  switch (s.kind) {
    case 'halfedge': {
      const h = s.id;
      const next = mesh.next(h);
      const prev = mesh.prev(h);
      const face = mesh.face(h);
      if (face !== -1) {
        spec.faces.push({ id: face, color: colors.face });
        label(`f${face}`, { kind: 'face', id: face }, colors.face);
      }
      halfedge(next, colors.next, `next h${next}`);
      if (prev !== next) halfedge(prev, colors.prev, `prev h${prev}`, hollowRoles.has('prev'));
      halfedge(mesh.twin(h), colors.twin, `twin h${mesh.twin(h)}`, hollowRoles.has('twin'));
      halfedge(h, colors.selected, `h${h}`);
      const vertex = convention === 'origin' ? mesh.origin(h) : mesh.origin(next);
      spec.vertices.push({ id: vertex, color: colors.origin });
      label(`${convention} v${vertex}`, { kind: 'vertex', id: vertex }, colors.origin);
      break;
    }
    case 'vertex': {
      const v = s.id;
      spec.vertices.push({ id: v, color: colors.origin });
      label(`v${v}`, s, colors.origin);
      const start = mesh.vertexHalfedge(v);
      if (start < 0) break;
      let h = start;
      do {
        if (mesh.face(h) !== -1) spec.faces.push({ id: mesh.face(h), color: colors.face });
        spec.vertices.push({ id: mesh.origin(mesh.twin(h)), color: colors.next });
        spec.edges.push({ id: h >> 1, color: colors.next });
        h = mesh.twin(mesh.prev(h));
      } while (h !== start && spec.vertices.length < 4096);
      halfedge(start, colors.selected, `halfedge h${start}`);
      break;
    }
    case 'face': {
      const f = s.id;
      spec.faces.push({ id: f, color: colors.face });
      label(`f${f}`, s, colors.face);
      const start = mesh.faceHalfedge(f);
      let h = start;
      do {
        if (h !== start) halfedge(h, colors.next);
        h = mesh.next(h);
      } while (h !== start && spec.halfedges.length < 4096);
      halfedge(start, colors.selected, `halfedge h${start}`);
      break;
    }
    case 'edge': {
      const e = s.id;
      spec.edges.push({ id: e, color: colors.selected });
      const h = mesh.edgeHalfedge(e);
      halfedge(h, colors.selected, `h${h}`);
      halfedge(mesh.twin(h), colors.twin, `h${mesh.twin(h)}`);
      label(`e${e}`, s, colors.selected);
      break;
    }
  }
  return spec;
}

/** The lighter preview of what a click would select. */
export function hoverHighlight(s: Selection): HighlightSpec {
  const spec = emptyHighlight();
  const color = colors.selected;
  if (s.kind === 'halfedge') spec.halfedges.push({ id: s.id, color });
  if (s.kind === 'vertex') spec.vertices.push({ id: s.id, color });
  if (s.kind === 'face') spec.faces.push({ id: s.id, color });
  if (s.kind === 'edge') spec.edges.push({ id: s.id, color });
  return spec;
}

/** What a phase created, moved and rewired, in the stepper's colours (ids no longer there are skipped). */
export function phaseHighlight(mesh: HalfedgeMesh, phase: ShownPhase): HighlightSpec {
  const spec = emptyHighlight();
  // the live ones (the phase lists at most PHASE_MARKS of each)
  const take = (ids: Int32Array | undefined, alive: (id: number) => boolean) => (ids ? [...ids].filter(alive) : []);
  const vertexAlive = (v: number) => v < mesh.vertexSlots && !mesh.vDeleted[v];
  const halfedgeAlive = (h: number) => h < mesh.halfedgeSlots && !mesh.eDeleted[h >> 1];
  const faceAlive = (f: number) => f < mesh.faceSlots && !mesh.fDeleted[f];
  for (const f of take(phase.created?.faces, faceAlive)) spec.faces.push({ id: f, color: phaseColors.created });
  for (const h of take(phase.rewired?.halfedges, halfedgeAlive)) spec.halfedges.push({ id: h, color: phaseColors.rewired });
  for (const h of take(phase.created?.halfedges, halfedgeAlive)) spec.halfedges.push({ id: h, color: phaseColors.created });
  for (const e of take(phase.created?.edges, (e) => halfedgeAlive(mesh.edgeHalfedge(e)))) spec.edges.push({ id: e, color: phaseColors.created });
  // a mark on (nearly) every vertex says nothing, and hides the colours a phase puts on them (a
  // smoothing step moves every vertex and colours each by how far it went)
  const movedMostly = phase.values?.vertices !== undefined && 2 * phase.movedCount >= mesh.nVertices;
  for (const v of take(movedMostly ? undefined : phase.moved?.vertices, vertexAlive)) spec.vertices.push({ id: v, color: phaseColors.moved });
  for (const v of take(phase.created?.vertices, vertexAlive)) spec.vertices.push({ id: v, color: phaseColors.created });
  return spec;
}

/** What the colours of a phase's marks mean, in the stepper's order: those `spec` uses. */
export function phaseMeanings(spec: HighlightSpec): PhaseMeaning[] {
  const used = new Set([...spec.faces, ...spec.halfedges, ...spec.edges, ...spec.vertices].map((mark) => mark.color));
  return (Object.keys(phaseColors) as PhaseMeaning[]).filter((name) => used.has(phaseColors[name]));
}

export type PhaseMeaning = keyof typeof phaseColors;

/** A quiz path: the start, each step, and the answer (right in green, a wrong pick in vermillion). */
export function quizHighlight(path: Selection[], picked: Selection | null, right: boolean): HighlightSpec {
  const spec = emptyHighlight();
  path.forEach((s, i) => {
    const last = i === path.length - 1;
    const color = i === 0 ? colors.selected : last && picked ? colors.face : colors.next;
    if (s.kind === 'halfedge') spec.halfedges.push({ id: s.id, color });
    if (s.kind === 'vertex') spec.vertices.push({ id: s.id, color });
    if (s.kind === 'face') spec.faces.push({ id: s.id, color });
    spec.labels.push({ text: i === 0 ? `start ${elementName(s)}` : elementName(s), on: s, color });
  });
  if (picked && !right) {
    const color = colors.twin;
    if (picked.kind === 'halfedge') spec.halfedges.push({ id: picked.id, color });
    if (picked.kind === 'vertex') spec.vertices.push({ id: picked.id, color });
    if (picked.kind === 'face') spec.faces.push({ id: picked.id, color });
    spec.labels.push({ text: `your pick ${elementName(picked)}`, on: picked, color });
  }
  return spec;
}

/** Two highlights drawn as one. */
export function combineHighlights(a: HighlightSpec, b: HighlightSpec): HighlightSpec {
  return {
    halfedges: [...a.halfedges, ...b.halfedges],
    faces: [...a.faces, ...b.faces],
    vertices: [...a.vertices, ...b.vertices],
    edges: [...a.edges, ...b.edges],
    labels: [...a.labels, ...b.labels],
  };
}

/** Every vertex and face labelled with its id. */
export function idLabels(mesh: HalfedgeMesh): HighlightSpec {
  const spec = emptyHighlight();
  for (const v of mesh.vertices()) spec.labels.push({ text: `v${v}`, on: { kind: 'vertex', id: v }, color: colors.origin });
  for (const f of mesh.faces()) spec.labels.push({ text: `f${f}`, on: { kind: 'face', id: f }, color: colors.face });
  return spec;
}
