/**
 * What to light up for a selection, in the legend's colours: for a halfedge its `next`, `prev`,
 * `twin`, `face` and `origin` together; for a vertex its outgoing halfedge and one-ring; for a face
 * its loop of halfedges. Pure: it returns a description the highlight layer draws.
 */
import { faceCentroid, type HalfedgeMesh } from '../core/index.js';
import { colors } from './colors.js';
import type { Convention } from './records.js';
import { type Selection } from './selection.js';
import { emptyHighlight, type HighlightSpec } from './scene/highlight.js';

type Point = [number, number, number];

/** Where a label for halfedge h goes: the middle of its arrow. */
function arrowMiddle(mesh: HalfedgeMesh, h: number): Point {
  const a = mesh.position(mesh.heVertex[h]);
  const b = mesh.position(mesh.heVertex[mesh.heNext[h]]);
  const side = mesh.heFace[h] !== -1 ? faceCentroid(mesh, mesh.heFace[h]) : null;
  const mid: Point = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2];
  if (!side) return mid;
  // a quarter of the way towards the face's centre, so twin labels do not overlap
  return [mid[0] + 0.25 * (side[0] - mid[0]), mid[1] + 0.25 * (side[1] - mid[1]), mid[2] + 0.25 * (side[2] - mid[2])];
}

export function selectionHighlight(mesh: HalfedgeMesh, s: Selection, convention: Convention): HighlightSpec {
  const spec = emptyHighlight();
  const label = (text: string, at: Point, color: string) => spec.labels.push({ text, at, color });
  const halfedge = (id: number, color: string, text?: string) => {
    spec.halfedges.push({ id, color });
    if (text) label(text, arrowMiddle(mesh, id), color);
  };
  switch (s.kind) {
    case 'halfedge': {
      const h = s.id;
      const next = mesh.heNext[h];
      const prev = mesh.hePrev[h];
      const face = mesh.heFace[h];
      if (face !== -1) {
        spec.faces.push({ id: face, color: colors.face });
        label(`f${face}`, faceCentroid(mesh, face) as Point, colors.face);
      }
      halfedge(next, colors.next, `next h${next}`);
      if (prev !== next) halfedge(prev, colors.prev, `prev h${prev}`);
      halfedge(h ^ 1, colors.twin, `twin h${h ^ 1}`);
      halfedge(h, colors.selected, `h${h}`);
      const vertex = convention === 'origin' ? mesh.heVertex[h] : mesh.heVertex[next];
      spec.vertices.push({ id: vertex, color: colors.origin });
      label(`${convention} v${vertex}`, mesh.position(vertex) as Point, colors.origin);
      break;
    }
    case 'vertex': {
      const v = s.id;
      spec.vertices.push({ id: v, color: colors.origin });
      label(`v${v}`, mesh.position(v) as Point, colors.origin);
      const start = mesh.vHalfedge[v];
      if (start < 0) break;
      let h = start;
      do {
        if (mesh.heFace[h] !== -1) spec.faces.push({ id: mesh.heFace[h], color: colors.face });
        spec.vertices.push({ id: mesh.heVertex[h ^ 1], color: colors.next });
        spec.edges.push({ id: h >> 1, color: colors.next });
        h = mesh.hePrev[h] ^ 1;
      } while (h !== start && spec.vertices.length < 4096);
      halfedge(start, colors.selected, `halfedge h${start}`);
      break;
    }
    case 'face': {
      const f = s.id;
      spec.faces.push({ id: f, color: colors.face });
      label(`f${f}`, faceCentroid(mesh, f) as Point, colors.face);
      const start = mesh.fHalfedge[f];
      let h = start;
      do {
        if (h !== start) halfedge(h, colors.next);
        h = mesh.heNext[h];
      } while (h !== start && spec.halfedges.length < 4096);
      halfedge(start, colors.selected, `halfedge h${start}`);
      break;
    }
    case 'edge': {
      const e = s.id;
      spec.edges.push({ id: e, color: colors.selected });
      halfedge(2 * e, colors.selected, `h${2 * e}`);
      halfedge(2 * e + 1, colors.twin, `h${2 * e + 1}`);
      const a = mesh.position(mesh.heVertex[2 * e]);
      const b = mesh.position(mesh.heVertex[2 * e + 1]);
      label(`e${e}`, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2], colors.selected);
      break;
    }
  }
  return spec;
}

/** The lighter preview of what a click would select. */
export function hoverHighlight(mesh: HalfedgeMesh, s: Selection): HighlightSpec {
  const spec = emptyHighlight();
  const color = colors.selected;
  if (s.kind === 'halfedge') spec.halfedges.push({ id: s.id, color });
  if (s.kind === 'vertex') spec.vertices.push({ id: s.id, color });
  if (s.kind === 'face') spec.faces.push({ id: s.id, color });
  if (s.kind === 'edge') spec.edges.push({ id: s.id, color });
  return spec;
}
