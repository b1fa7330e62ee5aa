/**
 * Isotropic remeshing: valid after every phase, the topology kept (closed stays closed, the genus,
 * χ and the boundary loops), the rim kept, the vertices on the input surface, and most edges within
 * 4/5 … 4/3 of the target where few were before; the same mesh stepped as straight through.
 */
import { describe, expect, it } from 'vitest';
import {
  buildMesh,
  cube,
  grid,
  type HalfedgeMesh,
  InvalidInputError,
  meshStats,
  type PolygonSoup,
  seededRandom,
  soupFromArrays,
  spatialOrder,
  TopologyError,
  torus,
  uvSphere,
  validate,
} from '../../src/index.js';
import { cannotRemesh, meanEdgeLength, remesh, remeshing, type RemeshingOptions } from '../../src/core/remeshing/index.js';
import { type Phase, phaseElements } from '../../src/core/change/operation.js';
import { meshContents } from '../core/contents.js';
import { vertexToSurfaceDistance } from '../decimation/helpers.js';
import { triangulate } from '../subdivision/helpers.js';

const SEED = 20260042;

/** An icosahedron split `levels` times, on the unit sphere, each vertex then moved by up to `noise` (seeded). */
function icosphere(levels: number, noise = 0): PolygonSoup {
  const t = (1 + Math.sqrt(5)) / 2;
  const positions = [-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1];
  let faces = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
  ];
  for (let level = 0; level < levels; level++) {
    const midpoints = new Map<string, number>();
    const midpoint = (a: number, b: number) => {
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      if (!midpoints.has(key)) {
        midpoints.set(key, positions.length / 3);
        for (let k = 0; k < 3; k++) positions.push((positions[3 * a + k] + positions[3 * b + k]) / 2);
      }
      return midpoints.get(key)!;
    };
    faces = faces.flatMap(([a, b, c]) => {
      const [ab, bc, ca] = [midpoint(a, b), midpoint(b, c), midpoint(c, a)];
      return [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]];
    });
  }
  const random = seededRandom(SEED);
  for (let v = 0; v < positions.length; v += 3) {
    const length = Math.hypot(positions[v], positions[v + 1], positions[v + 2]);
    for (let k = 0; k < 3; k++) positions[v + k] = positions[v + k] / length + noise * (2 * random() - 1);
  }
  return soupFromArrays(positions, faces);
}

/**
 * A 12 × 12 grid of triangles on the unit square, bent into a wave (z = 0.15 sin 2πx) with its
 * inside vertices moved by up to a third of a cell along x and y (seeded): open, one rim of four
 * straight sides, triangles of many shapes.
 */
function wavyGrid(): HalfedgeMesh {
  const n = 12;
  const mesh = meshOf(grid(n, n));
  const random = seededRandom(SEED);
  const p = mesh.positions;
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (!mesh.isBoundaryVertex(v)) for (let k = 0; k < 2; k++) p[3 * v + k] += ((2 * random() - 1) / 3) * (1 / n);
    p[3 * v + 2] = 0.15 * Math.sin(2 * Math.PI * p[3 * v]);
  }
  return mesh;
}

function meshOf(soup: PolygonSoup): HalfedgeMesh {
  return buildMesh(soup).mesh;
}

/** The share of the live edges whose length is within 4/5 … 4/3 of `target`. */
function shareWithin(mesh: HalfedgeMesh, target: number): number {
  const p = mesh.positions;
  let within = 0;
  for (const e of mesh.edges()) {
    const a = 3 * mesh.heVertex[2 * e];
    const b = 3 * mesh.heVertex[2 * e + 1];
    const length = Math.hypot(p[a] - p[b], p[a + 1] - p[b + 1], p[a + 2] - p[b + 2]);
    if (length >= 0.8 * target && length <= (4 / 3) * target) within++;
  }
  return within / mesh.nEdges;
}

function topologyOf(mesh: HalfedgeMesh) {
  const { eulerCharacteristic, genus, boundaryLoops, components, closed } = meshStats(mesh);
  return { eulerCharacteristic, genus, boundaryLoops, components, closed };
}

/** Steps through the remeshing, checking the mesh after every phase; returns the phases. */
function stepRemeshing(mesh: HalfedgeMesh, options: RemeshingOptions = {}): Phase[] {
  const phases: Phase[] = [];
  for (const phase of remeshing(mesh, options)) {
    expect(validate(mesh), `after "${phase.name}"`).toEqual([]);
    phases.push(phase);
  }
  return phases;
}

const fixtures: Array<[string, () => HalfedgeMesh, number]> = [
  // [name, mesh, the least share of edges within 4/5 … 4/3 L expected after three iterations]
  [`an icosphere with noise (seed ${SEED})`, () => meshOf(icosphere(3, 0.03)), 0.8],
  ['a latitude–longitude sphere (thin triangles at the poles)', () => meshOf(uvSphere(10, 24)), 0.8],
  ['a triangulated torus', () => meshOf(triangulate(torus(24, 10))), 0.8],
  [`an open wavy grid (seed ${SEED})`, wavyGrid, 0.75],
];

