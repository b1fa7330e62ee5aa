import { describe, expect, it } from 'vitest';
import { decimate } from '../../src/core/decimation/index.js';
import { InvalidInputError, TopologyError } from '../../src/core/errors.js';
import { signedVolume, vertexNormals } from '../../src/core/geometry.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { cube, disk, grid, torus, uvSphere } from '../../src/core/shapes.js';
import {
  cannotSmooth,
  smooth,
  type SmoothingMethod,
  smoothingMethods,
  type SmoothingOptions,
} from '../../src/core/smoothing/index.js';
import { addNoise, connectivity, largestMove, meshOf, stepSmoothing } from './helpers.js';

const SEED = 20240611;
const boundaryRules = ['fixed', 'smooth'] as const;
/** Every method with every boundary rule. */
const everyCombination = smoothingMethods.flatMap((method) => boundaryRules.map((boundary) => [method, boundary] as const));

/** A uv sphere of radius 1 with seeded noise of ±2% on every coordinate. */
function noisySphere(): HalfedgeMesh {
  const mesh = meshOf(uvSphere(24, 48));
  addNoise(mesh, SEED, 0.02);
  return mesh;
}

/** Standard deviation of the distances to the origin: how far a sphere is from round. */
function roughness(mesh: HalfedgeMesh): number {
  const p = mesh.positions;
  const radii = Array.from({ length: mesh.vertexSlots }, (_, v) => Math.hypot(p[3 * v], p[3 * v + 1], p[3 * v + 2]));
  const mean = radii.reduce((sum, r) => sum + r, 0) / radii.length;
  return Math.sqrt(radii.reduce((sum, r) => sum + (r - mean) ** 2, 0) / radii.length);
}

function isBoundary(mesh: HalfedgeMesh): (v: number) => boolean {
  return (v) => mesh.isBoundaryVertex(v);
}

describe('smoothing keeps the mesh', () => {
  it.each(everyCombination)('%s with a %s boundary: valid after every phase, connectivity untouched', (method, boundary) => {
    const mesh = meshOf(disk(4));
    addNoise(mesh, SEED, 0.05);
    const before = connectivity(mesh);
    const phases = stepSmoothing(mesh, { method, boundary, iterations: 3 });
    expect(phases).toHaveLength(method === 'taubin' ? 6 : 3);
    expect(connectivity(mesh)).toEqual(before);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual([61, 156, 96]);
  });

  it('names its phases: one per iteration, or shrink and inflate for Taubin', () => {
    const names = (method: SmoothingMethod) => stepSmoothing(meshOf(disk(2)), { method, iterations: 2 }).map((p) => p.name);
    expect(names('laplacian')).toEqual(['uniform step 1 of 2', 'uniform step 2 of 2']);
    expect(names('cotan')).toEqual(['cotangent step 1 of 2', 'cotangent step 2 of 2']);
    expect(names('taubin')).toEqual(['shrink 1 of 2 (λ = 0.5)', 'inflate 1 of 2 (μ = -0.53)', 'shrink 2 of 2 (λ = 0.5)', 'inflate 2 of 2 (μ = -0.53)']);
  });

  it('lists the vertices it may move and how far each one moved', () => {
    const mesh = meshOf(disk(3));
    addNoise(mesh, SEED, 0.05);
    const before = mesh.positions.slice();
    const [phase] = stepSmoothing(mesh, { method: 'laplacian', iterations: 1 });
    const interior = [...mesh.vertices()].filter((v) => !mesh.isBoundaryVertex(v));
    expect(Array.from(phase.moved!.vertices!)).toEqual(interior);
    const distances = phase.values!.vertices!;
    expect(distances).toHaveLength(mesh.vertexSlots);
    for (const v of mesh.vertices()) {
      const moved = Math.hypot(...[0, 1, 2].map((k) => mesh.positions[3 * v + k] - before[3 * v + k]));
      expect(distances[v]).toBeCloseTo(moved, 6);
      if (mesh.isBoundaryVertex(v)) expect(distances[v]).toBe(0);
    }
  });

  it('skips the deleted slots of a mesh that has not been compacted', () => {
    for (const method of smoothingMethods) {
      const mesh = noisySphere();
      decimate(mesh, { targetFaces: 800 });
      const live = mesh.clone();
      live.compact();
      stepSmoothing(mesh, { method, iterations: 3 });
      smooth(live, { method, iterations: 3 });
      const positions = [...mesh.vertices()].flatMap((v) => mesh.position(v));
      expect(positions).toEqual(Array.from(live.positions.subarray(0, 3 * live.nVertices)));
    }
  });

  it('runs straight through to the same positions as stepping', () => {
    for (const method of smoothingMethods) {
      const stepped = noisySphere();
      const straight = noisySphere();
      stepSmoothing(stepped, { method, iterations: 4 });
      smooth(straight, { method, iterations: 4 });
      expect(straight.positions).toEqual(stepped.positions);
    }
  });
});

