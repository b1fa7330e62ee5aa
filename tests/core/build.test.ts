import { describe, expect, it } from 'vitest';
import {
  annulus,
  bowTie,
  buildMesh,
  cube,
  disk,
  doubleTorus,
  fan,
  grid,
  inconsistentPair,
  meshStats,
  moebiusStrip,
  type PolygonSoup,
  singleTriangle,
  soupFromArrays,
  strip,
  tetrahedron,
  threeFacesOnAnEdge,
  torus,
  uvSphere,
  validate,
} from '../../src/index.js';
import { expectSurvivesReload } from './reload.js';

interface Expected {
  V: number;
  E: number;
  F: number;
  loops: number;
  components: number;
  chi: number;
  genus: number | null;
  orientable?: boolean;
  repairs?: string[];
}

const fixtures: Array<[string, () => PolygonSoup, Expected]> = [
  ['tetrahedron', tetrahedron, { V: 4, E: 6, F: 4, loops: 0, components: 1, chi: 2, genus: 0 }],
  ['cube of quads', cube, { V: 8, E: 12, F: 6, loops: 0, components: 1, chi: 2, genus: 0 }],
  ['single triangle', singleTriangle, { V: 3, E: 3, F: 1, loops: 1, components: 1, chi: 1, genus: 0 }],
  ['open fan of 5 triangles', () => fan(5), { V: 7, E: 11, F: 5, loops: 1, components: 1, chi: 1, genus: 0 }],
  // vertex 0 is the lower end of 200 corners' edges: more than the builder pairs by comparing each with the rest
  ['open fan of 100 triangles', () => fan(100), { V: 102, E: 201, F: 100, loops: 1, components: 1, chi: 1, genus: 0 }],
  ['strip of 4 squares', () => strip(4), { V: 10, E: 17, F: 8, loops: 1, components: 1, chi: 1, genus: 0 }],
  ['annulus', () => annulus(12), { V: 24, E: 36, F: 12, loops: 2, components: 1, chi: 0, genus: 0 }],
  ['disk', () => disk(3), { V: 37, E: 90, F: 54, loops: 1, components: 1, chi: 1, genus: 0 }],
  ['torus of quads', () => torus(8, 6), { V: 48, E: 96, F: 48, loops: 0, components: 1, chi: 0, genus: 1 }],
  ['double torus', doubleTorus, { V: 48, E: 100, F: 50, loops: 0, components: 1, chi: -2, genus: 2 }],
  ['sphere', () => uvSphere(6, 8), { V: 42, E: 120, F: 80, loops: 0, components: 1, chi: 2, genus: 0 }],
  ['quad grid', () => grid(3, 2, true), { V: 12, E: 17, F: 6, loops: 1, components: 1, chi: 1, genus: 0 }],
  // cut open along one rung: a strip (disk) whose two seam vertices were duplicated
  [
    'Möbius strip',
    () => moebiusStrip(10),
    {
      V: 22,
      E: 31,
      F: 10,
      loops: 1,
      components: 1,
      chi: 1,
      genus: null,
      orientable: false,
      repairs: ['non-orientable', 'reoriented-face'],
    },
  ],
  [
    'two triangles touching at one vertex',
    bowTie,
    { V: 6, E: 6, F: 2, loops: 2, components: 2, chi: 2, genus: 0, repairs: ['non-manifold-vertex'] },
  ],
  [
    'three faces on one edge',
    threeFacesOnAnEdge,
    {
      V: 7,
      E: 8,
      F: 3,
      loops: 2,
      components: 2,
      chi: 2,
      genus: 0,
      repairs: ['non-manifold-edge'],
    },
  ],
  [
    'inconsistently oriented pair',
    inconsistentPair,
    { V: 4, E: 5, F: 2, loops: 1, components: 1, chi: 1, genus: 0, repairs: ['reoriented-face'] },
  ],
];

