import { Matrix4, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { buildMesh, disk, grid, torus } from '../../src/index.js';
import { newPlacement, placeArrow } from '../../src/ui/scene/arrow-placement.js';
import { writeArrowMatrix } from '../../src/ui/scene/arrows.js';

describe('arrow matrices', () => {
  it('map the unit arrow onto each halfedge: tail at its start, tip at its end, as wide as placed, flat in its plane', () => {
    for (const { mesh } of [buildMesh(torus(7, 5)), buildMesh(disk(3))]) {
      const placement = newPlacement();
      const elements = new Float32Array(16 * mesh.nHalfedges);
      for (let h = 0; h < mesh.nHalfedges; h++) {
        placeArrow(mesh, h, placement, 1.5);
        writeArrowMatrix(placement, elements, 16 * h, 2);
        const matrix = new Matrix4().fromArray(elements, 16 * h);
        const at = (x: number, y: number, z: number) => new Vector3(x, y, z).applyMatrix4(matrix);
        const close = (p: Vector3, q: readonly number[]) => expect(p.distanceTo(new Vector3(...q))).toBeLessThan(1e-5);
        close(at(0, 0, 0), placement.start);
        close(at(1, 0, 0), placement.end);
        // the head's corners: half its width (times widthScale) to each side, in the arrow's plane
        const corner = at(0, 0.5, 0).sub(at(0, 0, 0));
        expect(corner.length()).toBeCloseTo(placement.width, 5);
        expect(Math.abs(corner.dot(new Vector3(...placement.normal)))).toBeLessThan(1e-5);
        expect(Math.abs(corner.dot(at(1, 0, 0).sub(at(0, 0, 0))))).toBeLessThan(1e-5);
        // the left of the arrow is normal × along: counter-clockwise seen from the front
        const along = at(1, 0, 0).sub(at(0, 0, 0));
        expect(new Vector3().crossVectors(along, corner).dot(new Vector3(...placement.normal))).toBeGreaterThan(0);
      }
    }
  });
});

describe('the typical edge length (when to draw edges and arrows)', () => {
  it('is the median of the edges’ lengths, sampled evenly on a large mesh', async () => {
    const { medianEdgeLength } = await import('../../src/ui/scene/surface.js');
    // a unit square of 2 × 2 cells cut into triangles: 12 sides of 0.5 and 4 diagonals of 0.71
    const square = buildMesh(grid(2, 2)).mesh;
    const positions = new Float32Array(square.positions);
    const edges = new Uint32Array(Array.from(square.edges()).flatMap((e) => [square.heVertex[2 * e], square.heVertex[2 * e + 1]]));
    expect(medianEdgeLength(positions, edges)).toBeCloseTo(0.5, 6);
    expect(medianEdgeLength(positions, new Uint32Array(0))).toBe(0);
    // a fine grid: sampled, not measured in full, yet the same answer
    const fine = buildMesh(grid(300, 300)).mesh;
    const fineEdges = new Uint32Array(Array.from(fine.edges()).flatMap((e) => [fine.heVertex[2 * e], fine.heVertex[2 * e + 1]]));
    expect(medianEdgeLength(new Float32Array(fine.positions), fineEdges)).toBeCloseTo(1 / 300, 6);
  });
});