describe('Taubin smoothing', () => {
  it(`keeps the volume of a noisy sphere far better than the uniform Laplacian (seed ${SEED})`, () => {
    const volume = signedVolume(meshOf(uvSphere(24, 48)));
    const change = (method: SmoothingMethod) => {
      const mesh = noisySphere();
      smooth(mesh, { method, iterations: 10 });
      return { volume: Math.abs(signedVolume(mesh) - volume) / volume, roughness: roughness(mesh) };
    };
    const noisy = roughness(noisySphere());
    const laplacian = change('laplacian');
    const taubin = change('taubin');
    // both smooth the noise away…
    expect(laplacian.roughness).toBeLessThan(noisy);
    expect(taubin.roughness).toBeLessThan(noisy / 2);
    // …but the Laplacian loses more than a tenth of the volume, Taubin less than 2% of it
    expect(laplacian.volume).toBeGreaterThan(0.1);
    expect(taubin.volume).toBeLessThan(0.02);
    expect(taubin.volume).toBeLessThan(laplacian.volume / 10);
  });

  it('applies λ and μ as given', () => {
    const mesh = meshOf(disk(2));
    addNoise(mesh, SEED, 0.1, 3, (v) => !mesh.isBoundaryVertex(v));
    const once = mesh.clone();
    smooth(once, { method: 'laplacian', iterations: 1, lambda: 0.3 });
    smooth(once, { method: 'laplacian', iterations: 1, lambda: -0.4 });
    smooth(mesh, { method: 'taubin', iterations: 1, lambda: 0.3, mu: -0.4 });
    expect(mesh.positions).toEqual(once.positions);
  });
});

describe('planar meshes stay planar', () => {
  const fixtures: Array<[string, () => HalfedgeMesh]> = [
    ['a disk of triangles', () => meshOf(disk(5))],
    ['a grid of triangles', () => meshOf(grid(7, 5))],
    ['a grid of quads', () => meshOf(grid(7, 5, true))],
  ];
  describe.each(fixtures)('%s in z = 0', (_, make) => {
    it.each(everyCombination)('under %s smoothing with a %s boundary', (method, boundary) => {
      const mesh = make();
      addNoise(mesh, SEED, 0.02, 2); // shake x and y only
      const options: SmoothingOptions = { method, boundary, iterations: 5 };
      if (cannotSmooth(mesh, options)) return; // cotangent weights on quads: refused, tested below
      const before = mesh.positions.slice();
      smooth(mesh, options);
      expect(largestMove(before, mesh.positions)).toBeGreaterThan(0);
      let largestZ = 0;
      for (const v of mesh.vertices()) largestZ = Math.max(largestZ, Math.abs(mesh.positions[3 * v + 2]));
      expect(largestZ).toBe(0);
    });
  });
});

describe('a regular grid with a fixed boundary is already smooth', () => {
  it.each([
    ['laplacian', 'triangles', false],
    ['taubin', 'triangles', false],
    ['cotan', 'triangles', false],
    ['laplacian', 'quads', true],
    ['taubin', 'quads', true],
  ] as const)('%s smoothing of %s: every interior vertex is the mean of its neighbours, so nothing moves', (method, _, quads) => {
    const mesh = meshOf(grid(8, 6, quads));
    const before = mesh.positions.slice();
    smooth(mesh, { method, iterations: 5 });
    expect(largestMove(before, mesh.positions)).toBeLessThan(1e-12);
  });

  it('but its rim moves when the boundary is smoothed: the corners are cut', () => {
    const mesh = meshOf(grid(4, 4, true));
    smooth(mesh, { method: 'laplacian', iterations: 1, boundary: 'smooth' });
    // corner (0, 0) moves halfway towards the mean of (1/4, 0) and (0, 1/4)
    expect(mesh.position(0)).toEqual([1 / 16, 1 / 16, 0]);
    // a vertex on a straight side is already the mean of its two boundary neighbours
    expect(mesh.position(1)).toEqual([1 / 4, 0, 0]);
  });
});

describe('nothing moves when λ = μ = 0', () => {
  it.each(everyCombination)('%s with a %s boundary', (method, boundary) => {
    const mesh = meshOf(disk(4));
    addNoise(mesh, SEED, 0.1);
    const before = mesh.positions.slice();
    const phases = stepSmoothing(mesh, { method, boundary, iterations: 3, lambda: 0, mu: 0 });
    expect(mesh.positions).toEqual(before);
    for (const phase of phases) expect(Math.max(...phase.values!.vertices!)).toBe(0);
  });
});

