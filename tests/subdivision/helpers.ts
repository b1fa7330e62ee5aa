/** Fixtures and checks shared by the subdivision tests. */
import { expect } from 'vitest';
import { buildMesh, type HalfedgeMesh, meshStats, type Phase, type PolygonSoup, soupFromArrays, validate } from '../../src/index.js';
import { type SubdivisionScheme, subdivisionOperation } from '../../src/core/subdivision/index.js';

/** Face lists of a soup, as arrays. */
export function faceLists(soup: PolygonSoup): number[][] {
  const faces: number[][] = [];
  for (let f = 0; f + 1 < soup.faceStarts.length; f++) {
    faces.push(Array.from(soup.faceIndices.subarray(soup.faceStarts[f], soup.faceStarts[f + 1])));
  }
  return faces;
}

/** Each face cut into triangles fanned from its first corner. */
export function triangulate(soup: PolygonSoup): PolygonSoup {
  const triangles = faceLists(soup).flatMap((face) => face.slice(2).map((c, i) => [face[0], face[i + 1], c]));
  return soupFromArrays(soup.positions, triangles);
}

export function meshOf(soup: PolygonSoup): HalfedgeMesh {
  return buildMesh(soup).mesh;
}

/** A square pyramid: four triangles and a quad, closed. */
export function pyramid(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1],
    [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
  );
}

/** A pentagon ringed by five quads: mixed polygons, one boundary loop. */
export function flower(): PolygonSoup {
  const positions: number[] = [];
  for (let i = 0; i < 5; i++) {
    const t = (2 * Math.PI * i) / 5;
    positions.push(Math.cos(t), Math.sin(t), 0, 2 * Math.cos(t), 2 * Math.sin(t), 0.3);
  }
  const inner = (i: number) => 2 * (i % 5);
  const outer = (i: number) => 2 * (i % 5) + 1;
  const faces: number[][] = [[0, 2, 4, 6, 8]];
  for (let i = 0; i < 5; i++) faces.push([inner(i), outer(i), outer(i + 1), inner(i + 1)]);
  return soupFromArrays(positions, faces);
}

/** The element counts a level of `scheme` must give (see each scheme's module header). */
export function expectedCounts(mesh: HalfedgeMesh, scheme: SubdivisionScheme, level = 0): [number, number, number] {
  const V = mesh.nVertices;
  const E = mesh.nEdges;
  const F = mesh.nFaces;
  switch (scheme) {
    case 'loop':
    case 'butterfly':
      return [V + E, 2 * E + 3 * F, 4 * F];
    case 'catmull-clark':
    case 'linear': {
      const corners = [...mesh.halfedges()].filter((h) => mesh.heFace[h] !== -1).length;
      return [V + E + F, 2 * E + corners, corners];
    }
    case 'sqrt3': {
      // odd levels split each boundary edge in three; triangles on one boundary edge get no face point
      const b = level % 2 === 1 ? [...mesh.edges()].filter((e) => mesh.isBoundaryEdge(e)).length : 0;
      const onOne = level % 2 === 1 ? [...mesh.faces()].filter((f) => boundaryEdgesOf(mesh, f) === 1).length : 0;
      return [V + F + 2 * b - onOne, E + 3 * F + 4 * b - 3 * onOne, 3 * F + 2 * b - 2 * onOne];
    }
  }
}

function boundaryEdgesOf(mesh: HalfedgeMesh, f: number): number {
  let count = 0;
  let h = mesh.fHalfedge[f];
  do {
    if (mesh.heFace[h ^ 1] === -1) count++;
    h = mesh.heNext[h];
  } while (h !== mesh.fHalfedge[f]);
  return count;
}

/** Runs one level phase by phase, checking `validate` at every phase; returns the phases. */
export function stepLevel(mesh: HalfedgeMesh, scheme: SubdivisionScheme, level = 0): Phase[] {
  const phases: Phase[] = [];
  for (const phase of subdivisionOperation(mesh, scheme, { level })) {
    expect(validate(mesh), `after '${phase.name}'`).toEqual([]);
    phases.push(phase);
  }
  return phases;
}

/** What a level must keep: Euler characteristic, genus, boundary loops and components. */
export function topologyOf(mesh: HalfedgeMesh) {
  const { eulerCharacteristic, genus, boundaryLoops, components } = meshStats(mesh);
  return { eulerCharacteristic, genus, boundaryLoops, components };
}

/** Every pointer array and the positions, cut to the live slots, for exact comparison. */
export function meshArrays(mesh: HalfedgeMesh) {
  const nH = mesh.halfedgeSlots;
  return {
    heNext: mesh.heNext.slice(0, nH),
    hePrev: mesh.hePrev.slice(0, nH),
    heVertex: mesh.heVertex.slice(0, nH),
    heFace: mesh.heFace.slice(0, nH),
    vHalfedge: mesh.vHalfedge.slice(0, mesh.vertexSlots),
    fHalfedge: mesh.fHalfedge.slice(0, mesh.faceSlots),
    positions: mesh.positions.slice(0, 3 * mesh.vertexSlots),
  };
}

/** Position of vertex v as an array. */
export function at(mesh: HalfedgeMesh, v: number): number[] {
  return Array.from(mesh.positions.subarray(3 * v, 3 * v + 3));
}

