/**
 * Saving a built mesh and reading it back must give the same mesh: a face-vertex file can hold
 * exactly what the builder makes, repairs included (a slit or a second edge between two vertices
 * would close up or merge on reading, which is why the builder never makes one).
 */
import { expect } from 'vitest';
import { reloadDifference } from '../../fuzz/reload.js';
import { type HalfedgeMesh, validate } from '../../src/index.js';

/** `mesh` is valid, and saved as OFF, binary PLY and halfedge JSON it reads back to the same mesh. */
export function expectSurvivesReload(mesh: HalfedgeMesh): void {
  expect(validate(mesh)).toEqual([]);
  expect(reloadDifference(mesh)).toBeNull();
}
