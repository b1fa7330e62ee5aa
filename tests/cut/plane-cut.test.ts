import { describe, expect, it } from 'vitest';
import { cutMesh, planeCut, type Plane } from '../../src/core/cut/index.js';
import { diffPointers } from '../../src/core/change/diff.js';
import { collapseEdge, splitEdge } from '../../src/core/edits/index.js';
import { InvalidInputError } from '../../src/core/errors.js';
import { signedVolume } from '../../src/core/geometry.js';
import { cube, disk, doubleTorus, grid, tetrahedron, torus, uvSphere } from '../../src/core/shapes.js';
import { mergeSoups } from '../../src/core/soup.js';
import { meshStats } from '../../src/core/stats.js';
import { expectSurvivesReload } from '../core/reload.js';
import { bowl, capDistance, halfVolumes, hollowBall, meshOf, size, steppedBlock, stepCut, uPrism } from './helpers.js';

const PHASE_NAMES = [
  'classify vertices',
  'split crossing edges',
  'split crossed faces',
  'separate the sides',
  'remove a side',
  'cap the cut',
];

describe('planeCut, phase by phase', () => {
  it('yields six named phases, each explained in two sentences, with a valid mesh after each', () => {
    const mesh = meshOf(uvSphere(8, 10));
    const phases = stepCut(mesh, [0, 0.3, 1, -0.1], { keep: 'above' });
    expect(phases.map((p) => p.name)).toEqual(PHASE_NAMES);
    for (const phase of phases) expect(phase.explanation.split(/(?<=\.) (?=[A-Z])/)).toHaveLength(2);
  });

  it('reports what each phase touched', () => {
    const mesh = meshOf(cube());
    const [classify, splitEdges, splitFaces, separate, remove, cap] = stepCut(mesh, [0, 0, 1, -0.5], { keep: 'below' });
    expect(classify.values!.vertices).toEqual(Float32Array.of(-0.5, -0.5, -0.5, -0.5, 0.5, 0.5, 0.5, 0.5));
    // the four vertical edges split: each a new vertex and a second edge, its own halfedges rewired
    expect(splitEdges.created!.vertices).toHaveLength(4);
    expect(splitEdges.created!.edges).toHaveLength(4);
    expect(new Set([...splitEdges.rewired!.halfedges!].map((h) => h >> 1)).size).toBeGreaterThanOrEqual(4);
    expect(splitFaces.rewired!.faces).toHaveLength(4);
    expect(splitFaces.created!.faces).toHaveLength(4);
    // the four edges along the cut doubled, the four vertices on it copied
    expect(separate.created!.edges).toHaveLength(4);
    expect(separate.rewired!.vertices!.length).toBeGreaterThanOrEqual(4);
    expect(separate.created!.vertices).toHaveLength(4);
    expect(remove.removed!.faces).toHaveLength(5);
    expect(cap.created!.faces).toHaveLength(2);
  });

  it('cuts a cube in half: closed halves of volume 1/2 with square caps', () => {
    const mesh = meshOf(cube());
    stepCut(mesh, [0, 0, 1, -0.5]);
    const stats = meshStats(mesh);
    expect([stats.components, stats.closed, stats.faces]).toEqual([2, true, 14]);
    expect(stats.componentDetails.map((c) => c.genus)).toEqual([0, 0]);
    expect(signedVolume(mesh)).toBeCloseTo(1, 14);
  });

  it('gives the same mesh run in one go as stepped', () => {
    const stepped = meshOf(torus(12, 8));
    const oneGo = stepped.clone();
    stepCut(stepped, [0.2, 0.1, 1, 0.05], { keep: 'below' });
    const phases = cutMesh(oneGo, [0.2, 0.1, 1, 0.05], { keep: 'below' });
    expect(phases.map((p) => p.name)).toEqual(PHASE_NAMES);
    expect(diffPointers(stepped, oneGo).total).toBe(0);
    expect(oneGo.positions).toEqual(stepped.positions);
  });

  it('blends vertex attributes at the new vertices', () => {
    const mesh = meshOf(uvSphere(8, 10));
    const height = mesh.vertexAttributes.add('height', 'float64', 1);
    for (const v of mesh.vertices()) height.data[v] = mesh.position(v)[2];
    stepCut(mesh, [0.4, 0, 1, -0.2]);
    for (const v of mesh.vertices()) expect(height.data[v]).toBeCloseTo(mesh.position(v)[2], 12);
  });

  it('refuses a plane with no direction, or an unknown side, before any phase runs', () => {
    const mesh = meshOf(cube());
    expect(() => planeCut(mesh, [0, 0, 0, 1])).toThrow(InvalidInputError);
    expect(() => planeCut(mesh, { a: 0, b: NaN, c: 1, d: 0 })).toThrow('four finite numbers');
    expect(() => planeCut(mesh, [0, 0, 1, 0], { keep: 'left' as 'above' })).toThrow("keep must be 'above', 'below' or 'both'");
  });
});

