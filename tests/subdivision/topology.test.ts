import { describe, expect, it } from 'vitest';
import {
  annulus,
  cube,
  diffPointers,
  phaseElements,
  disk,
  doubleTorus,
  fan,
  grid,
  type HalfedgeMesh,
  InvalidInputError,
  type PolygonSoup,
  singleTriangle,
  soupFromArrays,
  strip,
  tetrahedron,
  TopologyError,
  torus,
  uvSphere,
  validate,
} from '../../src/index.js';
import {
  butterflySubdivision,
  cannotSubdivide,
  loopSubdivision,
  sqrt3Subdivision,
  subdivide,
  type SubdivisionScheme,
  subdivisionOperation,
} from '../../src/core/subdivision/index.js';
import { at, expectedCounts, flower, meshArrays, meshOf, pyramid, stepLevel, topologyOf, triangulate } from './helpers.js';

const triangleFixtures: Array<[string, () => PolygonSoup]> = [
  ['tetrahedron', tetrahedron],
  ['sphere', () => uvSphere(5, 7)],
  ['triangulated torus', () => triangulate(torus(6, 4))],
  ['triangulated double torus', () => triangulate(doubleTorus())],
  ['open disk', () => disk(3)],
  ['grid', () => grid(3, 2)],
  ['strip', () => strip(3)],
  ['open fan', () => fan(4)],
  ['single triangle', singleTriangle],
];

const polygonFixtures: Array<[string, () => PolygonSoup]> = [
  ['cube', cube],
  ['torus of quads', () => torus(6, 4)],
  ['double torus', doubleTorus],
  ['pyramid (triangles and a quad)', pyramid],
  ['flower (a pentagon and quads, open)', flower],
  ['annulus (two boundary loops)', () => annulus(6)],
  ['grid of quads', () => grid(3, 2, true)],
  ...triangleFixtures,
];

const anyPolygons = (scheme: SubdivisionScheme) => scheme === 'catmull-clark' || scheme === 'linear';
const fixturesOf = (scheme: SubdivisionScheme) => (anyPolygons(scheme) ? polygonFixtures : triangleFixtures);
const schemes: SubdivisionScheme[] = ['loop', 'catmull-clark', 'butterfly', 'sqrt3', 'linear'];

const phaseNames: Record<SubdivisionScheme, string[]> = {
  loop: ['split every edge', 'cut the corners', 'place the edge points', 'move the old vertices'],
  'catmull-clark': ['add face points', 'split every edge at its edge point', 'connect the face points', 'move the old vertices'],
  butterfly: ['split every edge', 'cut the corners', 'place the edge points'],
  sqrt3: ['insert face points', 'flip the old edges', 'relax the old vertices'],
  linear: ['add face points', 'split every edge at its edge point', 'connect the face points'],
};