describe('buildMesh on named fixtures', () => {
  for (const [name, make, expected] of fixtures) {
    it(`builds the ${name} with exact counts and a valid structure`, () => {
      const { mesh, report } = buildMesh(make());
      expect(validate(mesh)).toEqual([]);
      const stats = meshStats(mesh, report);
      expect({
        V: stats.vertices,
        E: stats.edges,
        F: stats.faces,
        loops: stats.boundaryLoops,
        components: stats.components,
        chi: stats.eulerCharacteristic,
        genus: stats.genus,
      }).toEqual({
        V: expected.V,
        E: expected.E,
        F: expected.F,
        loops: expected.loops,
        components: expected.components,
        chi: expected.chi,
        genus: expected.genus,
      });
      expect(stats.halfedges).toBe(2 * expected.E);
      expect(stats.orientable).toBe(expected.orientable ?? true);
      expect(report.repairs.map((r) => r.kind).sort()).toEqual(expected.repairs ?? []);
    });
  }
});

describe('buildMesh keeps ids and orientation', () => {
  it('keeps vertex ids, face ids and each face loop starting at its first listed vertex', () => {
    const soup = cube();
    const { mesh, inputFaceOf } = buildMesh(soup);
    expect(inputFaceOf).toBeNull();
    for (let f = 0; f < 6; f++) {
      const listed = Array.from(soup.faceIndices.subarray(soup.faceStarts[f], soup.faceStarts[f + 1]));
      const loop: number[] = [];
      let h = mesh.fHalfedge[f];
      do {
        loop.push(mesh.heVertex[h]);
        h = mesh.heNext[h];
      } while (h !== mesh.fHalfedge[f]);
      expect(loop).toEqual(listed);
    }
  });

  it('numbers halfedges in order of first appearance, so face 0 holds h0, h2, h4', () => {
    const { mesh } = buildMesh(tetrahedron());
    expect(mesh.fHalfedge[0]).toBe(0);
    expect(mesh.heNext[0]).toBe(2);
    expect(mesh.heNext[2]).toBe(4);
  });

  it('gives a boundary vertex its outgoing boundary halfedge', () => {
    const { mesh } = buildMesh(fan(4));
    for (let v = 0; v < mesh.vertexSlots; v++) {
      expect(mesh.heFace[mesh.vHalfedge[v]]).toBe(-1);
      expect(mesh.heVertex[mesh.vHalfedge[v]]).toBe(v);
    }
  });

  it('flips the minority orientation of a component, not the majority', () => {
    // a strip of 8 triangles with the third one listed clockwise
    const soup = strip(4);
    const [a, b, c] = soup.faceIndices.subarray(6, 9);
    soup.faceIndices.set([a, c, b], 6);
    const { report, mesh } = buildMesh(soup);
    const flipped = report.repairs.find((r) => r.kind === 'reoriented-face');
    expect(flipped?.incidents.map((i) => i.inputFaces)).toEqual([[2]]);
    expect(validate(mesh)).toEqual([]);
  });

  it('keeps a closed mesh listed entirely clockwise as it is (no majority to follow)', () => {
    const soup = tetrahedron();
    for (let f = 0; f < 4; f++) soup.faceIndices.subarray(3 * f + 1, 3 * f + 3).reverse();
    const { mesh, report } = buildMesh(soup);
    expect(report.repairs).toEqual([]);
    expect(meshStats(mesh).volume).toBeLessThan(0);
  });
});

