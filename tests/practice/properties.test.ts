import { describe, expect, it } from 'vitest';
import { buildMesh, cube, decimate, grid, remesh, uvSphere } from '../../src/core/index.js';
import { checkProperties, exercises, findExercise, fixtureMesh, frozenInput, parseExercise } from '../../src/core/practice/index.js';
import { failures, grade } from './helpers.js';

const propertyExercises = exercises.filter((e) => e.compare === 'properties');

describe('grading by properties', () => {
  it('is how remeshing and simplification are graded, with bounds the library reaches with room', () => {
    expect(propertyExercises.map((e) => e.id)).toEqual(['isotropic-remesh', 'simplify']);
    const library = { 'isotropic-remesh': (m: ReturnType<typeof fixtureMesh>, input: never) => remesh(m, input), simplify: (m: ReturnType<typeof fixtureMesh>, input: { faces: number }) => decimate(m, { targetFaces: input.faces }) };
    for (const exercise of propertyExercises) {
      const bounds = exercise.bounds!;
      // tighter bounds than the exercise's: the library's result is not at the edge of passing
      const tighter = {
        maxDistance: bounds.maxDistance * 0.8,
        ...(bounds.shareNearTarget ? { shareNearTarget: Math.min(1, bounds.shareNearTarget * 1.5) } : {}),
        ...(bounds.shareOfTargetFaces ? { shareOfTargetFaces: bounds.shareOfTargetFaces } : {}),
      };
      for (const fixture of exercise.fixtures) {
        const before = fixtureMesh(fixture);
        const after = before.clone();
        library[exercise.id as keyof typeof library](after, frozenInput(fixture.input) as never);
        expect(checkProperties(after, before, fixture.input, tighter), `${exercise.id}: ${fixture.name}`).toBeNull();
      }
    }
  });

  it('says the first property a result lacks: triangles, topology, the target, the shape', () => {
    const sphere = buildMesh(uvSphere(8, 6)).mesh;
    const bounds = { shareNearTarget: 0.5, maxDistance: 0.04 };
    const L = { targetEdgeLength: 0.5, iterations: 3 };
    expect(checkProperties(buildMesh(cube()).mesh, buildMesh(cube()).mesh, L, bounds)).toBe('the result needs triangles; f0 is a quad.');

    const holed = sphere.clone();
    holed.deleteFace(0); // a hole where the face was: the same vertices and edges, one boundary loop more
    for (let h = 0; h < holed.halfedgeSlots; h++) if (holed.heFace[h] === 0) holed.heFace[h] = -1;
    expect(checkProperties(holed, sphere, L, bounds)).toBe('the topology changed: a component of the result has χ = 1 with 1 boundary loop, where the input\'s has χ = 2 with 0 boundary loops');

    expect(checkProperties(sphere, sphere, { targetEdgeLength: 5, iterations: 3 }, bounds)).toMatch(/^0 % of your \d+ edges are within 4\/5 … 4\/3 of the target length 5; at least 50 % must be$/);

    const shrunk = sphere.clone();
    for (const v of shrunk.vertices()) shrunk.setPosition(v, ...(shrunk.position(v).map((x) => 0.8 * x) as [number, number, number]));
    expect(checkProperties(shrunk, sphere, { targetEdgeLength: 0.6 }, { maxDistance: 0.04 })).toMatch(/^your v\d+ is 0\.1\d+ from the input surface; at most 0\.1\d+ is allowed \(4 % of its size\)$/);

    // a plane's grid drawn into one corner of itself: every point on the input, but most of the input far from it
    const plane = buildMesh(grid(4, 4)).mesh;
    const corner = plane.clone();
    for (const v of corner.vertices()) corner.setPosition(v, ...(corner.position(v).map((x) => 0.5 * x) as [number, number, number]));
    expect(checkProperties(corner, plane, { faces: 32 }, { shareOfTargetFaces: 0.9, maxDistance: 0.04 })).toMatch(/^the input's v\d+ is .* from your surface; at most .* is allowed \(4 % of its size\): part of the shape is lost$/);
    expect(checkProperties(plane, plane, { faces: 20 }, { shareOfTargetFaces: 0.9, maxDistance: 0.04 })).toBe('your mesh has 32 faces; the target is 20 (from 18 up to 20 pass)');
  });

  it('fails a remeshing that only splits for the target it misses, and a simplification that moves the corners for the shape it loses', async () => {
    const splitsOnly = await grade('isotropic-remesh', 'wrong/remesh-splits-only');
    expect(failures(splitsOnly)).toContainEqual(expect.stringMatching(/^a grid, to longer edges: properties held — \d+ % of your \d+ edges are within 4\/5 … 4\/3 of the target length 0\.28; at least 50 % must be$/));
    const midpoints = await grade('simplify', 'wrong/simplify-midpoints');
    expect(failures(midpoints)).toContainEqual(expect.stringMatching(/^a grid, to a quarter of its faces: properties held — the input's v\d+ is .* from your surface; .*: part of the shape is lost$/));
    // a hidden fixture says which property, never an id of its mesh
    const hidden = midpoints.checks.filter((c) => c.hidden && !c.passed);
    for (const check of hidden) expect(check.message).not.toMatch(/\b[vhef]\d+\b/);
  });

  it('reads bounds from an instructor\'s exercise file, and refuses bounds it cannot use by name', () => {
    const simplify = findExercise('simplify')!;
    const doc = { ...simplify, reference: 'reference.js', fixtures: simplify.fixtures.map(({ name, shapes, input }) => ({ name, shapes, input })) };
    expect(parseExercise(doc, '').bounds).toEqual(simplify.bounds);
    expect(() => parseExercise({ ...doc, bounds: undefined }, '')).toThrow('exercise: "bounds" must be an object such as { "shareNearTarget": 0.6, "maxDistance": 0.02 }');
    expect(() => parseExercise({ ...doc, bounds: { maxDistance: 2 } }, '')).toThrow('exercise: "bounds.maxDistance" must be a share of the input\'s size, above 0 and at most 1');
    expect(() => parseExercise({ ...doc, bounds: { maxDistance: 0.1, nearness: 1 } }, '')).toThrow('exercise: "bounds.nearness" is not a bound (known: maxDistance, shareNearTarget, shareOfTargetFaces)');
    expect(() => parseExercise({ ...doc, compare: 'mesh' }, '')).toThrow('exercise: "bounds" is for "compare": "properties" only');
  });
});
