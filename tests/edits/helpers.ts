/** Shared checks for the local edits: the reported changes against the pointer diff, and validity. */
import { expect } from 'vitest';
import { buildMesh } from '../../src/core/build.js';
import { applyChange } from '../../src/core/change/record.js';
import { diffPointers } from '../../src/core/change/diff.js';
import type { EditResult } from '../../src/core/edits/index.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { soupFromArrays, type PolygonSoup } from '../../src/core/soup.js';
import { validate } from '../../src/core/validate.js';
import { meshContents } from '../core/contents.js';

/**
 * Runs `edit` on `mesh`, then checks that the mesh is valid, that the edit reported exactly the
 * pointer changes `diffPointers` finds against a copy taken before, and that its change record
 * undoes and redoes it: backwards gives the mesh before, every array equal, and forwards the mesh
 * after. Returns the result.
 */
export function checkedEdit<R extends EditResult>(mesh: HalfedgeMesh, edit: (mesh: HalfedgeMesh) => R): R {
  const before = mesh.clone();
  const result = edit(mesh);
  expect(validate(mesh)).toEqual([]);
  expect(result.changes).toEqual(diffPointers(before, mesh, Infinity).changes);
  const after = meshContents(mesh);
  applyChange(mesh, result.record!, 'backward');
  expect(meshContents(mesh)).toEqual(meshContents(before));
  applyChange(mesh, result.record!, 'forward');
  expect(meshContents(mesh)).toEqual(after);
  return result;
}

export function meshOf(soup: PolygonSoup): HalfedgeMesh {
  const { mesh } = buildMesh(soup);
  expect(validate(mesh)).toEqual([]);
  return mesh;
}

/** Face degree → count, for live faces. */
export function degrees(mesh: HalfedgeMesh): Record<number, number> {
  const counts: Record<number, number> = {};
  for (const f of mesh.faces()) counts[mesh.faceDegree(f)] = (counts[mesh.faceDegree(f)] ?? 0) + 1;
  return counts;
}

export function counts(mesh: HalfedgeMesh): [number, number, number] {
  return [mesh.nVertices, mesh.nEdges, mesh.nFaces];
}

/** The edge joining u and v (either way round), or -1. */
export function edgeBetween(mesh: HalfedgeMesh, u: number, v: number): number {
  for (const e of mesh.edges()) {
    const a = mesh.heVertex[2 * e];
    const b = mesh.heVertex[2 * e + 1];
    if ((a === u && b === v) || (a === v && b === u)) return e;
  }
  return -1;
}

/** Two triangles on the unit square, sharing the diagonal 0–2: (0, 1, 2) and (0, 2, 3). */
export function square(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0],
    [
      [0, 1, 2],
      [0, 2, 3],
    ],
  );
}

/** Two triangles (0, 1, 2), (1, 0, 3) and a quad (0, 2, 1, 3) closing a sphere around them. */
export function triangleQuadPillow(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 0.5, 1, 0.2, 0.5, -1, 0.2],
    [
      [0, 1, 2],
      [1, 0, 3],
      [0, 2, 1, 3],
    ],
  );
}

/** Triangular bipyramid: equator 0, 1, 2 (counter-clockwise seen from +z), poles 3 (+z) and 4 (−z). */
export function bipyramid(): PolygonSoup {
  const positions = [1, 0, 0, -0.5, 0.866, 0, -0.5, -0.866, 0, 0, 0, 1, 0, 0, -1];
  return soupFromArrays(positions, [
    [0, 1, 3],
    [1, 2, 3],
    [2, 0, 3],
    [1, 0, 4],
    [2, 1, 4],
    [0, 2, 4],
  ]);
}