describe('buildMesh repairs and reports bad connectivity', () => {
  const square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];

  it('drops a face with an out-of-range index and names it', () => {
    const { mesh, report, inputFaceOf } = buildMesh(soupFromArrays(square, [[0, 1, 2], [0, 2, 9]]));
    expect(mesh.nFaces).toBe(1);
    expect(Array.from(inputFaceOf!)).toEqual([0]);
    const repair = report.repairs.find((r) => r.kind === 'out-of-range-index')!;
    expect(repair.incidents[0]!.inputFaces).toEqual([1]);
    expect(repair.incidents[0]!.message).toContain('vertex 9');
    expect(repair.incidents[0]!.message).toContain('0..3');
  });

  it('drops faces with fewer than 3 distinct vertices or a vertex visited twice', () => {
    const soup = soupFromArrays(
      [...square, 0.5, 0.5, 1],
      [
        [0, 1, 2],
        [0, 1],
        [3, 3, 3],
        [0, 1, 4, 1],
      ],
    );
    const { mesh, report } = buildMesh(soup);
    expect(mesh.nFaces).toBe(1);
    const repair = report.repairs.find((r) => r.kind === 'degenerate-face')!;
    expect(repair.count).toBe(3);
    expect(repair.incidents.map((i) => i.inputFaces![0])).toEqual([1, 2, 3]);
    expect(repair.incidents[2]!.message).toContain('vertex 1 twice');
    expect(validate(mesh)).toEqual([]);
  });

  it('keeps a quad that repeats a vertex in a row as a triangle', () => {
    const { mesh, report } = buildMesh(soupFromArrays(square, [[0, 1, 2, 2], [0, 0, 2, 3]]));
    expect(mesh.nFaces).toBe(2);
    expect(mesh.faceDegree(0)).toBe(3);
    expect(mesh.faceDegree(1)).toBe(3);
    expect(report.repairs.find((r) => r.kind === 'collapsed-repeated-vertex')?.count).toBe(2);
    expect(validate(mesh)).toEqual([]);
  });

  it('lists each copy of a pinched vertex with the original id', () => {
    const { mesh, report } = buildMesh(bowTie());
    const incident = report.repairs.find((r) => r.kind === 'non-manifold-vertex')!.incidents[0]!;
    expect(incident.inputVertices).toEqual([0]);
    expect(incident.vertices).toEqual([0, 5]);
    expect(mesh.position(5)).toEqual(mesh.position(0));
  });

  it('keeps two faces of a non-manifold edge joined and detaches the third', () => {
    const { mesh, report } = buildMesh(threeFacesOnAnEdge());
    const incident = report.repairs.find((r) => r.kind === 'non-manifold-edge')!.incidents[0]!;
    expect(incident.inputFaces).toEqual([0, 1, 2]);
    expect(incident.message).toContain('0, 1 stay joined, 2 detached with their own copies of vertices 1 and 0');
    // the edge's two vertices, then face 2's copies of them, at the same places
    const [a, b, ...copies] = incident.vertices!;
    expect([a, b]).toEqual([1, 0]);
    expect(copies.map((v) => mesh.position(v)).sort()).toEqual([mesh.position(a), mesh.position(b)].sort());
    // faces 0 and 1 share an edge; face 2 has no neighbour
    const neighbours = (f: number) => {
      const result: number[] = [];
      let h = mesh.fHalfedge[f];
      do {
        if (mesh.heFace[h ^ 1] !== -1) result.push(mesh.heFace[h ^ 1]);
        h = mesh.heNext[h];
      } while (h !== mesh.fHalfedge[f]);
      return result;
    };
    expect(neighbours(0)).toEqual([1]);
    expect(neighbours(2)).toEqual([]);
  });

  // four triangles on one edge, two of them the same: unpairing the extra faces alone left a slit
  // (two boundary edges joining vertices 0 and 1), which closed up when saved and read back
  it('repairs four faces on one edge into a mesh that survives save and reload', () => {
    const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1];
    const { mesh, report } = buildMesh(soupFromArrays(positions, [[0, 1, 2], [1, 0, 3], [0, 1, 4], [0, 1, 4]]));
    expect(validate(mesh)).toEqual([]);
    // faces 0 and 1 stay joined; faces 2 and 3, each with its own copies of 0 and 1, keep only
    // vertex 4 in common, which is then split too
    expect(report.repairs.map((r) => r.kind).sort()).toEqual(['non-manifold-edge', 'non-manifold-vertex', 'reoriented-face']);
    expect(meshStats(mesh).components).toBe(3);
    expectSurvivesReload(mesh);
  });

  for (const [name, make] of [
    ['Möbius strip', () => moebiusStrip(10)],
    ['three faces on one edge', threeFacesOnAnEdge],
    ['two triangles touching at one vertex', bowTie],
  ] as const) {
    it(`repairs the ${name} into a mesh that survives save and reload`, () => {
      expectSurvivesReload(buildMesh(make()).mesh);
    });
  }

  it('reports isolated vertices and keeps them', () => {
    const { mesh, report } = buildMesh(soupFromArrays([...square, 5, 5, 5], [[0, 1, 2, 3]]));
    expect(mesh.nVertices).toBe(5);
    expect(mesh.isIsolatedVertex(4)).toBe(true);
    expect(report.repairs.find((r) => r.kind === 'isolated-vertex')?.incidents[0]!.vertices).toEqual([4]);
    expect(meshStats(mesh).isolatedVertices).toBe(1);
  });

  it('loads a point set (vertices, no faces) without complaint beyond the isolated vertices', () => {
    const { mesh } = buildMesh(soupFromArrays(square, []));
    expect(mesh.nVertices).toBe(4);
    expect(mesh.nFaces).toBe(0);
    expect(validate(mesh)).toEqual([]);
  });

  it('reports NaN and infinite coordinates, and only those (huge ones are finite)', () => {
    const { report } = buildMesh(soupFromArrays([0, 0, 0, 1, 0, NaN, 0, Infinity, 0], [[0, 1, 2]]));
    const repair = report.repairs.find((r) => r.kind === 'non-finite-position')!;
    expect([repair.count, repair.message]).toEqual([2, '2 vertices have a NaN or infinite coordinate']);
    const huge = buildMesh(soupFromArrays([0, 0, 0, 1e308, 1e308, 0, 0, 1, 0], [[0, 1, 2]])).report;
    expect(huge.repairs).toEqual([]);
  });

  it('rejects arrays that do not describe a soup', () => {
    expect(() =>
      buildMesh({ positions: new Float64Array(4), faceStarts: new Uint32Array([0]), faceIndices: new Uint32Array() }),
    ).toThrow(/multiple of 3/);
    expect(() =>
      buildMesh({ positions: new Float64Array(9), faceStarts: new Uint32Array([0, 4]), faceIndices: new Uint32Array(3) }),
    ).toThrow(/faceStarts ends at 4/);
  });

  it('finds a third face on an edge among the many edges of one vertex', () => {
    // fan(100) and one more triangle on the spoke 0–51: the spokes are paired in one big bucket
    const { positions, faceIndices } = fan(100);
    const faces = Array.from({ length: 100 }, (_, f) => Array.from(faceIndices.subarray(3 * f, 3 * f + 3)));
    const { mesh, report } = buildMesh(soupFromArrays([...positions, 0, 0, 1], [...faces, [0, 51, 102]]));
    expect(validate(mesh)).toEqual([]);
    const incident = report.repairs.find((r) => r.kind === 'non-manifold-edge')!.incidents[0]!;
    expect(incident.inputFaces).toEqual([49, 50, 100]);
    expect(incident.message).toContain('49, 50 stay joined, 100 detached');
  });

  it('survives a vertex shared by thousands of faces in separate fans', () => {
    // 3000 triangles that each touch vertex 0 and nothing else: 3000 fans, 2999 copies
    const positions = [0, 0, 0];
    const faces: number[][] = [];
    for (let i = 0; i < 3000; i++) {
      positions.push(Math.cos(i), Math.sin(i), 1, Math.cos(i), Math.sin(i), 2);
      faces.push([0, 2 * i + 1, 2 * i + 2]);
    }
    const { mesh, report } = buildMesh(soupFromArrays(positions, faces));
    expect(validate(mesh)).toEqual([]);
    expect(report.repairs.find((r) => r.kind === 'non-manifold-vertex')!.incidents[0]!.vertices).toHaveLength(3000);
  });
});

