import { describe, expect, it } from 'vitest';
import { decimate, cannotDecimate, type DecimationOptions } from '../../src/core/decimation/index.js';
import { triangulateMesh } from '../../src/core/edits/index.js';
import { InvalidInputError, TopologyError } from '../../src/core/errors.js';
import { faceVertices } from '../../src/core/circulators.js';
import { faceNormal, signedVolume } from '../../src/core/geometry.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { annulus, cube, disk, fan, grid, strip, tetrahedron, torus, uvSphere } from '../../src/core/shapes.js';
import type { PolygonSoup } from '../../src/core/soup.js';
import { spatialOrder } from '../../src/core/spatial-order.js';
import { meshStats } from '../../src/core/stats.js';
import { validate } from '../../src/core/validate.js';
import { bunny, diagonal, meshOf, stepDecimation, vertexToSurfaceDistance } from './helpers.js';

/** The mesh of `soup` with every polygon cut into triangles. */
function triangulated(soup: PolygonSoup): HalfedgeMesh {
  const mesh = meshOf(soup);
  triangulateMesh(mesh, { record: false });
  return mesh;
}

/** Euler characteristic, genus, boundary loops and closedness. */
function topology(mesh: HalfedgeMesh) {
  const { eulerCharacteristic, genus, boundaryLoops, closed, components } = meshStats(mesh);
  return { eulerCharacteristic, genus, boundaryLoops, closed, components };
}

describe('decimation keeps the mesh valid and its topology', () => {
  it.each([
    ['a sphere', () => meshOf(uvSphere(16, 32)), 100],
    ['a torus', () => triangulated(torus(24, 12)), 120],
    ['a disk', () => meshOf(disk(8)), 80],
  ] as const)('%s: valid after every batch, same Euler characteristic and genus, at the target', (_, make, target) => {
    const mesh = make();
    const before = topology(mesh);
    const phases = stepDecimation(mesh, { targetFaces: target });
    expect(phases.length).toBeGreaterThan(2);
    expect(topology(mesh)).toEqual(before);
    expect(mesh.nFaces).toBe(target);
  });

  it('keeps a closed surface closed, down to the smallest one: a tetrahedron', () => {
    const mesh = meshOf(uvSphere(10, 16));
    stepDecimation(mesh, { targetFaces: 0 });
    expect(topology(mesh)).toEqual({ eulerCharacteristic: 2, genus: 0, boundaryLoops: 0, closed: true, components: 1 });
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual([4, 6, 4]);
  });

  it.each([
    ['a disk', () => meshOf(disk(3))],
    ['a grid', () => meshOf(grid(5, 3))],
    ['a strip', () => meshOf(strip(6))],
    ['a fan', () => meshOf(fan(7))],
    ['an annulus', () => triangulated(annulus(12))],
    ['a torus', () => triangulated(torus(10, 6))],
  ] as const)('%s: valid and of the same topology all the way down to what cannot collapse', (_, make) => {
    for (const share of [0, 0.3, 0.6]) {
      const mesh = make();
      const before = topology(mesh);
      stepDecimation(mesh, { targetFaces: Math.floor(share * mesh.nFaces), batchFraction: 0.2 });
      expect(topology(mesh)).toEqual(before);
    }
  });

  it('reaches the target exactly, or one below when the last collapse takes two triangles', () => {
    const even = meshOf(uvSphere(12, 20));
    decimate(even, { targetFaces: 150 });
    expect(even.nFaces).toBe(150);
    const odd = meshOf(uvSphere(12, 20));
    decimate(odd, { targetFaces: 151 });
    expect(odd.nFaces).toBe(150);
    // a boundary collapse takes one triangle, so an open mesh can stop at an odd count
    const open = meshOf(disk(6));
    decimate(open, { targetFaces: 101 });
    expect([100, 101]).toContain(open.nFaces);
  });

  it('halves the faces when no target is given', () => {
    const mesh = meshOf(uvSphere(12, 20));
    const faces = mesh.nFaces;
    decimate(mesh);
    expect(mesh.nFaces).toBe(faces / 2);
  });

  it('turns no triangle of a sphere inside out', () => {
    const mesh = meshOf(uvSphere(24, 48));
    decimate(mesh, { targetFaces: 200 });
    const n = [0, 0, 0];
    const centroid = [0, 0, 0];
    for (const f of mesh.faces()) {
      faceNormal(mesh, f, n);
      centroid.fill(0);
      let h = mesh.fHalfedge[f];
      for (let k = 0; k < 3; k++, h = mesh.heNext[h]) mesh.position(mesh.heVertex[h]).forEach((x, i) => (centroid[i] += x / 3));
      // every face of a convex shape around the origin faces away from it
      expect(n[0] * centroid[0] + n[1] * centroid[1] + n[2] * centroid[2]).toBeGreaterThan(0);
    }
    expect(signedVolume(mesh)).toBeGreaterThan(0.9 * signedVolume(meshOf(uvSphere(24, 48))));
  });
});

