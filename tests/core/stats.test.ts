import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  applyChange,
  boundaryEdgesChange,
  buildMesh,
  cube,
  faceArea,
  faceCentroid,
  faceNormal,
  grid,
  invertChange,
  meshStats,
  mergeSoups,
  signedVolume,
  singleTriangle,
  soupFromArrays,
  surfaceArea,
  tetrahedron,
  torus,
  triangleQuality,
  uvSphere,
  vertexNormals,
} from '../../src/index.js';
import { editSequences, runEdits } from './edit-sequences.js';

describe('meshStats', () => {
  it('measures the unit cube exactly', () => {
    const { mesh, report } = buildMesh(cube());
    const stats = meshStats(mesh, report);
    expect(stats.surfaceArea).toBe(6);
    expect(stats.volume).toBe(1);
    expect(stats.boundingBox).toEqual({ min: [0, 0, 0], max: [1, 1, 1] });
    expect(stats.faceDegrees).toEqual({ 4: 6 });
    expect(stats.closed).toBe(true);
    expect(stats.manifold).toBe(true);
    expect(stats.triangleQuality).toBeNull();
  });

  it('measures the regular tetrahedron: edge 2√2, volume 8/3', () => {
    const { mesh } = buildMesh(tetrahedron());
    const stats = meshStats(mesh);
    expect(stats.volume).toBeCloseTo(8 / 3, 12);
    expect(stats.surfaceArea).toBeCloseTo(4 * (Math.sqrt(3) / 4) * 8, 12);
    // every face equilateral: longest edge / shortest altitude = 2/√3
    expect(stats.triangleQuality!.min).toBeCloseTo(2 / Math.sqrt(3), 12);
    expect(stats.triangleQuality!.max).toBeCloseTo(2 / Math.sqrt(3), 12);
  });

  it('gives no volume for an open mesh, and the area of a right triangle', () => {
    const { mesh } = buildMesh(singleTriangle());
    const stats = meshStats(mesh);
    expect(stats.volume).toBeNull();
    expect(stats.surfaceArea).toBe(0.5);
    // legs 1, 1, hypotenuse √2: (√2)² / (2 · 1/2) = 2
    expect(stats.triangleQuality!.mean).toBeCloseTo(2, 12);
  });

  it('approaches the volume and area of the smooth torus as it is refined', () => {
    const R = 1;
    const r = 0.35;
    const { mesh } = buildMesh(torus(200, 200, R, r));
    const stats = meshStats(mesh);
    expect(stats.volume! / (2 * Math.PI ** 2 * R * r * r)).toBeCloseTo(1, 3);
    expect(stats.surfaceArea / (4 * Math.PI ** 2 * R * r)).toBeCloseTo(1, 3);
    expect(stats.genus).toBe(1);
  });

  it('counts components and sums their genera', () => {
    const { mesh } = buildMesh(mergeSoups([cube(), torus(6, 4), tetrahedron()]));
    const stats = meshStats(mesh);
    expect(stats.components).toBe(3);
    expect(stats.componentDetails.map((c) => c.genus)).toEqual([0, 1, 0]);
    expect(stats.genus).toBe(1);
    expect(stats.eulerCharacteristic).toBe(2 + 0 + 2);
  });

  it('gives each part its genus: two tori are 1 + 1, not a double torus', () => {
    const stats = meshStats(buildMesh(mergeSoups([torus(6, 4), torus(5, 3)])).mesh);
    expect(stats.genusPerPart).toEqual([1, 1]);
    expect(stats.genus).toBe(2);
  });

  it('gives a torus and a sphere their genera in component order', () => {
    const stats = meshStats(buildMesh(mergeSoups([torus(6, 4), uvSphere(4, 6)])).mesh);
    expect(stats.genusPerPart).toEqual([1, 0]);
    expect(stats.genus).toBe(1);
  });

  it('counts zero-area triangles apart in the quality figures', () => {
    const { mesh } = buildMesh(soupFromArrays([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0], [[0, 1, 2], [0, 1, 3]]));
    const quality = triangleQuality(mesh)!;
    expect(quality.count).toBe(2);
    expect(quality.degenerate).toBe(1);
  });
});

describe('normals and per-face measures', () => {
  it('gives outward unit normals on the cube', () => {
    const { mesh } = buildMesh(cube());
    for (let f = 0; f < mesh.faceSlots; f++) {
      const n = faceNormal(mesh, f);
      const c = faceCentroid(mesh, f);
      const outward = c.map((x) => x - 0.5);
      expect(n[0] * outward[0] + n[1] * outward[1] + n[2] * outward[2]).toBeCloseTo(0.5, 12);
      expect(faceArea(mesh, f)).toBe(1);
    }
  });

  it('gives vertex normals of a fine sphere close to the radial direction', () => {
    const { mesh } = buildMesh(uvSphere(40, 80));
    const normals = vertexNormals(mesh);
    const p = mesh.positions;
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const dot = normals[3 * v] * p[3 * v] + normals[3 * v + 1] * p[3 * v + 1] + normals[3 * v + 2] * p[3 * v + 2];
      expect(dot).toBeGreaterThan(0.999);
    }
  });

  it('finds the signed volume and area of a planar grid are 0 and 1', () => {
    const { mesh } = buildMesh(grid(4, 4));
    expect(signedVolume(mesh)).toBe(0);
    expect(surfaceArea(mesh)).toBeCloseTo(1, 14);
  });
});

describe('boundaryEdgesChange (seed 20261126)', () => {
  it('tells how far each of random edits and its undo moved the boundary-edge count, on open meshes too', () => {
    let moved = 0;
    fc.assert(
      fc.property(editSequences, (sequence) => {
        runEdits(sequence, (mesh, record, step) => {
          const after = meshStats(mesh).boundaryEdges;
          applyChange(mesh, record, 'backward');
          const before = meshStats(mesh).boundaryEdges;
          expect(boundaryEdgesChange(mesh, invertChange(record)), `${step}, undone`).toBe(before - after);
          applyChange(mesh, record, 'forward');
          expect(boundaryEdgesChange(mesh, record), step).toBe(after - before);
          if (after !== before) moved++;
        });
      }),
      { seed: 20261126, numRuns: 300 },
    );
    expect(moved).toBeGreaterThan(100);
  });
});