describe.each(schemes)('%s subdivision', (scheme) => {
  describe.each(fixturesOf(scheme))('on a %s', (_, soup) => {
    it('passes validate() after every phase of three levels, with the counts the scheme predicts', () => {
      const mesh = meshOf(soup());
      for (let level = 0; level < 3; level++) {
        const counts = expectedCounts(mesh, scheme, level);
        stepLevel(mesh, scheme, level);
        expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual(counts);
      }
    });

    it('keeps the Euler characteristic, genus, boundary loops and components', () => {
      const mesh = meshOf(soup());
      const before = topologyOf(mesh);
      subdivide(mesh, scheme, 2);
      expect(topologyOf(mesh)).toEqual(before);
    });

    it('gives exactly the one-shot result when stepped phase by phase', () => {
      const stepped = meshOf(soup());
      const straight = stepped.clone();
      for (let level = 0; level < 2; level++) stepLevel(stepped, scheme, level);
      subdivide(straight, scheme, 2);
      expect(meshArrays(stepped)).toEqual(meshArrays(straight));
    });
  });

  it('names its phases and explains each in two sentences', () => {
    const phases = stepLevel(meshOf(tetrahedron()), scheme);
    expect(phases.map((p) => p.name)).toEqual(phaseNames[scheme]);
    for (const phase of phases) expect(phase.explanation.match(/[.!?](\s|$)/g)).toHaveLength(2);
  });

  it('lists every element whose pointers a phase changed as created or rewired, and every vertex it moved', () => {
    const check = (mesh: HalfedgeMesh, level = 0) => {
      let before = mesh.clone();
      for (const step of subdivisionOperation(mesh, scheme, { level })) {
        const phase = { ...step, ...phaseElements(step.change!) };
        const created = new Set(phase.created?.vertices ?? []);
        const listed = {
          halfedge: new Set([...(phase.rewired?.halfedges ?? []), ...[...(phase.created?.edges ?? [])].flatMap((e) => [2 * e, 2 * e + 1])]),
          vertex: new Set([...(phase.rewired?.vertices ?? []), ...created]),
          face: new Set([...(phase.rewired?.faces ?? []), ...(phase.created?.faces ?? [])]),
        };
        const { changes } = diffPointers(before, mesh, Infinity);
        expect(changes.filter((c) => !listed[c.element].has(c.id)), phase.name).toEqual([]);
        const moved = new Set(phase.moved?.vertices ?? []);
        const unlisted = [...before.vertices()].filter((v) => !moved.has(v) && at(before, v).some((x, k) => x !== at(mesh, v)[k]));
        expect(unlisted, phase.name).toEqual([]);
        before = mesh.clone();
      }
    };
    check(meshOf(anyPolygons(scheme) ? flower() : disk(2)));
    check(meshOf(anyPolygons(scheme) ? torus(4, 3) : tetrahedron()));
    if (scheme === 'sqrt3') check(meshOf(disk(2)), 1);
  });
});

describe('√3 subdivision on odd levels of an open mesh', () => {
  it('splits the boundary in three first, in two more phases', () => {
    const mesh = meshOf(disk(2));
    const phases = stepLevel(mesh, 'sqrt3', 1);
    expect(phases.map((p) => p.name)).toEqual([
      'split the boundary edges in three',
      'join the boundary points to the opposite corners',
      ...phaseNames.sqrt3,
    ]);
  });

  it('triples the boundary every second level, like the inside', () => {
    const mesh = meshOf(disk(2));
    const boundaryEdges = () => [...mesh.edges()].filter((e) => mesh.isBoundaryEdge(e)).length;
    const counts = [boundaryEdges()];
    for (let level = 0; level < 4; level++) {
      stepLevel(mesh, 'sqrt3', level);
      counts.push(boundaryEdges());
    }
    expect(counts).toEqual([12, 12, 36, 36, 108]);
  });

  it('handles a triangle with two boundary edges on an odd level by a face point', () => {
    const mesh = meshOf(fan(2)); // both triangles have two boundary edges
    const counts = expectedCounts(mesh, 'sqrt3', 1);
    stepLevel(mesh, 'sqrt3', 1);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual(counts);
  });

  it('ignores the level on a closed mesh', () => {
    const odd = meshOf(tetrahedron());
    const even = odd.clone();
    expect(stepLevel(odd, 'sqrt3', 1).map((p) => p.name)).toEqual(phaseNames.sqrt3);
    stepLevel(even, 'sqrt3', 0);
    expect(meshArrays(odd)).toEqual(meshArrays(even));
  });
});