describe('the phases', () => {
  const mesh = meshOf(uvSphere(16, 32));
  const faces = mesh.nFaces;
  const phases = stepDecimation(mesh, { targetFaces: 200 });
  const [quadrics, ...batches] = phases;

  it('first compute the quadrics, with the cheapest collapse at each vertex for a colour map', () => {
    expect(quadrics.name).toBe('compute quadrics');
    expect(quadrics.removed.faces).toBeUndefined();
    const costs = quadrics.values!.vertices!;
    expect(costs).toHaveLength(meshOf(uvSphere(16, 32)).vertexSlots);
    for (const cost of costs) expect(cost).toBeGreaterThanOrEqual(0);
  });

  it('then collapse about a tenth of the faces left in each batch, down to the target', () => {
    let left = faces;
    for (const batch of batches) {
      const removed = batch.removed!.faces!.length;
      expect(batch.name).toBe(`collapse ${removed} faces (${left - removed} left)`);
      expect(removed).toBeLessThanOrEqual(Math.floor(left / 10) + 1);
      left -= removed;
    }
    expect(left).toBe(200);
    expect(batches.length).toBe(Math.ceil(Math.log(200 / faces) / Math.log(0.9)));
  });

  it('list what they removed (deleted, not compacted) and the survivors they moved', () => {
    expect(mesh.isCompact).toBe(false);
    for (const batch of batches) {
      const { removed, moved, rewired } = batch;
      for (const v of removed!.vertices!) expect(mesh.isVertexDeleted(v)).toBe(true);
      for (const e of removed!.edges!) expect(mesh.isEdgeDeleted(e)).toBe(true);
      for (const f of removed!.faces!) expect(mesh.isFaceDeleted(f)).toBe(true);
      // a collapse removes a vertex and three edges inside a closed surface, and two faces
      expect(removed!.edges!.length).toBe(3 * removed!.vertices!.length);
      expect(removed!.faces!.length).toBe(2 * removed!.vertices!.length);
      expect(moved!.vertices!.length).toBeGreaterThan(0);
      expect(rewired!.halfedges!.length).toBeGreaterThan(0);
    }
    // a later batch may take a survivor in turn, but the last batch's are all live, and every
    // halfedge it rewired that is still there lies on a face (or beside one) at a survivor
    const last = batches.at(-1)!;
    const survivors = new Set(last.moved!.vertices!);
    for (const v of survivors) expect(mesh.isVertexDeleted(v)).toBe(false);
    const atSurvivor = (f: number) => f >= 0 && [...faceVertices(mesh, f)].some((v) => survivors.has(v));
    for (const h of last.rewired!.halfedges!) {
      if (!mesh.isHalfedgeDeleted(h)) expect(atSurvivor(mesh.face(h)) || atSurvivor(mesh.face(mesh.twin(h))), `h${h}`).toBe(true);
    }
  });

  it('run straight through to the same mesh, renumbered in spatial order first, in one batch unless told', () => {
    const straight = meshOf(uvSphere(16, 32));
    const renumbering = decimate(straight, { targetFaces: 200 });
    const stepped = meshOf(uvSphere(16, 32));
    expect(spatialOrder(stepped)).toEqual(renumbering);
    expect(stepDecimation(stepped, { targetFaces: 200, batchFraction: 1 })).toHaveLength(2);
    expect([straight.heNext, straight.heVertex, straight.positions]).toEqual([stepped.heNext, stepped.heVertex, stepped.positions]);
  });

  it('take a bigger share per batch when asked', () => {
    const coarse = stepDecimation(meshOf(uvSphere(16, 32)), { targetFaces: 200, batchFraction: 0.5 });
    expect(coarse.length).toBeLessThan(phases.length);
  });
});

describe('the boundary', () => {
  it('keeps one loop, its vertices exactly on the original circle', () => {
    const mesh = meshOf(disk(8));
    const rim = new Set(
      [...mesh.vertices()].filter((v) => mesh.isBoundaryVertex(v)).map((v) => mesh.position(v).join()),
    );
    stepDecimation(mesh, { targetFaces: 60 });
    expect(topology(mesh).boundaryLoops).toBe(1);
    const boundary = [...mesh.vertices()].filter((v) => mesh.isBoundaryVertex(v));
    expect(boundary.length).toBeGreaterThan(3);
    for (const v of boundary) {
      // not just on the circle: each one is an original rim vertex, where it was
      expect(rim.has(mesh.position(v).join())).toBe(true);
      expect(Math.hypot(...mesh.position(v))).toBeCloseTo(1, 12);
    }
  });

  it('simplifies the straight sides of a flat grid first and keeps its corners', () => {
    const mesh = meshOf(grid(10, 10));
    decimate(mesh, { targetFaces: 20 });
    expect(topology(mesh)).toMatchObject({ boundaryLoops: 1, eulerCharacteristic: 1 });
    const positions = [...mesh.vertices()].map((v) => mesh.position(v));
    for (const corner of [
      [0, 0, 0],
      [1, 0, 0],
      [1, 1, 0],
      [0, 1, 0],
    ]) {
      expect(positions).toContainEqual(corner);
    }
    // everything stays in the plane, and inside the square
    for (const [x, y, z] of positions) {
      expect(z).toBe(0);
      expect(Math.min(x, y)).toBeGreaterThanOrEqual(0);
      expect(Math.max(x, y)).toBeLessThanOrEqual(1);
    }
  });
});