describe.each(fixtures)('remeshing %s', (_, make, least) => {
  it('leaves a valid mesh after every phase, with the topology of the input: closed or not, χ, genus, boundary loops', () => {
    const mesh = make();
    const before = topologyOf(mesh);
    const phases = stepRemeshing(mesh);
    expect(phases).toHaveLength(12);
    expect(topologyOf(mesh)).toEqual(before);
  });

  it(`brings most edges within 4/5 … 4/3 of the target (over ${least} of them, from fewer before)`, () => {
    const mesh = make();
    const target = meanEdgeLength(mesh);
    const before = shareWithin(mesh, target);
    remesh(mesh);
    expect(validate(mesh)).toEqual([]);
    expect(shareWithin(mesh, target)).toBeGreaterThan(least);
    expect(shareWithin(mesh, target)).toBeGreaterThan(before);
  });

  it('keeps every vertex on the input surface', () => {
    const input = make();
    const mesh = input.clone();
    remesh(mesh);
    expect(vertexToSurfaceDistance(mesh, input)).toBeLessThan(1e-9);
  });

  it('gives the same mesh stepped phase by phase as straight through (which renumbers it first and compacts it after)', () => {
    const stepped = make();
    const straight = stepped.clone();
    spatialOrder(stepped);
    stepRemeshing(stepped, { iterations: 2 });
    stepped.compact();
    remesh(straight, { iterations: 2 });
    expect(meshContents(stepped)).toEqual(meshContents(straight));
  });
});

describe('remeshing an open mesh', () => {
  it('keeps the rim on the input rim, and its four corners where they were', () => {
    const mesh = wavyGrid();
    const corners = [0, 12, 12 * 13, 13 * 13 - 1].map((v) => Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)));
    remesh(mesh);
    const rim = [...mesh.vertices()].filter((v) => mesh.isBoundaryVertex(v)).map((v) => Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)));
    for (const [x, y, z] of rim) {
      expect(Math.min(x, y, 1 - x, 1 - y), `(${x}, ${y}) is on a side of the square`).toBeCloseTo(0, 12);
      expect(z).toBeCloseTo(0.15 * Math.sin(2 * Math.PI * x), 12);
    }
    for (const corner of corners) expect(rim).toContainEqual(corner);
  });

  it('coarsens and refines: the face count follows the target length', () => {
    const coarse = wavyGrid();
    const fine = wavyGrid();
    const L = meanEdgeLength(coarse);
    remesh(coarse, { targetEdgeLength: 2 * L });
    remesh(fine, { targetEdgeLength: L / 2 });
    const faces = wavyGrid().nFaces;
    expect(coarse.nFaces).toBeLessThan(faces / 2);
    expect(fine.nFaces).toBeGreaterThan(2 * faces);
    for (const mesh of [coarse, fine]) {
      expect(validate(mesh)).toEqual([]);
      expect(topologyOf(mesh)).toEqual(topologyOf(wavyGrid()));
    }
  });
});

describe('the phases of remeshing', () => {
  it('are four per iteration, named, each explained in two sentences', () => {
    const phases = stepRemeshing(meshOf(icosphere(2)), { iterations: 2 });
    expect(phases.map((p) => p.name)).toEqual(
      [1, 2].flatMap((i) => [
        `split long edges (iteration ${i} of 2)`,
        `collapse short edges (iteration ${i} of 2)`,
        `flip edges towards valence 6 (iteration ${i} of 2)`,
        `smooth and project (iteration ${i} of 2)`,
      ]),
    );
    for (const phase of phases) expect(phase.explanation.match(/[.!?](\s|$)/g), phase.name).toHaveLength(2);
  });

  it('list every vertex they moved, and how far the smoothing moved each', () => {
    const mesh = wavyGrid();
    let before = mesh.clone();
    for (const step of remeshing(mesh, { iterations: 2 })) {
      const phase = { ...step, ...phaseElements(step.change!) };
      const moved = new Set(phase.moved.vertices ?? []);
      const unlisted = [...before.vertices()].filter(
        (v) => !mesh.vDeleted[v] && !moved.has(v) && [0, 1, 2].some((k) => mesh.positions[3 * v + k] !== before.positions[3 * v + k]),
      );
      expect(unlisted, phase.name).toEqual([]);
      if (phase.name.startsWith('smooth')) {
        const v = phase.moved.vertices![0];
        const distance = Math.hypot(...[0, 1, 2].map((k) => mesh.positions[3 * v + k] - before.positions[3 * v + k]));
        expect(phase.values!.vertices![v]).toBeCloseTo(distance, 6);
      }
      before = mesh.clone();
    }
  });

  it('change nothing for zero iterations', () => {
    const mesh = wavyGrid();
    const before = meshContents(mesh);
    expect(stepRemeshing(mesh, { iterations: 0 })).toEqual([]);
    expect(meshContents(mesh)).toEqual(before);
  });
});

describe('preconditions of remeshing', () => {
  it('refuses quads with the sentence saying why, before changing anything', () => {
    const mesh = meshOf(cube());
    const before = meshContents(mesh);
    const reason = 'remeshing needs triangles; f0 is a quad. Triangulate the mesh first.';
    expect(cannotRemesh(mesh)).toBe(reason);
    expect(() => remeshing(mesh)).toThrow(new TopologyError(reason));
    expect(() => remesh(mesh)).toThrow(new TopologyError(reason));
    expect(meshContents(mesh)).toEqual(before);
  });

  it('refuses a mesh without faces', () => {
    const mesh = meshOf(soupFromArrays([0, 0, 0], []));
    expect(cannotRemesh(mesh)).toBe('there are no faces to remesh');
  });

  it('rejects a target length that is not a number > 0 and iterations that are not a whole number ≥ 0', () => {
    const mesh = meshOf(icosphere(1));
    for (const options of [{ targetEdgeLength: 0 }, { targetEdgeLength: -1 }, { targetEdgeLength: NaN }, { iterations: 1.5 }, { iterations: -1 }]) {
      expect(() => cannotRemesh(mesh, options), JSON.stringify(options)).toThrow(InvalidInputError);
    }
    expect(cannotRemesh(mesh, { targetEdgeLength: 0.1, iterations: 5 })).toBeNull();
  });
});
