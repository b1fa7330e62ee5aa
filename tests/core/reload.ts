/**
 * Saving a built mesh and reading it back must give the same mesh: a face-vertex file can hold
 * exactly what the builder makes, repairs included (a slit or a second edge between two vertices
 * would close up or merge on reading, which is why the builder never makes one).
 */
import { expect } from 'vitest';
import { buildMesh, type BuildReport, type HalfedgeMesh, meshStats, readMesh, validate, writeMesh } from '../../src/index.js';

/** Counts that a save and reload must keep. */
function shape(mesh: HalfedgeMesh, report?: BuildReport) {
  const stats = meshStats(mesh, report);
  return {
    V: stats.vertices,
    E: stats.edges,
    F: stats.faces,
    loops: stats.boundaryLoops,
    components: stats.components,
    chi: stats.eulerCharacteristic,
    isolated: stats.isolatedVertices,
  };
}

/**
 * Writes `mesh` as OFF and as binary PLY, reads each back and builds it: the same counts, a valid
 * mesh, and nothing left to repair but the isolated vertices the mesh already had.
 */
export function expectSurvivesReload(mesh: HalfedgeMesh): void {
  expect(validate(mesh)).toEqual([]);
  for (const format of ['off', 'ply-binary'] as const) {
    const file = readMesh(writeMesh(mesh, format), { fileName: `reload.${format === 'off' ? 'off' : 'ply'}` });
    const reloaded = buildMesh(file.soup);
    expect(validate(reloaded.mesh)).toEqual([]);
    expect({ format, ...shape(reloaded.mesh, reloaded.report) }).toEqual({ format, ...shape(mesh) });
    expect(reloaded.report.repairs.map((r) => r.kind).filter((kind) => kind !== 'isolated-vertex')).toEqual([]);
  }
}
