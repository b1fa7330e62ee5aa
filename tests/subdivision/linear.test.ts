/**
 * Linear subdivision: Catmull-Clark's topology with plain averages. Its connectivity must be
 * exactly Catmull-Clark's (the same arrays, element for element), its points the centroids,
 * midpoints and old places, and its result valid after every phase.
 */
import { describe, expect, it } from 'vitest';
import { cube, disk, grid, type HalfedgeMesh, type PolygonSoup, torus, uvSphere, validate } from '../../src/index.js';
import { cannotSubdivide, linearSubdivision, subdivide, subdivisionOperation } from '../../src/core/subdivision/index.js';
import { runOperation } from '../../src/core/change/operation.js';
import { meshContents } from '../core/contents.js';
import { at, expectedCounts, flower, meshOf, pyramid, stepLevel, topologyOf } from './helpers.js';

const fixtures: Array<[string, () => PolygonSoup]> = [
  ['cube', cube],
  ['torus of quads', () => torus(6, 4)],
  ['pyramid (triangles and a quad)', pyramid],
  ['flower (a pentagon and quads, open)', flower],
  ['open disk of triangles', () => disk(2)],
  ['grid of quads', () => grid(3, 2, true)],
];

/** The mesh's contents without the vertex positions: its connectivity and slot counts. */
function connectivity(mesh: HalfedgeMesh): Record<string, unknown> {
  const { 'vertex:position': _, ...rest } = meshContents(mesh);
  return rest;
}

/** The corners of every face, by face, before a level. */
function cornersOf(mesh: HalfedgeMesh): number[][] {
  return [...mesh.faces()].map((f) => {
    const corners: number[] = [];
    let h = mesh.fHalfedge[f];
    do {
      corners.push(mesh.heVertex[h]);
      h = mesh.heNext[h];
    } while (h !== mesh.fHalfedge[f]);
    return corners;
  });
}

function mean(points: number[][]): number[] {
  return [0, 1, 2].map((k) => points.reduce((sum, p) => sum + p[k], 0) / points.length);
}

describe.each(fixtures)('linear subdivision of a %s', (_, soup) => {
  it('has the counts of Catmull-Clark: V + E + F vertices, 2E + C edges, C faces (C = Σ face degrees)', () => {
    const mesh = meshOf(soup());
    for (let level = 0; level < 2; level++) {
      const counts = expectedCounts(mesh, 'linear');
      stepLevel(mesh, 'linear');
      expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual(counts);
    }
    expect(validate(mesh)).toEqual([]);
  });

  it('gives exactly Catmull-Clark’s connectivity, only the points differ', () => {
    const linear = meshOf(soup());
    const catmullClark = linear.clone();
    subdivide(linear, 'linear', 2);
    subdivide(catmullClark, 'catmull-clark', 2);
    expect(connectivity(linear)).toEqual(connectivity(catmullClark));
    expect(Array.from(linear.positions.subarray(0, 3 * linear.vertexSlots))).not.toEqual(
      Array.from(catmullClark.positions.subarray(0, 3 * catmullClark.vertexSlots)),
    );
  });

  it('puts each face point at its face’s centroid and each edge point at its edge’s midpoint, and leaves the old vertices', () => {
    const mesh = meshOf(soup());
    const before = mesh.clone();
    const [V, E, F] = [mesh.vertexSlots, mesh.edgeSlots, mesh.faceSlots];
    const corners = cornersOf(before);
    subdivide(mesh, 'linear');
    for (let v = 0; v < V; v++) expect(at(mesh, v)).toEqual(at(before, v));
    corners.forEach((face, f) => {
      const centroid = mean(face.map((v) => at(before, v)));
      at(mesh, V + f).forEach((x, k) => expect(x).toBeCloseTo(centroid[k], 14));
    });
    for (let e = 0; e < E; e++) {
      const midpoint = mean([at(before, before.heVertex[2 * e]), at(before, before.heVertex[2 * e + 1])]);
      at(mesh, V + F + e).forEach((x, k) => expect(x).toBeCloseTo(midpoint[k], 14));
    }
  });

  it('keeps the Euler characteristic, genus, boundary loops and components', () => {
    const mesh = meshOf(soup());
    const before = topologyOf(mesh);
    subdivide(mesh, 'linear', 2);
    expect(topologyOf(mesh)).toEqual(before);
  });

  it('gives the same mesh stepped phase by phase as straight through', () => {
    const stepped = meshOf(soup());
    const straight = stepped.clone();
    stepLevel(stepped, 'linear');
    subdivide(straight, 'linear');
    expect(meshContents(stepped)).toEqual(meshContents(straight));
  });
});

describe('linear subdivision', () => {
  it('keeps a flat quad flat: a grid stays in its plane', () => {
    const mesh = meshOf(grid(3, 3, true));
    subdivide(mesh, 'linear', 2);
    for (const v of mesh.vertices()) expect(at(mesh, v)[2]).toBe(0);
  });

  it('moves no old vertex of a sphere, where Catmull-Clark moves them all inwards', () => {
    const mesh = meshOf(uvSphere(4, 6));
    const before = mesh.clone();
    runOperation(linearSubdivision(mesh));
    for (const v of before.vertices()) expect(at(mesh, v)).toEqual(at(before, v));
  });

  it('applies to any polygons, and is stepped in three phases', () => {
    expect(cannotSubdivide(meshOf(flower()), 'linear')).toBeNull();
    const phases = runOperation(subdivisionOperation(meshOf(cube()), 'linear'));
    expect(phases.map((p) => p.name)).toEqual(['add face points', 'split every edge at its edge point', 'connect the face points']);
  });
});
