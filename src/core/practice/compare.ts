/**
 * Is the student's mesh the reference's, up to the ids of new and deleted elements? Vertices are
 * matched by position (within a millionth of the mesh's size, since the same formula summed in
 * another order differs in its last bits), then every face and every hole is compared as a cyclic
 * list of matched vertices, and every edge as the pair it joins. The first difference is said in
 * the student's ids.
 */
import { boundingBox } from '../geometry.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { AnswerKind } from './exercise.js';

/** Null when `yours` is `reference` up to ids, else the first difference in words. */
export function compareMeshes(yours: HalfedgeMesh, reference: HalfedgeMesh): string | null {
  const counts = (m: HalfedgeMesh) => [m.nVertices, m.nEdges, m.nFaces];
  const [v, e, f] = counts(yours);
  const [rv, re, rf] = counts(reference);
  if (v !== rv || e !== re || f !== rf) {
    return `your mesh has ${v} vertices, ${e} edges and ${f} faces; the library's has ${rv}, ${re} and ${rf}`;
  }
  const tolerance = sameSpotTolerance(reference);
  const match = new Map<number, number>(); // your vertex → reference vertex
  const taken = new Set<number>();
  for (const v of yours.vertices()) {
    const r = nearestVertex(reference, yours.position(v), tolerance);
    if (r === -1) return `your v${v} is at ${formatPoint(yours.position(v))}, where the library's mesh has no vertex`;
    if (taken.has(r)) return `your v${v} is at ${formatPoint(yours.position(v))}, where another of your vertices already is`;
    taken.add(r);
    match.set(v, r);
  }
  const mapped = (cycle: number[]) => cycle.map((v) => match.get(v) ?? -1);
  const yourFaces = cycles(yours, false);
  const referenceFaces = new Set(cycles(reference, false).map(({ corners }) => canonical(corners)));
  for (const { id, corners } of yourFaces) {
    if (!referenceFaces.has(canonical(mapped(corners)))) {
      return `your f${id} (${corners.map((v) => `v${v}`).join(' → ')}) is not a face of the library's result`;
    }
  }
  const referenceHoles = new Set(cycles(reference, true).map(({ corners }) => canonical(corners)));
  const yourHoles = cycles(yours, true);
  if (yourHoles.length !== referenceHoles.size) {
    return `your mesh has ${yourHoles.length} boundary loops; the library's has ${referenceHoles.size}`;
  }
  for (const { id, corners } of yourHoles) {
    if (!referenceHoles.has(canonical(mapped(corners)))) {
      return `the boundary loop through your h${id} (${corners.map((v) => `v${v}`).join(' → ')}) is not a boundary loop of the library's result`;
    }
  }
  const referenceEdges = new Set<string>();
  for (const e of reference.edges()) referenceEdges.add(edgeKey(reference.heVertex[2 * e], reference.heVertex[2 * e + 1]));
  for (const e of yours.edges()) {
    const [a, b] = [yours.heVertex[2 * e], yours.heVertex[2 * e + 1]];
    if (!referenceEdges.has(edgeKey(match.get(a) ?? -1, match.get(b) ?? -1))) {
      return `your e${e} joins v${a} and v${b}, which the library's result does not join`;
    }
  }
  return null;
}

/** Null when the answers agree (as `kind` says), else the difference in words. */
export function compareAnswers(kind: AnswerKind, yours: unknown, reference: unknown, yourMesh: HalfedgeMesh, referenceMesh: HalfedgeMesh): string | null {
  const said = `your code returned ${show(yours)}; the library's answer is ${show(reference)}`;
  switch (kind) {
    case 'none':
      return null;
    case 'exact':
      return JSON.stringify(yours) === JSON.stringify(reference) ? null : said;
    case 'cycle': {
      if (!Array.isArray(yours) || !Array.isArray(reference)) return said;
      return yours.length === reference.length && canonical(yours as number[]) === canonical(reference as number[]) ? null : `${said} (any starting vertex is right; the order is not)`;
    }
    case 'vertex': {
      if (reference === -1 || yours === -1) return yours === reference ? null : said;
      if (typeof yours !== 'number' || !Number.isInteger(yours) || yours < 0 || yours >= yourMesh.vertexSlots || yourMesh.isVertexDeleted(yours)) {
        return `your code returned ${show(yours)}, which is not a vertex of your mesh; the library's answer is v${String(reference)}`;
      }
      const tolerance = sameSpotTolerance(referenceMesh);
      const [p, q] = [yourMesh.position(yours), referenceMesh.position(reference as number)];
      return distance(p, q) <= tolerance ? null : `your code returned v${yours} at ${formatPoint(p)}; the library's vertex is at ${formatPoint(q)}`;
    }
  }
}

function show(value: unknown): string {
  if (value === undefined) return 'nothing';
  const text = JSON.stringify(value);
  return text === undefined ? String(value) : text.length > 80 ? `${text.slice(0, 77)}…` : text;
}

/** Each live face (or, with `holes`, each boundary loop) as its corners in order, with an id to name it by. */
function cycles(mesh: HalfedgeMesh, holes: boolean): { id: number; corners: number[] }[] {
  const out: { id: number; corners: number[] }[] = [];
  const seen = new Uint8Array(mesh.halfedgeSlots);
  for (const h of mesh.halfedges()) {
    if (seen[h] || (mesh.heFace[h] === -1) !== holes) continue;
    const corners: number[] = [];
    let g = h;
    // bounded: a cycle has at most as many halfedges as the mesh
    for (let steps = 0; steps <= mesh.halfedgeSlots && !seen[g]; steps++) {
      seen[g] = 1;
      corners.push(mesh.heVertex[g]);
      g = mesh.heNext[g];
      if (g < 0) break;
    }
    out.push({ id: holes ? h : mesh.heFace[h], corners });
  }
  return out;
}

/** The cycle written from its smallest id, so that equal cycles give equal text. */
function canonical(cycle: number[]): string {
  if (cycle.length === 0) return '';
  let start = 0;
  for (let i = 1; i < cycle.length; i++) {
    if (compareRotations(cycle, i, start) < 0) start = i;
  }
  return [...cycle.slice(start), ...cycle.slice(0, start)].join(',');
}

function compareRotations(cycle: number[], a: number, b: number): number {
  for (let k = 0; k < cycle.length; k++) {
    const d = cycle[(a + k) % cycle.length] - cycle[(b + k) % cycle.length];
    if (d !== 0) return d;
  }
  return 0;
}

function edgeKey(a: number, b: number): string {
  return a < b ? `${a},${b}` : `${b},${a}`;
}

function nearestVertex(mesh: HalfedgeMesh, p: number[], tolerance: number): number {
  let best = -1;
  let bestDistance = tolerance;
  for (const v of mesh.vertices()) {
    const d = distance(p, mesh.position(v));
    if (d <= bestDistance) {
      best = v;
      bestDistance = d;
    }
  }
  return best;
}

function distance(p: number[], q: number[]): number {
  return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

/** How near two positions must be to be the same vertex: a millionth of the mesh's size. */
function sameSpotTolerance(mesh: HalfedgeMesh): number {
  const box = boundingBox(mesh);
  const diagonal = box ? Math.hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]) : 0;
  return 1e-6 * Math.max(1e-12, diagonal);
}

function formatPoint(p: number[]): string {
  return `(${p.map((x) => Math.round(x * 1e4) / 1e4).join(', ')})`;
}