describe('the boundary', () => {
  it('stays exactly where it was when fixed', () => {
    const mesh = meshOf(disk(4));
    addNoise(mesh, SEED, 0.05);
    const before = mesh.positions.slice();
    smooth(mesh, { method: 'taubin', iterations: 5 });
    for (const v of mesh.vertices()) {
      if (mesh.isBoundaryVertex(v)) expect(mesh.position(v)).toEqual(Array.from(before.subarray(3 * v, 3 * v + 3)));
    }
  });

  it('moves towards the mean of its two boundary neighbours when smoothed, not into the surface', () => {
    const mesh = meshOf(disk(4));
    addNoise(mesh, SEED, 0.05, 3, isBoundary(mesh));
    const before = mesh.clone();
    smooth(mesh, { method: 'cotan', iterations: 1, lambda: 0.5, boundary: 'smooth' });
    for (const v of mesh.vertices()) {
      if (!mesh.isBoundaryVertex(v)) continue;
      const h = before.vHalfedge[v];
      const [a, b] = [before.target(h), before.origin(before.prev(h))];
      const expected = [0, 1, 2].map((k) => {
        const p = before.positions;
        return p[3 * v + k] + 0.5 * ((p[3 * a + k] + p[3 * b + k]) / 2 - p[3 * v + k]);
      });
      mesh.position(v).forEach((x, k) => expect(x).toBeCloseTo(expected[k], 14));
    }
  });

  it('shrinks a round rim under the Laplacian and keeps it round', () => {
    const mesh = meshOf(disk(4));
    smooth(mesh, { method: 'laplacian', iterations: 10, boundary: 'smooth' });
    const radii = [...mesh.vertices()].filter(isBoundary(mesh)).map((v) => Math.hypot(...mesh.position(v)));
    expect(Math.max(...radii)).toBeLessThan(1);
    expect(Math.max(...radii) - Math.min(...radii)).toBeLessThan(1e-12);
  });
});

describe('cotangent weights', () => {
  it('move the vertices of a sphere along its normal, where uniform weights also slide them over it', () => {
    // a uv sphere's triangles shrink towards the poles: the plain average of a vertex's
    // neighbours lies off to the side, the cotangent-weighted one straight below it
    const tangentialShare = (method: SmoothingMethod) => {
      const mesh = meshOf(uvSphere(16, 24));
      const before = mesh.positions.slice();
      const normals = vertexNormals(mesh);
      smooth(mesh, { method, iterations: 1, lambda: 0.5 });
      let tangential = 0;
      let total = 0;
      for (let i = 0; i < before.length; i += 3) {
        const d = [0, 1, 2].map((k) => mesh.positions[i + k] - before[i + k]);
        const along = d[0] * normals[i] + d[1] * normals[i + 1] + d[2] * normals[i + 2];
        total += Math.hypot(...d);
        tangential += Math.sqrt(Math.max(0, d[0] ** 2 + d[1] ** 2 + d[2] ** 2 - along ** 2));
      }
      return tangential / total;
    };
    expect(tangentialShare('laplacian')).toBeGreaterThan(0.2);
    expect(tangentialShare('cotan')).toBeLessThan(0.05);
  });

  it('are refused on polygons other than triangles, with the reason', () => {
    const mesh = meshOf(cube());
    const before = mesh.positions.slice();
    const reason = 'cotangent smoothing needs triangles; f0 is a quad. Use the uniform Laplacian or Taubin, or triangulate the mesh first.';
    expect(cannotSmooth(mesh, { method: 'cotan' })).toBe(reason);
    expect(() => smooth(mesh, { method: 'cotan' })).toThrow(new TopologyError(reason));
    expect(mesh.positions).toEqual(before);
    expect(cannotSmooth(mesh, { method: 'laplacian' })).toBeNull();
    expect(cannotSmooth(meshOf(torus(6, 4)), { method: 'taubin' })).toBeNull();
  });
});

describe('bad options', () => {
  it.each([
    [{ method: 'bilaplacian' }, "unknown smoothing method 'bilaplacian': use laplacian, cotan, taubin"],
    [{ method: 'laplacian', iterations: -1 }, 'iterations must be a whole number ≥ 0, not -1'],
    [{ method: 'laplacian', iterations: 2.5 }, 'not 2.5'],
    [{ method: 'taubin', lambda: Number.NaN }, 'lambda must be a finite number, not NaN'],
    [{ method: 'taubin', mu: Infinity }, 'mu must be a finite number, not Infinity'],
    [{ method: 'cotan', boundary: 'free' }, "boundary must be 'fixed' or 'smooth', not 'free'"],
  ])('%j is refused with an InvalidInputError', (options, message) => {
    const mesh = meshOf(disk(2));
    expect(() => smooth(mesh, options as SmoothingOptions)).toThrow(InvalidInputError);
    expect(() => cannotSmooth(mesh, options as SmoothingOptions)).toThrow(message);
  });

  it('does nothing for zero iterations', () => {
    const mesh = noisySphere();
    const before = mesh.positions.slice();
    expect(stepSmoothing(mesh, { method: 'taubin', iterations: 0 })).toEqual([]);
    expect(mesh.positions).toEqual(before);
  });
});
