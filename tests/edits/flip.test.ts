import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { canFlipEdge, flipEdge } from '../../src/core/edits/index.js';
import { TopologyError } from '../../src/core/errors.js';
import { cube, tetrahedron, uvSphere } from '../../src/core/shapes.js';
import { checkedEdit, counts, degrees, edgeBetween, meshOf, square } from './helpers.js';

const SEED = 4242;

describe('flipEdge', () => {
  it('turns the diagonal of a square of two triangles to the other diagonal', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 2);
    expect(canFlipEdge(mesh, e)).toBeNull();
    const result = checkedEdit(mesh, (m) => flipEdge(m, e));
    expect(edgeBetween(mesh, 0, 2)).toBe(-1);
    expect(edgeBetween(mesh, 1, 3)).toBe(e);
    expect(counts(mesh)).toEqual([4, 5, 2]);
    expect(degrees(mesh)).toEqual({ 3: 2 });
    expect(result.created).toEqual({});
    expect(result.removed).toEqual({});
  });

  it('gives the original edge back when flipped twice', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 2);
    flipEdge(mesh, e);
    checkedEdit(mesh, (m) => flipEdge(m, e));
    expect(edgeBetween(mesh, 0, 2)).toBe(e);
  });

  it('refuses a boundary edge, saying why, and throws that sentence if called anyway', () => {
    const mesh = meshOf(square());
    const e = edgeBetween(mesh, 0, 1);
    expect(canFlipEdge(mesh, e)).toBe(`e${e} is on the boundary: a flip needs a face on both sides`);
    expect(() => flipEdge(mesh, e)).toThrow(TopologyError);
    expect(() => flipEdge(mesh, e)).toThrow(`flipEdge: e${e} is on the boundary`);
  });

  it('refuses an edge between quads', () => {
    const mesh = meshOf(cube());
    expect(canFlipEdge(mesh, 0)).toMatch(/^f\d beside e0 has 4 sides: a flip needs a triangle on both sides$/);
  });

  it('refuses every edge of a tetrahedron: the flipped edge already exists', () => {
    const mesh = meshOf(tetrahedron());
    for (const e of mesh.edges()) {
      expect(canFlipEdge(mesh, e)).toMatch(new RegExp(`^flipping e${e} would create an edge that already exists \\(v\\d–v\\d\\)$`));
    }
  });

  it('refuses edges that do not exist or were deleted', () => {
    const mesh = meshOf(square());
    expect(canFlipEdge(mesh, 99)).toBe('e99 is not an edge of this mesh (ids run 0…4)');
    mesh.deleteEdge(4);
    expect(canFlipEdge(mesh, 4)).toBe('e4 is deleted');
  });

  it(`keeps a sphere valid through random flips, each reporting exactly its changes (seed ${SEED})`, () => {
    fc.assert(
      fc.property(fc.array(fc.nat(), { minLength: 1, maxLength: 40 }), (picks) => {
        const mesh = meshOf(uvSphere(6, 8));
        for (const pick of picks) {
          const e = pick % mesh.edgeSlots;
          const why = canFlipEdge(mesh, e);
          if (why) expect(() => flipEdge(mesh, e)).toThrow(why);
          else checkedEdit(mesh, (m) => flipEdge(m, e));
        }
        expect(mesh.nVertices - mesh.nEdges + mesh.nFaces).toBe(2);
        expect(degrees(mesh)).toEqual({ 3: mesh.nFaces });
      }),
      { seed: SEED, numRuns: 50 },
    );
  });
});