describe('the maximum error', () => {
  it('lets a flat grid collapse freely: inside the plane and along its straight sides, collapses cost nothing', () => {
    const mesh = meshOf(grid(12, 12));
    decimate(mesh, { maxError: 1e-9 });
    expect(validate(mesh)).toEqual([]);
    expect([mesh.nVertices, mesh.nFaces]).toEqual([4, 2]);
  });

  it('stops a curved surface early, the lower the limit the earlier', () => {
    const faces = (maxError: number) => {
      const mesh = meshOf(uvSphere(16, 32));
      decimate(mesh, { maxError });
      return mesh.nFaces;
    };
    const loose = faces(0.05);
    const tight = faces(0.005);
    expect(tight).toBeGreaterThan(loose);
    expect(loose).toBeGreaterThan(4);
    expect(tight).toBeLessThan(meshOf(uvSphere(16, 32)).nFaces);
  });

  it('and the target face count: whichever is reached first stops it', () => {
    const mesh = meshOf(uvSphere(16, 32));
    decimate(mesh, { maxError: 1, targetFaces: 300 });
    expect(mesh.nFaces).toBe(300);
  });
});

describe('the bunny at a quarter of its faces', () => {
  const original = bunny();
  const mesh = original.clone();
  decimate(mesh, { targetFaces: Math.round(original.nFaces / 4) });
  const size = diagonal(original);

  it('is a closed genus-0 surface of 918 triangles', () => {
    expect(validate(mesh)).toEqual([]);
    expect(topology(original)).toEqual(topology(mesh));
    expect(mesh.nFaces).toBe(918);
  });

  it('stays within 1% of the bounding-box diagonal of the original, both ways (at the vertices)', () => {
    expect(vertexToSurfaceDistance(original, mesh)).toBeLessThan(0.01 * size);
    expect(vertexToSurfaceDistance(mesh, original)).toBeLessThan(0.01 * size);
  });

  it('keeps its volume to within 2%', () => {
    expect(Math.abs(signedVolume(mesh) / signedVolume(original) - 1)).toBeLessThan(0.02);
  });
});

describe('what decimation needs', () => {
  it('refuses polygons other than triangles, changing nothing', () => {
    const mesh = meshOf(cube());
    const before = mesh.heNext.slice();
    const reason = 'decimation needs triangles; f0 is a quad. Triangulate the mesh first.';
    expect(cannotDecimate(mesh, {})).toBe(reason);
    expect(() => decimate(mesh, { targetFaces: 4 })).toThrow(new TopologyError(reason));
    expect(mesh.heNext).toEqual(before);
    expect(cannotDecimate(meshOf(tetrahedron()), {})).toBeNull();
  });

  it.each([
    [{ targetFaces: -1 }, 'targetFaces must be a whole number ≥ 0, not -1'],
    [{ targetFaces: 10.5 }, 'not 10.5'],
    [{ maxError: -0.1 }, 'maxError must be a number ≥ 0, not -0.1'],
    [{ maxError: Number.NaN }, 'not NaN'],
    [{ batchFraction: 0 }, 'batchFraction must be in (0, 1], not 0'],
    [{ batchFraction: 1.5 }, 'not 1.5'],
  ])('refuses %j with an InvalidInputError', (options, message) => {
    const mesh = meshOf(tetrahedron());
    expect(() => decimate(mesh, options as DecimationOptions)).toThrow(InvalidInputError);
    expect(() => cannotDecimate(mesh, options as DecimationOptions)).toThrow(message);
  });

  it('leaves a tetrahedron as it is: no edge of it can collapse', () => {
    const mesh = meshOf(tetrahedron());
    const phases = stepDecimation(mesh, { targetFaces: 2 });
    expect(phases.map((p) => p.name)).toEqual(['compute quadrics']);
    expect(mesh.nFaces).toBe(4);
  });

  it('does nothing when the mesh already has no more faces than the target', () => {
    const mesh = meshOf(uvSphere(6, 8));
    const phases = stepDecimation(mesh, { targetFaces: mesh.nFaces });
    expect(phases).toHaveLength(1);
    expect(mesh.isCompact).toBe(true);
  });
});
