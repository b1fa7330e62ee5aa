import { describe, expect, it } from 'vitest';
import { canCollapseEdge, canFlipEdge, validate } from '../../src/core/index.js';
import { exercises, findExercise, fixtureMesh, gradeSolution } from '../../src/core/practice/index.js';
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
      'flip-edge', 'split-edge', 'collapse-edge', 'poke-face', 'loop-subdivision',
    ]);
    for (const exercise of exercises) {
      expect(exercise.task.length).toBeGreaterThan(0);
      expect(exercise.hints.length).toBeGreaterThan(0);
      for (const fixture of exercise.fixtures) expect(validate(fixtureMesh(fixture))).toEqual([]);
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
