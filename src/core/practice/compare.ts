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
  const atReference = nearestVertexIn(reference, sameSpotTolerance(reference));
  const match = new Map<number, number>(); // your vertex → reference vertex
  const taken = new Set<number>();
  for (const v of yours.vertices()) {
    const r = atReference(yours.position(v));
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
    case 'face': {
      if (reference === -1 || yours === -1) return yours === reference ? null : said;
      if (typeof yours !== 'number' || !Number.isInteger(yours) || yours < 0 || yours >= yourMesh.faceSlots || yourMesh.isFaceDeleted(yours)) {
        return `your code returned ${show(yours)}, which is not a face of your mesh; the library's answer is f${String(reference)}`;
      }
      const tolerance = sameSpotTolerance(referenceMesh);
      const corners = (mesh: HalfedgeMesh, f: number) => faceCorners(mesh, f).map((v) => mesh.position(v));
      const [mine, theirs] = [corners(yourMesh, yours), corners(referenceMesh, reference as number)];
      const same = mine.length === theirs.length && theirs.some((_, start) => mine.every((p, i) => distance(p, theirs[(start + i) % theirs.length]) <= tolerance));
      return same ? null : `your code returned f${yours}, with corners at ${mine.map(formatPoint).join(' → ')}; the library's face has them at ${theirs.map(formatPoint).join(' → ')}`;
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

/**
 * Null when `yours` is a triangulation of `before` with the library's result `reference`, else the
 * first difference in words: the same vertices (by position) and holes as the reference, every
 * face the reference left as it was left so, and every other face a triangle whose corners follow
 * one another around one face of `before` (a diagonal, never a new edge across two faces), turning
 * the way that face turns (a triangle that folds over, or has no area, is not a cut of the face).
 * With the counts equal to the reference's and every edge of `before` kept, those triangles tile
 * each face: any diagonals pass, not only the library's.
 */
export function compareTriangulation(yours: HalfedgeMesh, reference: HalfedgeMesh, before: HalfedgeMesh): string | null {
  const counts = (m: HalfedgeMesh) => [m.nVertices, m.nEdges, m.nFaces];
  const [v, e, f] = counts(yours);
  const [rv, re, rf] = counts(reference);
  if (v !== rv || e !== re || f !== rf) {
    return `your mesh has ${v} vertices, ${e} edges and ${f} faces; the library's has ${rv}, ${re} and ${rf}`;
  }
  const atBefore = nearestVertexIn(before, sameSpotTolerance(reference));
  // your vertex → the vertex of `before` at its place (a triangulation adds no vertex)
  const match = new Map<number, number>();
  const taken = new Set<number>();
  for (const v of yours.vertices()) {
    const b = atBefore(yours.position(v));
    if (b === -1 || taken.has(b)) return `your v${v} is at ${formatPoint(yours.position(v))}, where the fixture had no vertex of its own`;
    taken.add(b);
    match.set(v, b);
  }
  const mapped = (cycle: number[]) => cycle.map((v) => match.get(v) ?? -1);
  const yourEdges = new Set<string>();
  for (const e of yours.edges()) yourEdges.add(edgeKey(match.get(yours.heVertex[2 * e]) ?? -1, match.get(yours.heVertex[2 * e + 1]) ?? -1));
  for (const e of before.edges()) {
    const [a, b] = [before.heVertex[2 * e], before.heVertex[2 * e + 1]];
    if (!yourEdges.has(edgeKey(a, b))) return `the edge between v${a} and v${b} is gone from your mesh: a triangulation only adds diagonals`;
  }
  // the faces the library left (those it could not cut), as they were
  const kept = new Set(cycles(reference, false).filter(({ corners }) => corners.length > 3).map(({ corners }) => canonical(corners.map((v) => atBefore(reference.position(v))))));
  // for each vertex of `before`, the faces it is a corner of, with its place around each
  const facesAt = new Map<number, { face: number; corners: number[] }[]>();
  for (const { id, corners } of cycles(before, false)) {
    for (const c of corners) facesAt.set(c, [...(facesAt.get(c) ?? []), { face: id, corners }]);
  }
  // the fixture's own triangles, untouched (a triangle with no area, too, is no face to cut)
  const triangles = new Set(cycles(before, false).filter(({ corners }) => corners.length === 3).map(({ corners }) => canonical(corners)));
  for (const { id, corners } of cycles(yours, false)) {
    const cycle = mapped(corners);
    if (kept.has(canonical(cycle)) || triangles.has(canonical(cycle))) continue;
    if (cycle.length !== 3) return `your f${id} has ${cycle.length} sides: every face the library cut must be cut into triangles`;
    const within = (facesAt.get(cycle[0]) ?? []).find(({ corners }) => inOrderAround(corners, cycle));
    if (!within) return `your f${id} (${corners.map((v) => `v${v}`).join(' → ')}) is not a triangle cut from one face of the fixture, in its order`;
    const normal = faceNormalOf(before, within.corners);
    const [p, q, r] = cycle.map((v) => before.position(v));
    const turn = crossOf([q[0] - p[0], q[1] - p[1], q[2] - p[2]], [r[0] - p[0], r[1] - p[1], r[2] - p[2]]);
    const along = turn[0] * normal[0] + turn[1] * normal[1] + turn[2] * normal[2];
    const scale = Math.hypot(...turn) * Math.hypot(...normal);
    if (!(along > 1e-9 * scale) || scale === 0) {
      return `your f${id} (${corners.map((v) => `v${v}`).join(' → ')}) ${scale === 0 ? 'has no area' : 'folds over: it turns against its face'}: cut f${within.face} of the fixture along other diagonals`;
    }
  }
  const referenceHoles = new Set(cycles(reference, true).map(({ corners }) => canonical(corners.map((v) => atBefore(reference.position(v))))));
  const yourHoles = cycles(yours, true);
  if (yourHoles.length !== referenceHoles.size) return `your mesh has ${yourHoles.length} boundary loops; the library's has ${referenceHoles.size}`;
  for (const { id, corners } of yourHoles) {
    if (!referenceHoles.has(canonical(mapped(corners)))) {
      return `the boundary loop through your h${id} (${corners.map((v) => `v${v}`).join(' → ')}) is not a boundary loop of the library's result`;
    }
  }
  return null;
}

/** The corners of face `f`, from its halfedge. */
function faceCorners(mesh: HalfedgeMesh, f: number): number[] {
  return loopCorners(mesh, mesh.fHalfedge[f]);
}

/** The corners along `next` from halfedge `start` (bounded by the mesh's size). */
export function loopCorners(mesh: HalfedgeMesh, start: number): number[] {
  const corners: number[] = [];
  let h = start;
  do {
    corners.push(mesh.heVertex[h]);
    h = mesh.heNext[h];
  } while (h !== start && h >= 0 && corners.length <= mesh.halfedgeSlots);
  return corners;
}

function inOrderAround(cycle: number[], part: number[]): boolean {
  const at = part.map((v) => cycle.indexOf(v));
  if (at.some((i) => i < 0)) return false;
  let turns = 0;
  for (let i = 0; i < at.length; i++) if (at[(i + 1) % at.length] < at[i]) turns++;
  return turns === 1;
}

/** Newell's vector area of a polygon given by its corners. */
function faceNormalOf(mesh: HalfedgeMesh, corners: number[]): number[] {
  const n = [0, 0, 0];
  for (let i = 0; i < corners.length; i++) {
    const p = mesh.position(corners[i]);
    const q = mesh.position(corners[(i + 1) % corners.length]);
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

function crossOf(a: number[], b: number[]): number[] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
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

/**
 * The vertex of `mesh` nearest a point, within `tolerance` (of equally near ones the highest id,
 * as a scan of every vertex in order finds it), or -1. The vertices are put in cells twice the
 * tolerance wide, so that only the 27 cells around the point's own can hold one near enough:
 * matching every vertex of a mesh costs its size, not its square.
 */
export function nearestVertexIn(mesh: HalfedgeMesh, tolerance: number): (p: number[]) => number {
  const size = 2 * tolerance;
  const { positions } = mesh;
  // cells whose numbers share a key are searched together: whatever is found there is measured
  const key = (i: number, j: number, k: number) => Math.imul(i, 73856093) ^ Math.imul(j, 19349663) ^ Math.imul(k, 83492791);
  const cellOf = (x: number) => Math.floor(x / size);
  const cells = new Map<number, number[]>();
  for (const v of mesh.vertices()) {
    const at = key(cellOf(positions[3 * v]), cellOf(positions[3 * v + 1]), cellOf(positions[3 * v + 2]));
    const cell = cells.get(at);
    if (cell) cell.push(v);
    else cells.set(at, [v]);
  }
  return ([x, y, z]) => {
    const [i, j, k] = [cellOf(x), cellOf(y), cellOf(z)];
    let best = -1;
    let bestDistance = tolerance;
    for (let di = -1; di <= 1; di++) {
      for (let dj = -1; dj <= 1; dj++) {
        for (let dk = -1; dk <= 1; dk++) {
          for (const v of cells.get(key(i + di, j + dj, k + dk)) ?? []) {
            const d = Math.hypot(x - positions[3 * v], y - positions[3 * v + 1], z - positions[3 * v + 2]);
            if (d < bestDistance || (d === bestDistance && v > best)) {
              best = v;
              bestDistance = d;
            }
          }
        }
      }
    }
    return best;
  };
}

function distance(p: number[], q: number[]): number {
  return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

/** How near two positions must be to be the same vertex: a millionth of the mesh's size. */
export function sameSpotTolerance(mesh: HalfedgeMesh): number {
  const box = boundingBox(mesh);
  const diagonal = box ? Math.hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]) : 0;
  return 1e-6 * Math.max(1e-12, diagonal);
}

function formatPoint(p: number[]): string {
  return `(${p.map((x) => Math.round(x * 1e4) / 1e4).join(', ')})`;
}
