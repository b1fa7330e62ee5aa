import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { faceHalfedges, loopHalfedges } from '../../src/core/circulators.js';
import { canExtrudeFace, extrudeFace } from '../../src/core/edits/index.js';
import { faceArea, faceCentroid, faceNormal, signedVolume } from '../../src/core/geometry.js';
import { cube, grid, tetrahedron, torus } from '../../src/core/shapes.js';
import { seamEdges } from '../../src/core/seams.js';
import { soupFromArrays } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { euler, expectRefused, fixtures } from './fixtures.js';
import { checkedEdit, counts, degrees, meshOf } from './helpers.js';

const SEED = 4242;

const cornersOf = (mesh: ReturnType<typeof meshOf>, f: number) => [...faceHalfedges(mesh, f)].map((h) => mesh.heVertex[h]);

describe('extrudeFace', () => {
  it('pulls a cube face out along its normal on a ring of four quads', () => {
    const mesh = meshOf(cube());
    const { face, created } = checkedEdit(mesh, (m) => extrudeFace(m, 1, { offset: 0.5 }));
    expect(face).toBe(1);
    expect(counts(mesh)).toEqual([12, 20, 10]);
    expect(euler(mesh)).toBe(2);
    expect(degrees(mesh)).toEqual({ 4: 10 });
    expect([created.vertices, created.edges, created.faces].map((ids) => ids?.length)).toEqual([4, 8, 4]);
    // the top face (z = 1, normal +z) now sits at z = 1.5 over the same square
    expect(cornersOf(mesh, 1).map((v) => mesh.position(v))).toEqual([
      [0, 0, 1.5],
      [1, 0, 1.5],
      [1, 1, 1.5],
      [0, 1, 1.5],
    ]);
    expect(faceCentroid(mesh, 1)).toEqual([0.5, 0.5, 1.5]);
    expect(signedVolume(mesh)).toBeCloseTo(1.5, 14);
  });

  it('insets a cube face without moving it: the corners go half way to the centroid', () => {
    const mesh = meshOf(cube());
    checkedEdit(mesh, (m) => extrudeFace(m, 1, { inset: 0.5 }));
    expect(cornersOf(mesh, 1).map((v) => mesh.position(v))).toEqual([
      [0.25, 0.25, 1],
      [0.75, 0.25, 1],
      [0.75, 0.75, 1],
      [0.25, 0.75, 1],
    ]);
    expect(faceArea(mesh, 1)).toBe(0.25);
    expect(signedVolume(mesh)).toBeCloseTo(1, 14);
  });

  it("gives the assignment's example: a quad beside a triangle, shrunk by half", () => {
    const mesh = meshOf(
      soupFromArrays(
        [-1, 1, 0, 1, 1, 0, 2, 0, 0, -1, -1, 0, 1, -1, 0],
        [
          [0, 3, 4, 1],
          [1, 4, 2],
        ],
      ),
    );
    checkedEdit(mesh, (m) => extrudeFace(m, 0, { inset: 0.5 }));
    expect(counts(mesh)).toEqual([9, 14, 6]);
    expect(degrees(mesh)).toEqual({ 3: 1, 4: 5 });
    expect(cornersOf(mesh, 0).map((v) => mesh.position(v))).toEqual([
      [-0.5, 0.5, 0],
      [-0.5, -0.5, 0],
      [0.5, -0.5, 0],
      [0.5, 0.5, 0],
    ]);
  });

  it('moves a tilted triangle by the offset along its normal and shrinks it by the inset', () => {
    const mesh = meshOf(tetrahedron());
    const [centroid, normal, area] = [faceCentroid(mesh, 2), faceNormal(mesh, 2), faceArea(mesh, 2)];
    checkedEdit(mesh, (m) => extrudeFace(m, 2, { offset: 0.3, inset: 0.25 }));
    faceCentroid(mesh, 2).forEach((x, c) => expect(x).toBeCloseTo(centroid[c] + 0.3 * normal[c], 14));
    faceNormal(mesh, 2).forEach((x, c) => expect(x).toBeCloseTo(normal[c], 14));
    expect(faceArea(mesh, 2)).toBeCloseTo(area * 0.75 ** 2, 14);
    expect([counts(mesh), euler(mesh)]).toEqual([[7, 12, 7], 2]);
  });

  it('extrudes a face on the boundary: the quad on each boundary side has the old boundary as its outer side', () => {
    const mesh = meshOf(grid(2, 2, true)); // face 0 is a corner cell: two of its sides are on the boundary
    const boundaryBefore = [...loopHalfedges(mesh, mesh.vHalfedge[0])];
    checkedEdit(mesh, (m) => extrudeFace(m, 0, { offset: 1 }));
    expect(counts(mesh)).toEqual([13, 20, 8]);
    expect(euler(mesh)).toBe(1);
    // the same hole, on the same halfedges; the faces inside them now the ring's quads
    expect([...loopHalfedges(mesh, mesh.vHalfedge[0])]).toEqual(boundaryBefore);
    const stats = meshStats(mesh);
    expect([stats.boundaryLoops, stats.components]).toEqual([1, 1]);
    expect(cornersOf(mesh, 0).map((v) => mesh.position(v)[2])).toEqual([1, 1, 1, 1]);
  });

  it('keeps a torus a torus', () => {
    const mesh = meshOf(torus(5, 4));
    checkedEdit(mesh, (m) => extrudeFace(m, 7, { offset: 0.1, inset: 0.2 }));
    expect(counts(mesh)).toEqual([24, 48, 24]);
    expect(meshStats(mesh).genus).toBe(1);
  });

  it('copies vertex and face attributes to the new elements and keeps every corner value, so no seam appears', () => {
    const mesh = meshOf(cube());
    const heat = mesh.vertexAttributes.add('heat', 'float64', 1);
    heat.data.set([0, 1, 2, 3, 4, 5, 6, 7]);
    const material = mesh.faceAttributes.add('material', 'uint8', 1);
    material.data.set([0, 9, 0, 0, 0, 0]);
    const uv = mesh.halfedgeAttributes.add('uv', 'float64', 2);
    for (let h = 0; h < mesh.halfedgeSlots; h++) uv.data.set([h, -h], 2 * h);
    const cornerValues = [...faceHalfedges(mesh, 1)].map((h) => [...mesh.halfedgeAttributes.get('uv')!.data.subarray(2 * h, 2 * h + 2)]);
    const oldCorners = cornersOf(mesh, 1);
    const seams = seamEdges(mesh);
    checkedEdit(mesh, (m) => extrudeFace(m, 1, { inset: 0.1 }));
    const data = mesh.halfedgeAttributes.get('uv')!.data;
    expect([...faceHalfedges(mesh, 1)].map((h) => [...data.subarray(2 * h, 2 * h + 2)])).toEqual(cornerValues);
    expect(cornersOf(mesh, 1).map((v) => mesh.vertexAttributes.get('heat')!.data[v])).toEqual(oldCorners.map((v) => v));
    expect([...mesh.faces()].map((f) => mesh.faceAttributes.get('material')!.data[f])).toEqual([0, 9, 0, 0, 0, 0, 9, 9, 9, 9]);
    expect(seamEdges(mesh)).toEqual(seams);
  });

  it('refuses an inset outside 0 … 1, an offset that is not finite, a deleted face, and leaves the mesh as it was', () => {
    const mesh = meshOf(cube());
    const why = 'inset = 1.5 is not between 0 and 1: it is the fraction of the way the corners of f2 move toward its centroid';
    expect(canExtrudeFace(mesh, 2, { inset: 1.5 })).toBe(why);
    expectRefused(mesh, () => extrudeFace(mesh, 2, { inset: 1.5 }), `extrudeFace: ${why}`);
    expect(canExtrudeFace(mesh, 2, { inset: -0.1 })).toMatch(/^inset = -0.1 is not between 0 and 1/);
    expect(canExtrudeFace(mesh, 2, { inset: Number.NaN })).toMatch(/^inset = NaN is not between 0 and 1/);
    expect(canExtrudeFace(mesh, 2, { offset: Infinity })).toBe('offset = Infinity is not a finite number: f2 cannot move that far');
    expect(canExtrudeFace(mesh, 6)).toBe('f6 is not a face of this mesh (ids run 0…5)');
    expect(canExtrudeFace(mesh, 2, { inset: 1, offset: -2 })).toBeNull();
    mesh.deleteFace(3);
    expect(canExtrudeFace(mesh, 3)).toBe('f3 is deleted');
  });

  it('refuses to move a face of zero area (it has no normal), but insets it', () => {
    const mesh = meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 2, 0, 0], [[0, 1, 2]]));
    const why = 'f0 has no area, so no normal to move it along: extrude it with offset 0 (inset alone works)';
    expect(canExtrudeFace(mesh, 0, { offset: 1 })).toBe(why);
    expectRefused(mesh, () => extrudeFace(mesh, 0, { offset: 1 }), `extrudeFace: ${why}`);
    checkedEdit(mesh, (m) => extrudeFace(m, 0, { inset: 0.5 }));
    expect(counts(mesh)).toEqual([6, 9, 4]);
  });

  it(`extrudes random faces of closed, open and several-part meshes, keeping them valid and χ unchanged (seed ${SEED})`, () => {
    const amount = (min: number) => fc.oneof(fc.constant(0), fc.double({ min, max: 1, noNaN: true }));
    fc.assert(
      fc.property(
        fc.nat(fixtures.length - 1),
        fc.array(fc.record({ pick: fc.nat(), offset: amount(-1), inset: amount(0) }), { minLength: 1, maxLength: 6 }),
        (which, steps) => {
          const mesh = meshOf(fixtures[which][1]());
          const chi = euler(mesh);
          for (const { pick, offset, inset } of steps) {
            const f = pick % mesh.faceSlots;
            const why = canExtrudeFace(mesh, f, { offset, inset });
            if (why) {
              expectRefused(mesh, () => extrudeFace(mesh, f, { offset, inset }), `extrudeFace: ${why}`);
              continue;
            }
            const k = mesh.faceDegree(f);
            const [before, centroid, normal] = [counts(mesh), faceCentroid(mesh, f), faceNormal(mesh, f)];
            checkedEdit(mesh, (m) => extrudeFace(m, f, { offset, inset }));
            expect(counts(mesh)).toEqual([before[0] + k, before[1] + 2 * k, before[2] + k]);
            expect(mesh.faceDegree(f)).toBe(k);
            faceCentroid(mesh, f).forEach((x, c) => expect(x).toBeCloseTo(centroid[c] + offset * normal[c], 9));
          }
          expect(euler(mesh)).toBe(chi);
        },
      ),
      { seed: SEED, numRuns: 60 },
    );
  });
});
