import { describe, expect, it } from 'vitest';
import { buildMesh, canCollapseEdge, collapseEdge, disk, grid, type HalfedgeMesh, validate } from '../../src/core/index.js';
import { compareMeshes, replayWrites } from '../../src/core/practice/index.js';
import { inProcess, solution } from './helpers.js';

/** The edge ids of `mesh`, shortest first. */
function byLength(mesh: HalfedgeMesh): number[] {
  const length = (e: number) => {
    const [a, b] = [mesh.position(mesh.heVertex[2 * e]), mesh.position(mesh.heVertex[2 * e + 1])];
    return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  };
  return [...mesh.edges()].sort((a, b) => length(a) - length(b));
}

// The remeshing and simplification solutions are built on the collapse solution: it must do what
// the library does on every edge, not only on its exercise's fixtures (it once lost a corner
// triangle with two boundary sides, whatever side it was collapsed from)
describe('the collapse-edge test solution', () => {
  for (const [name, start] of [['a grid', grid(3, 3)], ['a disk', disk(2)]] as const) {
    it(`does what the library does, refusals included, on every edge of ${name} collapsed down one edge at a time`, async () => {
      const mesh = buildMesh(start).mesh;
      const source = solution('collapse-edge');
      let tried = 0;
      for (let step = 0; step < 100; step++) {
        const edges = [...mesh.edges()];
        const outputs = await inProcess(source, edges.map((input) => ({ mesh, input })));
        edges.forEach((e, i) => {
          const output = outputs[i];
          const library = mesh.clone();
          const refused = canCollapseEdge(library, e);
          if (!refused) collapseEdge(library, e);
          const where = `step ${step}, e${e}`;
          expect(output.error, where).toBeNull();
          expect(output.value === -1, `${where}: ${refused}`).toBe(refused !== null);
          const mine = replayWrites(mesh.clone(), output.writes);
          expect(validate(mine), where).toEqual([]);
          expect(compareMeshes(mine, library), where).toBeNull();
          tried++;
        });
        const next = byLength(mesh).find((e) => canCollapseEdge(mesh, e) === null);
        if (next === undefined) break;
        collapseEdge(mesh, next);
      }
      expect(tried).toBeGreaterThan(100);
    });
  }
});