describe('buildMesh carries attributes', () => {
  it('copies vertex, face and corner attributes, following flips and dropped faces', () => {
    const soup = inconsistentPair();
    soup.faceIndices = new Uint32Array([0, 1, 2, 1, 2, 3, 0, 0, 0]);
    soup.faceStarts = new Uint32Array([0, 3, 6, 9]);
    soup.vertexAttributes = [{ name: 'weight', itemSize: 1, data: new Float32Array([10, 11, 12, 13]) }];
    soup.faceAttributes = [{ name: 'label', itemSize: 1, data: new Int32Array([100, 101, 102]) }];
    // corner attribute = the corner's own vertex id, so it must follow the vertex through the flip
    soup.cornerAttributes = [{ name: 'corner', itemSize: 1, data: new Float32Array([0, 1, 2, 1, 2, 3, 0, 0, 0]) }];
    const { mesh } = buildMesh(soup);
    expect(Array.from(mesh.vertexAttributes.get('weight')!.data)).toEqual([10, 11, 12, 13]);
    expect(Array.from(mesh.faceAttributes.get('label')!.data)).toEqual([100, 101]);
    const corner = mesh.halfedgeAttributes.get('corner')!.data;
    for (let h = 0; h < mesh.halfedgeSlots; h++) {
      if (mesh.heFace[h] !== -1) expect(corner[h]).toBe(mesh.heVertex[h]);
    }
  });
});
