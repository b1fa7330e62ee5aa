import { Matrix4, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { buildMesh, disk, torus } from '../../src/index.js';
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