describe('planeCut on closed meshes', () => {
  const cases: Array<[string, () => ReturnType<typeof meshOf>, Plane]> = [
    ['a sphere, off-centre and tilted', () => meshOf(uvSphere(10, 14)), [0.3, -0.2, 1, -0.13]],
    ['a sphere, through its equator vertices', () => meshOf(uvSphere(10, 14)), [0, 0, 1, 0]],
    ['a torus, across its tube', () => meshOf(torus(16, 10)), [1, 0, 0, -0.07]],
    ['a torus, through its hole along vertex rows', () => meshOf(torus(16, 10)), [0, 0, 1, 0]],
    ['a tetrahedron, along one of its edges', () => meshOf(tetrahedron()), [0, 1, -1, 0]],
    ['a cube, diagonally through two vertical edges', () => meshOf(cube()), [1, -1, 0, 0]],
    ['a hollow ball', () => meshOf(hollowBall()), [0, 0, 1, -0.1]],
    ['a voxel double torus, along lattice planes', () => meshOf(doubleTorus()), [1, 0, 0, -2]],
    ['a stepped voxel block, along the step', () => meshOf(steppedBlock()), [0, 0, 1, -1]],
    ['a U-shaped prism, across both arms', () => meshOf(uPrism()), [0, 1, 0, -2]],
  ];
  for (const [name, make, plane] of cases) {
    it(`cuts ${name} into closed capped halves whose volumes add up`, () => {
      const mesh = make();
      const volume = signedVolume(mesh);
      const [above, below] = halfVolumes(mesh, plane);
      expect(Math.abs(above + below - volume) / volume).toBeLessThan(1e-9);
      expect(above).toBeGreaterThan(0);
      expect(below).toBeGreaterThan(0);
      const both = mesh.clone();
      const phases = stepCut(both, plane);
      expect(meshStats(both).closed).toBe(true);
      expect(capDistance(both, phases, plane)).toBeLessThan(1e-12 * size(mesh));
    });
  }

  it('caps a torus cut through its hole with two discs per side', () => {
    const mesh = meshOf(torus(16, 10));
    const open = mesh.clone();
    stepCut(open, [1, 0, 0, -0.07], { keep: 'above', cap: false });
    expect(meshStats(open).boundaryLoops).toBe(2);
    const phases = stepCut(mesh, [1, 0, 0, -0.07], { keep: 'above' });
    const loopLength = meshStats(open).boundaryEdges;
    // two discs of n1 and n2 corners: (n1 − 2) + (n2 − 2) triangles
    expect(phases[5].created!.faces).toHaveLength(loopLength - 4);
    expect(meshStats(mesh)).toMatchObject({ closed: true, components: 1, genus: 0 });
  });

  it('caps a hollow ball with a ring: one cap with a hole, per side', () => {
    const mesh = meshOf(hollowBall());
    const open = mesh.clone();
    stepCut(open, [0, 0, 1, -0.1], { keep: 'below', cap: false });
    const loopLength = meshStats(open).boundaryEdges;
    const phases = stepCut(mesh, [0, 0, 1, -0.1], { keep: 'below' });
    // a polygon of n corners with one hole: n + 2 − 2 triangles
    expect(phases[5].created!.faces).toHaveLength(loopLength);
    expect(meshStats(mesh)).toMatchObject({ closed: true, components: 1, genus: 0 });
  });

  it('splits each U face crossed twice into three, keeping the two arms above', () => {
    const mesh = meshOf(uPrism());
    const phases = stepCut(mesh, [0, 1, 0, -2], { keep: 'above' });
    expect(phases[2].rewired!.faces).toHaveLength(6); // the two U faces and four side quads
    const stats = meshStats(mesh);
    expect([stats.components, stats.closed]).toEqual([2, true]);
    expect(signedVolume(mesh)).toBeCloseTo(2, 12);
  });

  it('cuts through a voxel step, where faces lie in the plane: they stay with the side behind them', () => {
    const mesh = meshOf(steppedBlock());
    stepCut(mesh, [0, 0, 1, -1], { keep: 'above' });
    expect(signedVolume(mesh)).toBeCloseTo(1, 12);
    expect(meshStats(mesh).closed).toBe(true);
    const cubeMesh = meshOf(cube());
    stepCut(cubeMesh, [0, 0, 1, 0], { keep: 'above' });
    expect([cubeMesh.nFaces, signedVolume(cubeMesh)]).toEqual([6, 1]);
  });
});

