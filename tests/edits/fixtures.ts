/** Meshes for the property tests of the modelling edits (extrude, bevels, face collapse), and what they share. */
import { expect } from 'vitest';
import { TopologyError } from '../../src/core/errors.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { annulus, cube, disk, grid, strip, tetrahedron, torus } from '../../src/core/shapes.js';
import { mergeSoups, type PolygonSoup } from '../../src/core/soup.js';
import { meshContents } from '../core/contents.js';
import { bipyramid } from './helpers.js';

/** Closed, open (one hole, two holes) and several parts at once, each with χ noted by the name. */
export const fixtures: Array<[string, () => PolygonSoup]> = [
  ['cube', cube],
  ['tetrahedron', tetrahedron],
  ['bipyramid', bipyramid],
  ['torus', () => torus(5, 4)],
  ['open grid of quads', () => grid(3, 3, true)],
  ['open grid of triangles', () => grid(2, 2)],
  ['disk', () => disk(2)],
  ['strip', () => strip(3)],
  ['annulus', () => annulus(6)],
  ['cube, tetrahedron and grid as one mesh', () => mergeSoups([cube(), tetrahedron(), grid(2, 2, true)])],
];

export function euler(mesh: HalfedgeMesh): number {
  return mesh.nVertices - mesh.nEdges + mesh.nFaces;
}

/** Asserts that `attempt` throws a TopologyError saying exactly `message` and leaves the mesh as it was. */
export function expectRefused(mesh: HalfedgeMesh, attempt: () => unknown, message: string): void {
  const before = meshContents(mesh);
  let thrown: unknown = null;
  try {
    attempt();
  } catch (error) {
    thrown = error;
  }
  expect(thrown).toBeInstanceOf(TopologyError);
  expect((thrown as TopologyError).message).toBe(message);
  expect(meshContents(mesh)).toEqual(before);
}
