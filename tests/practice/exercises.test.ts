import { describe, expect, it } from 'vitest';
import { canCollapseEdge, canFlipEdge, validate } from '../../src/core/index.js';
import { exercises, findExercise, fixtureMesh, frozenInput, gradeSolution } from '../../src/core/practice/index.js';
import { failures, grade, inProcess } from './helpers.js';

describe('every exercise', () => {
  for (const exercise of exercises) {
    it(`${exercise.id}: the library's own algorithm, written as a solution, passes every check`, async () => {
      const report = await grade(exercise.id, exercise.id);
      expect(failures(report)).toEqual([]);
      expect(report.checks).toHaveLength(exercise.fixtures.length * (exercise.kind === 'query' ? 1 : 2));
      if (exercise.kind === 'edit') {
        // something really happened on at least one fixture, and every result is a valid mesh
        expect(report.fixtures.some((f) => f.writes.length > 0)).toBe(true);
        for (const f of report.fixtures) expect(validate(f.after)).toEqual([]);
      }
    });

    it(`${exercise.id}: the starter code runs and fails somewhere (it is a start, not an answer)`, async () => {
      const report = await gradeSolution(exercise, exercise.starter, inProcess);
      expect(report.passed).toBe(false);
    });
  }

  it('has the ids the course asks for, each with a task, hints and fixtures that build', () => {
    expect(exercises.map((e) => e.id)).toEqual([
      'vertex-degree', 'face-degree', 'one-ring', 'is-boundary-vertex', 'boundary-loops', 'euler-characteristic',
      'flip-edge', 'split-edge', 'collapse-edge', 'inset-vertex', 'extrude-face', 'bevel-vertex', 'bevel-edge',
      'dissolve-edge', 'dissolve-vertex', 'collapse-face', 'make-boundary', 'weld-edges', 'triangulate',
      'loop-subdivision', 'catmull-clark', 'linear-subdivision', 'isotropic-remesh', 'simplify',
    ]);
    for (const exercise of exercises) {
      expect(exercise.task.length).toBeGreaterThan(0);
      expect(exercise.hints.length).toBeGreaterThan(0);
      for (const fixture of exercise.fixtures) expect(validate(fixtureMesh(fixture))).toEqual([]);
    }
  });

  it('finds inset-vertex by its older id, poke-face', () => {
    expect(findExercise('poke-face')).toBe(findExercise('inset-vertex'));
    expect(findExercise('poke-face')!.id).toBe('inset-vertex');
  });

  const operations = ['flip-edge', 'split-edge', 'collapse-edge', 'inset-vertex', 'extrude-face', 'bevel-vertex', 'bevel-edge', 'dissolve-edge', 'dissolve-vertex', 'collapse-face', 'make-boundary', 'weld-edges', 'triangulate', 'catmull-clark', 'linear-subdivision'];

  it('gives every local operation hidden fixtures, each with its rule, for cases the library does and cases it refuses', () => {
    for (const id of operations) {
      const exercise = findExercise(id)!;
      const hidden = exercise.fixtures.filter((f) => f.hidden);
      expect(hidden.length, id).toBeGreaterThan(0);
      expect(exercise.fixtures.filter((f) => !f.hidden).length, id).toBeGreaterThanOrEqual(3);
      for (const fixture of hidden) expect(fixture.rule, `${id}: ${fixture.name}`).toMatch(/^[A-Z].{20,}\.$/);
      if (exercise.refusal === undefined) continue;
      // a hard case the library does, and (where it refuses anything) one it refuses
      const refused = hidden.filter((f) => /\(refused\)$/.test(f.name));
      expect(hidden.length - refused.length, id).toBeGreaterThan(0);
      if (id !== 'inset-vertex') expect(refused.length, id).toBeGreaterThan(0);
    }
  });

  it(`says "(refused)" in a fixture's name exactly where the library refuses it, and tells it to return the refusal`, () => {
    for (const exercise of exercises.filter((e) => e.refusal !== undefined)) {
      for (const fixture of exercise.fixtures) {
        const mesh = fixtureMesh(fixture);
        const value = (exercise.reference as (m: typeof mesh, input: unknown) => unknown)(mesh, frozenInput(fixture.input));
        const refused = value === exercise.refusal;
        expect(/\(refused\)$/.test(fixture.name), `${exercise.id}: ${fixture.name}`).toBe(refused);
        if (refused) expect(fixture.rule, `${exercise.id}: ${fixture.name}`).toContain(`return ${String(exercise.refusal)} and change nothing`);
        else expect(validate(mesh), `${exercise.id}: ${fixture.name}`).toEqual([]);
      }
    }
  });

  it('has fixtures for the hard cases they are named after', () => {
    const mesh = (id: string, name: RegExp) => {
      const fixture = findExercise(id)!.fixtures.find((f) => name.test(f.name))!;
      return { mesh: fixtureMesh(fixture), input: fixture.input as number };
    };
    const link = mesh('collapse-edge', /link condition/);
    expect(canCollapseEdge(link.mesh, link.input)).toMatch(/link condition/);
    const tetra = mesh('collapse-edge', /tetrahedron/);
    expect(canCollapseEdge(tetra.mesh, tetra.input)).toMatch(/tetrahedron/);
    const boundary = mesh('collapse-edge', /on the boundary/);
    expect(boundary.mesh.isBoundaryEdge(boundary.input)).toBe(true);
    expect(canCollapseEdge(boundary.mesh, boundary.input)).toBeNull();
    const flipBoundary = mesh('flip-edge', /boundary edge/);
    expect(canFlipEdge(flipBoundary.mesh, flipBoundary.input)).toMatch(/boundary/);
    const flipJoined = mesh('flip-edge', /tetrahedron/);
    expect(canFlipEdge(flipJoined.mesh, flipJoined.input)).toMatch(/already exists/);
    const flipQuads = mesh('flip-edge', /quads/);
    expect(canFlipEdge(flipQuads.mesh, flipQuads.input)).toMatch(/4 sides/);
    const split = mesh('split-edge', /boundary/);
    expect(split.mesh.isBoundaryEdge(split.input)).toBe(true);
    const valence3 = mesh('vertex-degree', /valence 3/);
    expect(valence3.mesh.vertexDegree(valence3.input)).toBe(3);
    const twoParts = findExercise('boundary-loops')!.fixtures.find((f) => /two components/.test(f.name))!;
    expect(twoParts.shapes).toHaveLength(2);
  });
});