describe('preconditions', () => {
  it('tells why Loop does not apply to a quad mesh, and throws that sentence before changing anything', () => {
    const mesh = meshOf(cube());
    const before = meshArrays(mesh);
    const reason = 'Loop subdivision needs triangles; f0 is a quad. Triangulate the mesh first.';
    expect(cannotSubdivide(mesh, 'loop')).toBe(reason);
    expect(() => loopSubdivision(mesh)).toThrow(new TopologyError(reason));
    expect(() => subdivide(mesh, 'loop', 2)).toThrow(TopologyError);
    expect(meshArrays(mesh)).toEqual(before);
  });

  it('names the first face that is not a triangle, for Butterfly and √3 too', () => {
    const mesh = meshOf(pyramid());
    expect(cannotSubdivide(mesh, 'butterfly')).toBe('Butterfly subdivision needs triangles; f0 is a quad. Triangulate the mesh first.');
    expect(cannotSubdivide(meshOf(flower()), 'sqrt3')).toBe('√3 subdivision needs triangles; f0 is a pentagon. Triangulate the mesh first.');
    expect(() => butterflySubdivision(mesh)).toThrow(TopologyError);
    expect(() => sqrt3Subdivision(mesh)).toThrow(TopologyError);
  });

  // two triangles on the same three corners: Loop would join the midpoints of two shared edges
  // once inside each triangle, a second edge between the same two vertices
  it('refuses, for Loop, Butterfly and √3, two triangles that share two edges; Catmull-Clark takes them', () => {
    const pillow = () => meshOf(soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2], [1, 0, 2]]));
    for (const scheme of ['loop', 'butterfly', 'sqrt3'] as const) {
      const mesh = pillow();
      expect(cannotSubdivide(mesh, scheme)).toMatch(/cannot split f0 and f1: they share two edges \(the same three corners\), so it would join two new vertices twice\.$/);
      expect(() => subdivide(mesh, scheme, 1)).toThrow(TopologyError);
    }
    const mesh = pillow();
    subdivide(mesh, 'catmull-clark', 1);
    expect(validate(mesh)).toEqual([]);
  });

  it('lets Catmull-Clark and linear subdivision take any polygons, and every scheme take triangles', () => {
    expect(cannotSubdivide(meshOf(flower()), 'catmull-clark')).toBeNull();
    expect(cannotSubdivide(meshOf(flower()), 'linear')).toBeNull();
    for (const scheme of schemes) expect(cannotSubdivide(meshOf(tetrahedron()), scheme)).toBeNull();
  });

  it('rejects an unknown scheme and a bad number of levels', () => {
    const mesh = meshOf(tetrahedron());
    expect(() => cannotSubdivide(mesh, 'doo-sabin' as SubdivisionScheme)).toThrow(InvalidInputError);
    expect(() => subdivisionOperation(mesh, 'doo-sabin' as SubdivisionScheme)).toThrow(InvalidInputError);
    expect(() => subdivide(mesh, 'loop', -1)).toThrow(InvalidInputError);
    expect(() => subdivide(mesh, 'loop', 1.5)).toThrow(InvalidInputError);
    expect(() => sqrt3Subdivision(mesh, { level: -1 })).toThrow(InvalidInputError);
  });

  it('does nothing for zero levels', () => {
    const mesh = meshOf(tetrahedron());
    const before = meshArrays(mesh);
    subdivide(mesh, 'loop', 0);
    expect(meshArrays(mesh)).toEqual(before);
  });

  it('compacts a mesh with deleted elements first', () => {
    const mesh = meshOf(grid(2, 2));
    deleteCornerTriangle(mesh, [...mesh.vertices()].find((v) => mesh.vertexDegree(v) === 2)!);
    expect(validate(mesh)).toEqual([]);
    expect(mesh.isCompact).toBe(false);
    const counts = expectedCounts(mesh, 'loop');
    stepLevel(mesh, 'loop');
    expect(mesh.isCompact).toBe(true);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual(counts);
  });
});

/** Deletes the one triangle at boundary vertex v of valence 2, with v and its two edges. */
function deleteCornerTriangle(mesh: HalfedgeMesh, v: number): void {
  const out = mesh.vHalfedge[v]; // v → a, on the boundary
  const into = mesh.hePrev[out]; // b → v, on the boundary
  const ba = mesh.heNext[into ^ 1]; // b → a, the triangle's third side: it borders the hole now
  const triangle = mesh.heFace[ba];
  const beforeB = mesh.hePrev[into];
  const afterA = mesh.heNext[out];
  mesh.heFace[ba] = -1;
  mesh.heNext[beforeB] = ba;
  mesh.hePrev[ba] = beforeB;
  mesh.heNext[ba] = afterA;
  mesh.hePrev[afterA] = ba;
  mesh.vHalfedge[mesh.heVertex[ba]] = ba;
  mesh.deleteEdge(out >> 1);
  mesh.deleteEdge(into >> 1);
  mesh.deleteFace(triangle);
  mesh.deleteVertex(v);
}
