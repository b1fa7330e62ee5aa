/**
 * A face's triangles for drawing and for triangle-only files: `degree − 2` of them, on its own
 * corners, wound as the face, and covering exactly the face (seen along its normal), convex or not.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { buildMesh, faceVectorArea, type HalfedgeMesh } from '../../src/index.js';
import { faceTriangles } from '../../src/core/face-triangles.js';

/** A face of `n` corners at the given angles (sorted: a polygon star-shaped around its centre, so simple) and radii, turned and bent out of its plane a little. */
function starFace(angles: number[], radii: number[], tilt: [number, number], bend: number): HalfedgeMesh {
  const [a, b] = tilt;
  const positions = new Float64Array(3 * angles.length);
  angles.forEach((angle, i) => {
    const x = radii[i] * Math.cos(angle);
    const y = radii[i] * Math.sin(angle);
    const z = bend * (i % 2 === 0 ? 1 : -1);
    // turned about x by a, then about z by b
    const y1 = y * Math.cos(a) - z * Math.sin(a);
    const z1 = y * Math.sin(a) + z * Math.cos(a);
    positions.set([x * Math.cos(b) - y1 * Math.sin(b), x * Math.sin(b) + y1 * Math.cos(b), z1], 3 * i);
  });
  const faceIndices = Uint32Array.from(angles, (_, i) => i);
  return buildMesh({ positions, faceStarts: Uint32Array.of(0, angles.length), faceIndices }).mesh;
}

/** The area of triangle (a, b, c) along `normal` (a unit vector): negative when wound against it. */
function areaAlong(mesh: HalfedgeMesh, [a, b, c]: number[], normal: number[]): number {
  const [p, q, r] = [a, b, c].map((v) => mesh.position(v));
  const u = [0, 1, 2].map((k) => q[k] - p[k]);
  const w = [0, 1, 2].map((k) => r[k] - p[k]);
  const cross = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
  return (cross[0] * normal[0] + cross[1] * normal[1] + cross[2] * normal[2]) / 2;
}

describe('faceTriangles', () => {
  it('covers a face of up to twelve corners, convex or not and a little bent, with degree − 2 triangles wound as the face', () => {
    const corners = fc.integer({ min: 4, max: 12 });
    const face = corners.chain((n) =>
      fc.record({
        angles: fc.uniqueArray(fc.integer({ min: 0, max: 359 }), { minLength: n, maxLength: n }).map((degrees) => degrees.sort((p, q) => p - q).map((d) => (d * Math.PI) / 180)),
        radii: fc.array(fc.double({ min: 0.2, max: 1, noNaN: true }), { minLength: n, maxLength: n }),
        tilt: fc.tuple(fc.double({ min: -3, max: 3, noNaN: true }), fc.double({ min: -3, max: 3, noNaN: true })),
        bend: fc.double({ min: 0, max: 1e-3, noNaN: true }),
      }),
    );
    let notConvex = 0;
    fc.assert(
      fc.property(face, ({ angles, radii, tilt, bend }) => {
        // a polygon with a gap of half a turn or more between corners is not star-shaped around its centre
        const gaps = angles.map((angle, i) => (i + 1 < angles.length ? angles[i + 1] : angles[0] + 2 * Math.PI) - angle);
        fc.pre(Math.max(...gaps) < Math.PI * 0.95);
        const mesh = starFace(angles, radii, tilt, bend);
        const n = angles.length;
        const vectorArea = faceVectorArea(mesh, 0);
        const area = Math.hypot(...vectorArea);
        const normal = vectorArea.map((x) => x / area);
        const triangles = Array.from(faceTriangles(mesh, 0));
        expect(triangles).toHaveLength(3 * (n - 2));
        expect(triangles.every((v) => v >= 0 && v < n)).toBe(true);
        let covered = 0;
        for (let t = 0; t < triangles.length; t += 3) {
          const part = areaAlong(mesh, triangles.slice(t, t + 3), normal);
          // none wound against the face (a fan across a reflex corner would be)
          expect(part).toBeGreaterThan(-1e-9);
          covered += part;
        }
        // the triangles together are the face: no overlap, no gap
        expect(covered).toBeCloseTo(area, 6);
        for (let i = 0; i < n; i++) if (areaAlong(mesh, [(i + n - 1) % n, i, (i + 1) % n], normal) < -1e-9) notConvex++;
      }),
      { seed: 28, numRuns: 400 },
    );
    // the faces drawn were mostly not convex: the ear clipping was what was tested
    expect(notConvex).toBeGreaterThan(400);
  });
});
