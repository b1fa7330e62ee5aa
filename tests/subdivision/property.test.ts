import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { type PolygonSoup, soupFromArrays, torus, uvSphere } from '../../src/index.js';
import { type SubdivisionScheme } from '../../src/core/subdivision/index.js';
import { expectedCounts, faceLists, meshOf, stepLevel, topologyOf, triangulate } from './helpers.js';

const SEED = 20261121;
const schemes: SubdivisionScheme[] = ['loop', 'catmull-clark', 'butterfly', 'sqrt3'];

/** Subdivides two levels phase by phase: valid after every phase, the predicted counts, the same topology. */
function checkLevels(soup: PolygonSoup, scheme: SubdivisionScheme): void {
  const mesh = meshOf(soup);
  const topology = topologyOf(mesh);
  for (let level = 0; level < 2; level++) {
    const counts = expectedCounts(mesh, scheme, level);
    stepLevel(mesh, scheme, level);
    expect([mesh.nVertices, mesh.nEdges, mesh.nFaces]).toEqual(counts);
  }
  expect(topologyOf(mesh)).toEqual(topology);
}

/** The faces of `soup` whose flag is set (at least one): open meshes, holes, pinched vertices, isolated vertices. */
function someFaces(soup: PolygonSoup, keep: boolean[]): PolygonSoup {
  const faces = faceLists(soup).filter((_, i) => keep[i]);
  return soupFromArrays(soup.positions, faces.length > 0 ? faces : faceLists(soup).slice(0, 1));
}

/**
 * Flips the listed edges of a closed triangle soup where they are still flippable, making vertices
 * of every valence: the pair (a, b, c), (b, a, d) becomes (c, a, d), (d, b, c).
 */
function flipEdges(soup: PolygonSoup, picks: number[]): PolygonSoup {
  const faces = faceLists(soup);
  const key = (a: number, b: number) => `${Math.min(a, b)},${Math.max(a, b)}`;
  for (const pick of picks) {
    const sides = new Map<string, Array<[number, number]>>(); // edge → (face, corner) pairs
    faces.forEach((face, f) => face.forEach((v, i) => {
      const k = key(v, face[(i + 1) % 3]);
      sides.set(k, [...(sides.get(k) ?? []), [f, i]]);
    }));
    const edges = [...sides.entries()].filter(([, s]) => s.length === 2);
    const [, [[f, i], [g, j]]] = edges[pick % edges.length];
    const [a, b, c] = [faces[f][i], faces[f][(i + 1) % 3], faces[f][(i + 2) % 3]];
    const d = faces[g][(j + 2) % 3];
    // skip a flip that would join two vertices already joined (or a vertex to itself)
    if (c === d || sides.has(key(c, d)) || faces[g][j] !== b) continue;
    faces[f] = [c, a, d];
    faces[g] = [d, b, c];
  }
  return soupFromArrays(soup.positions, faces);
}

const sphere = uvSphere(5, 6);
const quads = torus(5, 4);
const triangles = triangulate(quads);

describe(`random open meshes, faces picked from a sphere and a torus (seed ${SEED})`, () => {
  it.each(schemes)('%s: every phase valid, the counts predicted, the topology kept', (scheme) => {
    const sources = scheme === 'catmull-clark' ? [sphere, quads] : [sphere, triangles];
    const faceCount = Math.max(...sources.map((soup) => soup.faceStarts.length - 1));
    fc.assert(
      fc.property(fc.nat(1), fc.array(fc.boolean(), { minLength: faceCount, maxLength: faceCount }), (source, keep) => {
        checkLevels(someFaces(sources[source], keep), scheme);
      }),
      { seed: SEED, numRuns: 50 },
    );
  });
});

describe(`random closed meshes, a sphere and a torus with random edges flipped (seed ${SEED})`, () => {
  it('flipping makes valences the unflipped meshes do not have', () => {
    const valences = (soup: PolygonSoup) => {
      const mesh = meshOf(soup);
      return new Set([...mesh.vertices()].map((v) => mesh.vertexDegree(v)));
    };
    const picks = Array.from({ length: 20 }, (_, i) => 7 * i + 3);
    expect(valences(flipEdges(triangles, picks)).size).toBeGreaterThan(valences(triangles).size + 2);
    expect(valences(flipEdges(sphere, picks)).size).toBeGreaterThan(valences(sphere).size + 2);
  });

  it.each(schemes)('%s: every phase valid, the counts predicted, the topology kept', (scheme) => {
    fc.assert(
      fc.property(fc.nat(1), fc.array(fc.nat(), { maxLength: 25 }), (source, picks) => {
        checkLevels(flipEdges([sphere, triangles][source], picks), scheme);
      }),
      { seed: SEED, numRuns: 50 },
    );
  });
});