describe('planeCut through a saddle, where the section touches itself at a vertex', () => {
  // the plane x + y + z = 3 passes through the corner (1, 1, 1) where the top voxel sits on the slab
  const plane: Plane = [1, 1, 1, -3];

  it('joins the copies of that vertex where the cap closes them into one fan (the side below)', () => {
    const mesh = meshOf(steppedBlock());
    const [, , , separate, , cap] = stepCut(mesh, plane, { keep: 'below' });
    expect(separate.created!.vertices!.length).toBeGreaterThan(0);
    expect(cap.removed!.vertices).toHaveLength(1);
    expect(meshStats(mesh).closed).toBe(true);
  });

  it('keeps them apart where the cap leaves two fans (the side above)', () => {
    const mesh = meshOf(steppedBlock());
    const [, , , , , cap] = stepCut(mesh, plane, { keep: 'above' });
    expect(cap.removed?.vertices).toBeUndefined();
    expect(meshStats(mesh).closed).toBe(true);
  });

  it('gives halves whose volumes add up', () => {
    const [above, below] = halfVolumes(meshOf(steppedBlock()), plane);
    expect(above + below).toBeCloseTo(5, 12);
  });
});

describe('planeCut along a face that lies within the tolerance of the plane', () => {
  it('closes the outline that rounding makes cross itself with a fan, keeping the volume', () => {
    // tilted by 1e-10 against the U's inner wall x = 1: some of its corners snap, some do not
    const plane: Plane = [1, 2.1794495837686634e-10, 4.358898797462985e-10, -(1 + 3 * 2.1794495837686634e-10)];
    const mesh = meshOf(uPrism());
    const phases = stepCut(mesh, plane);
    expect(phases[5].explanation).toMatch(/2 caps of 8 triangles \(2 are a fan from one corner, as their outlines cross themselves/);
    expect(meshStats(mesh).closed).toBe(true);
    const [above, below] = halfVolumes(meshOf(uPrism()), plane);
    expect(above + below).toBeCloseTo(7, 12);
  });
});

describe('planeCut on open meshes', () => {
  it('cuts a disk across into two open pieces (nothing to cap)', () => {
    const mesh = meshOf(disk(4));
    const phases = stepCut(mesh, [1, 0.2, 0, -0.3]);
    const stats = meshStats(mesh);
    expect([stats.components, stats.boundaryLoops, stats.faces > 96]).toEqual([2, 2, true]);
    expect(phases[5].created?.faces).toBeUndefined();
    expect(phases[5].explanation).toMatch(/2 loops stay open: .* as it runs along the boundary the mesh already had/);
  });

  it('cuts a grid along a row of its vertices without splitting any edge', () => {
    const mesh = meshOf(grid(4, 4));
    const phases = stepCut(mesh, [0, 1, 0, -0.5]);
    expect(phases[1].created?.vertices).toBeUndefined();
    const stats = meshStats(mesh);
    expect([stats.components, stats.faces, stats.vertices]).toEqual([2, 32, 30]);
    expect(stats.componentDetails.map((c) => c.faces)).toEqual([16, 16]);
  });

  it('cuts a grid along its diagonal edges, and just beside them', () => {
    const along = meshOf(grid(4, 4));
    stepCut(along, [1, -1, 0, 0]);
    expect(meshStats(along).componentDetails.map((c) => c.faces).sort()).toEqual([16, 16]);
    const beside = meshOf(grid(4, 4));
    stepCut(beside, [1, -1, 0, -0.1], { keep: 'below' });
    expect(meshStats(beside).components).toBe(1);
  });

  it('cuts an open bowl through its rim', () => {
    const mesh = meshOf(bowl());
    stepCut(mesh, [1, 0, 0, -0.1]);
    const stats = meshStats(mesh);
    expect([stats.components, stats.boundaryLoops]).toEqual([2, 2]);
  });

  it('cuts an open bowl parallel to its rim, capping the pure cut loop of the piece below', () => {
    const mesh = meshOf(bowl());
    stepCut(mesh, [0, 0, 1, 0.5], { keep: 'below' });
    expect(meshStats(mesh).closed).toBe(true);
  });
});

describe('planeCut on a mesh with deleted elements', () => {
  it('skips the deleted slots and leaves their ids alone', () => {
    const mesh = meshOf(mergeSoups([cube(), uvSphere(8, 10)]));
    // delete the cube (its 8 vertices, 12 edges and 6 faces come first)
    for (let f = 0; f < 6; f++) mesh.deleteFace(f);
    for (let e = 0; e < 12; e++) mesh.deleteEdge(e);
    for (let v = 0; v < 8; v++) mesh.deleteVertex(v);
    const volume = signedVolume(mesh);
    stepCut(mesh, [0.2, 0, 1, -0.3]);
    expect(meshStats(mesh)).toMatchObject({ closed: true, components: 2 });
    expect(signedVolume(mesh)).toBeCloseTo(volume, 12);
    expect(mesh.isVertexDeleted(0) && mesh.isFaceDeleted(5)).toBe(true);
  });
});

describe('planes that miss the mesh', () => {
  it('leave the mesh as it was when both sides are kept, saying so', () => {
    const mesh = meshOf(uvSphere(8, 10));
    const before = mesh.clone();
    const phases = stepCut(mesh, [0, 0, 1, -5]);
    expect(phases[0].explanation).toMatch(/the plane does not cross the mesh/);
    expect(diffPointers(before, mesh).total).toBe(0);
    expect(mesh.positions).toEqual(before.positions);
    expect(mesh.nFaces).toBe(before.nFaces);
  });

  it('leave nothing when the empty side is kept, and everything when the full one is', () => {
    const empty = meshOf(uvSphere(8, 10));
    stepCut(empty, [0, 0, 1, -5], { keep: 'above' });
    expect([empty.nVertices, empty.nEdges, empty.nFaces]).toEqual([0, 0, 0]);
    const full = meshOf(uvSphere(8, 10));
    stepCut(full, [0, 0, 1, -5], { keep: 'below' });
    expect(full.nFaces).toBe(meshOf(uvSphere(8, 10)).nFaces);
  });

  it('only touch a mesh at a vertex without cutting it', () => {
    const mesh = meshOf(tetrahedron());
    const phases = stepCut(mesh, [1, 1, 1, -3]);
    expect(phases[0].explanation).toMatch(/3 below and 1 on it/);
    expect(phases[0].explanation).toMatch(/the plane does not cross the mesh/);
    expect([mesh.nVertices, mesh.nFaces, meshStats(mesh).closed]).toEqual([4, 4, true]);
  });
});

// on a coarse mesh two corners the cut must join are often joined already, round the other way:
// a second edge between them is what no file can hold
describe('planeCut on coarse meshes, between vertices already joined', () => {
  it('caps a torus of 4 × 3 quads without a second edge between two vertices', () => {
    // the plane y = 0.825 meets the torus's top rings at vertices already joined round the ring
    const mesh = meshOf(torus(4, 3));
    stepCut(mesh, [0, 0.001, 0, -0.000825], { keep: 'below' });
    expect(meshStats(mesh).boundaryLoops).toBe(0);
    expectSurvivesReload(mesh);
  });

  it('splits a face between two corners on the plane that an edge already joins', () => {
    // a tetrahedron with one edge split (a quad among its faces) and another collapsed
    const mesh = meshOf(tetrahedron());
    splitEdge(mesh, 2);
    collapseEdge(mesh, 1);
    stepCut(mesh, [0, 0.001, 0, 0], { keep: 'above', cap: false });
    expectSurvivesReload(mesh);
  });
});
