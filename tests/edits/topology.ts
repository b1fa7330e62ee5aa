/** Checks the dissolve, make-boundary and weld tests share: counts and χ, a face's corners, a refusal that leaves the mesh as it was. */
import { expect } from 'vitest';
import { TopologyError } from '../../src/core/errors.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { meshStats } from '../../src/core/stats.js';
import { meshContents } from '../core/contents.js';

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
