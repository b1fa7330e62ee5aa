/**
 * Checks the dissolve, make-boundary and weld tests share: counts and χ, a face's corners, a
 * refusal that leaves the mesh as it was, and the start meshes and steps of their property tests.
 */
import { expect } from 'vitest';
import type { EditResult } from '../../src/core/edits/index.js';
import { TopologyError } from '../../src/core/errors.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { annulus, cube, disk, fan, grid, strip, tetrahedron, torus, uvSphere } from '../../src/core/shapes.js';
import { mergeSoups, type PolygonSoup } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { meshContents } from '../core/contents.js';
import { checkedEdit } from './helpers.js';

export interface Topology {
  V: number;
  E: number;
  F: number;
  chi: number;
  loops: number;
  components: number;
}

/** V, E, F, χ, boundary loops and connected pieces, from `meshStats`. */
export function topology(mesh: HalfedgeMesh): Topology {
  const s = meshStats(mesh);
  return { V: s.vertices, E: s.edges, F: s.faces, chi: s.eulerCharacteristic, loops: s.boundaryLoops, components: s.components };
}

/** The corners of face `f` in order, starting from the smallest id (so equal cycles compare equal). */
export function corners(mesh: HalfedgeMesh, f: number): number[] {
  const list: number[] = [];
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    list.push(mesh.heVertex[h]);
    h = mesh.heNext[h];
  } while (h !== start && list.length <= mesh.halfedgeSlots);
  const k = list.indexOf(Math.min(...list));
  return list.slice(k).concat(list.slice(0, k));
}

/** The smallest halfedge id on the `next` cycle through `h`: the same number for every halfedge of a loop. */
export function loopId(mesh: HalfedgeMesh, h: number): number {
  let min = h;
  let g = mesh.heNext[h];
  for (let i = 0; g !== h && i <= mesh.halfedgeSlots; i++, g = mesh.heNext[g]) min = Math.min(min, g);
  return min;
}

/**
 * The predicate says `sentence`; the edit, called anyway, throws a TopologyError that starts with
 * its name and says it too; and the mesh is left exactly as it was.
 */
export function expectRefused(mesh: HalfedgeMesh, why: string | null, sentence: string | RegExp, name: string, edit: (mesh: HalfedgeMesh) => unknown): void {
  if (typeof sentence === 'string') expect(why).toBe(sentence);
  else expect(why).toMatch(sentence);
  const before = meshContents(mesh);
  let thrown: unknown = null;
  try {
    edit(mesh);
  } catch (error) {
    thrown = error;
  }
  expect(thrown).toBeInstanceOf(TopologyError);
  expect((thrown as Error).message).toBe(`${name}: ${why}`);
  expect(meshContents(mesh)).toEqual(before);
}

/** Start meshes of the property tests: closed, open, with two holes, and of several pieces. */
export const propertyShapes: Record<string, () => PolygonSoup> = {
  cube,
  tetrahedron,
  sphere: () => uvSphere(4, 6),
  torus: () => torus(4, 3),
  grid: () => grid(3, 3),
  quadGrid: () => grid(3, 2, true),
  disk: () => disk(2),
  strip: () => strip(3),
  fan: () => fan(4, 1.5 * Math.PI),
  annulus: () => annulus(6),
  cubeAndGrid: () => mergeSoups([cube(), grid(2, 2)]),
  threePieces: () => mergeSoups([tetrahedron(), annulus(4), fan(3)]),
};

/** The `k`-th of `ids` (modulo their number), or -1 when there are none. */
export function nth(ids: Iterable<number>, k: number): number {
  const list = [...ids];
  return list.length === 0 ? -1 : list[k % list.length];
}

/** The live boundary edges. */
export function boundaryEdges(mesh: HalfedgeMesh): number[] {
  return [...mesh.edges()].filter((e) => mesh.isBoundaryEdge(e));
}

/**
 * How χ changes when face `f` becomes a hole, counted before: −1 for the face, +1 for each edge
 * along a hole (it goes), −1 for each corner whose two edges on f both lie along a hole (it goes).
 */
export function holeChiChange(mesh: HalfedgeMesh, f: number): number {
  let change = -1;
  const start = mesh.fHalfedge[f];
  let h = start;
  do {
    const along = mesh.heFace[h ^ 1] === -1;
    if (along) change++;
    if (along && mesh.heFace[mesh.heNext[h] ^ 1] === -1) change--;
    h = mesh.heNext[h];
  } while (h !== start);
  return change;
}

/**
 * One step of a property test: when the predicate allows it, the edit, checked against the
 * pointer-diff oracle, validity and its undo/redo; when not, the refusal, mesh unchanged. Returns
 * the result, or null when refused.
 */
export function step<R extends EditResult>(mesh: HalfedgeMesh, why: string | null, name: string, edit: (mesh: HalfedgeMesh) => R): R | null {
  if (why) {
    expectRefused(mesh, why, why, name, edit);
    return null;
  }
  return checkedEdit(mesh, edit);
}
