import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  buildMesh,
  cube,
  doubleTorus,
  meshStats,
  type PolygonSoup,
  soupFromArrays,
  tetrahedron,
  torus,
  uvSphere,
  validate,
} from '../../src/index.js';
import { expectSurvivesReload } from './reload.js';

const SEED = 20261121;

/** Face lists of a soup, as arrays. */
function faceLists(soup: PolygonSoup): number[][] {
  const faces: number[][] = [];
  for (let f = 0; f + 1 < soup.faceStarts.length; f++) {
    faces.push(Array.from(soup.faceIndices.subarray(soup.faceStarts[f], soup.faceStarts[f + 1])));
  }
  return faces;
}

const closedShapes: Array<[string, PolygonSoup, number]> = [
  ['tetrahedron', tetrahedron(), 0],
  ['cube', cube(), 0],
  ['sphere', uvSphere(6, 7), 0],
  ['torus', torus(7, 5), 1],
  ['double torus', doubleTorus(), 2],
];

describe(`random soups (seed ${SEED})`, () => {
  it('always build into a mesh that validate() accepts, with every face kept or reported', () => {
    const soup = fc
      .integer({ min: 0, max: 25 })
      .chain((nV) =>
        fc.record({
          nV: fc.constant(nV),
          faces: fc.array(fc.array(fc.integer({ min: -1, max: nV + 1 }), { maxLength: 7 }), { maxLength: 60 }),
        }),
      );
    fc.assert(
      fc.property(soup, ({ nV, faces }) => {
        const positions = Array.from({ length: 3 * nV }, (_, i) => Math.sin(i * 12.9898) * 43758.5453 % 1);
        // negative indices cannot be stored in the soup's Uint32Array: they wrap to huge ones
        const { mesh, report } = buildMesh(soupFromArrays(positions, faces));
        expect(validate(mesh)).toEqual([]);
        const dropped = report.repairs
          .filter((r) => r.kind === 'out-of-range-index' || r.kind === 'degenerate-face')
          .reduce((n, r) => n + r.count, 0);
        expect(mesh.nFaces + dropped).toBe(faces.length);
      }),
      { seed: SEED, numRuns: 400 },
    );
  });
});

describe(`damaged closed meshes (seed ${SEED})`, () => {
  for (const [name, shape, genus] of closedShapes) {
    const faces = faceLists(shape);
    const positions = Array.from(shape.positions);

    it(`a ${name} with random faces flipped is re-oriented: closed, genus ${genus}, valid`, () => {
      fc.assert(
        fc.property(fc.array(fc.boolean(), { minLength: faces.length, maxLength: faces.length }), (flips) => {
          const damaged = faces.map((f, i) => (flips[i] ? [...f].reverse() : f));
          const { mesh, report } = buildMesh(soupFromArrays(positions, damaged));
          expect(validate(mesh)).toEqual([]);
          const stats = meshStats(mesh, report);
          expect([stats.closed, stats.orientable, stats.genus, stats.components]).toEqual([true, true, genus, 1]);
          const reoriented = report.repairs.find((r) => r.kind === 'reoriented-face')?.count ?? 0;
          const flipped = flips.filter(Boolean).length;
          expect(reoriented).toBe(Math.min(flipped, faces.length - flipped));
        }),
        { seed: SEED, numRuns: 60 },
      );
    });

    it(`a ${name} with faces removed, duplicated and glued at random stays valid and survives save and reload`, () => {
      const edit = fc.array(
        fc.oneof(
          fc.record({ kind: fc.constant('remove' as const), face: fc.nat(faces.length - 1) }),
          fc.record({ kind: fc.constant('duplicate' as const), face: fc.nat(faces.length - 1) }),
          fc.record({
            kind: fc.constant('glue' as const),
            face: fc.array(fc.nat(positions.length / 3 - 1), { minLength: 3, maxLength: 5 }),
          }),
        ),
        { maxLength: 12 },
      );
      fc.assert(
        fc.property(edit, (edits) => {
          const damaged = faces.map((f) => [...f]);
          for (const e of edits) {
            if (e.kind === 'remove') damaged.splice(e.face % damaged.length, 1);
            else if (e.kind === 'duplicate') damaged.push([...faces[e.face]!]);
            else damaged.push(e.face);
            if (damaged.length === 0) damaged.push(faces[0]!);
          }
          const { mesh } = buildMesh(soupFromArrays(positions, damaged));
          expectSurvivesReload(mesh);
        }),
        { seed: SEED, numRuns: 150 },
      );
    });
  }
});
