// Hidden fixtures (a hard case graded by its rule, its mesh never shown) and the partial credit
// of a hard case refused cleanly.
import { describe, expect, it } from 'vitest';
import { gradescope } from '../../src/cli/commands/grade.js';
import { checkNames, findExercise, gradeSolution, PARTIAL_CREDIT, parseExercise } from '../../src/core/practice/index.js';
import { grade, inProcess } from './helpers.js';

const ids = /\b[vhef]\d+\b/;

describe('a hidden fixture', () => {
  it('that fails says so and gives its rule, with no id of its mesh, no input and no writes', async () => {
    const report = await grade('extrude-face', 'wrong/extrude-forgets-corner-halfedge');
    const exercise = findExercise('extrude-face')!;
    const fixture = exercise.fixtures.find((f) => f.hidden && /corner of a grid/.test(f.name))!;
    const result = report.fixtures.find((f) => f.fixture === fixture.name)!;
    const check = result.checks.find((c) => c.name.endsWith('valid mesh'))!;
    expect(check).toMatchObject({ passed: false, status: 'failed', score: 0, hidden: true });
    expect(check.message).toBe(`the mesh your code left breaks an invariant. A hidden case: ${fixture.rule}`);
    expect(check.message).not.toMatch(ids);
    expect(result).toMatchObject({ hidden: true, writes: [], visits: [], reads: 0, firstBroken: null, input: undefined });
    // the same mistake on a fixture that is shown: the invariant, the write and its line
    const shown = report.fixtures[0];
    expect(shown.hidden).toBe(false);
    expect(shown.writes.length).toBeGreaterThan(0);
    expect(shown.checks[0].message).toMatch(ids);
  });

  it('that passes says passed, as any other', async () => {
    const report = await grade('extrude-face', 'extrude-face');
    const hidden = report.checks.filter((c) => c.hidden);
    expect(hidden.length).toBeGreaterThan(0);
    expect(hidden.every((c) => c.passed && c.message === 'passed')).toBe(true);
  });

  it('that the library refuses, and the code does not: said without the value the code returned', async () => {
    // a bevel that does not check the amount: on an amount of 1.5 it bevels anyway
    const source = (await import('node:fs')).readFileSync(new URL('./solutions/bevel-vertex.js', import.meta.url), 'utf8').replace('if (!(amount >= 0 && amount <= 1)) return -1;', '');
    const report = await gradeSolution(findExercise('bevel-vertex')!, source, inProcess);
    const failed = report.checks.filter((c) => !c.passed);
    expect(failed.map((c) => c.name)).toEqual(['hidden: an amount of 1.5 (refused): same as the library']);
    expect(failed[0].message).toBe('the library refuses this case, but your code did not return -1 and leave the mesh as it was. A hidden case: An amount outside 0 … 1 is refused: return -1 and change nothing.');
  });
});

describe('a hard case refused cleanly', () => {
  it(`that the library handles earns ${PARTIAL_CREDIT} of each of its checks, beside every shown fixture passing`, async () => {
    const report = await grade('bevel-vertex', 'wrong/bevel-refuses-boundary');
    const partial = report.checks.filter((c) => c.status === 'partial');
    expect(partial.map((c) => c.name)).toEqual([
      'hidden: a vertex on the boundary (4 edges): valid mesh',
      'hidden: a vertex on the boundary (4 edges): same as the library',
      'hidden: a vertex on the boundary with two faces: valid mesh',
      'hidden: a vertex on the boundary with two faces: same as the library',
    ]);
    for (const check of partial) {
      expect(check).toMatchObject({ passed: false, score: 0.8, hidden: true });
      expect(check.message).toMatch(/^your code refused this case cleanly \(it returned -1 and left the mesh as it was\), but the library does the edit: 0\.8 of the point\. A hidden case: /);
    }
    expect(report.checks.filter((c) => c.status === 'failed')).toEqual([]);
    expect(report.passed).toBe(false);
    expect(report.maxScore).toBe(14);
    expect(report.score).toBe(14 - 4 * (1 - PARTIAL_CREDIT));
  });

  it('earns nothing while a fixture that is shown fails (refusing is not instead of the edit)', async () => {
    const exercise = findExercise('bevel-vertex')!;
    const report = await gradeSolution(exercise, exercise.starter, inProcess); // always -1
    const handled = report.checks.filter((c) => /on the boundary/.test(c.name));
    expect(handled.length).toBe(4);
    for (const check of handled) {
      expect(check).toMatchObject({ status: 'failed', score: 0 });
      expect(check.message).toContain('(a clean refusal earns 0.8 of the point once every fixture that is not hidden passes)');
    }
    // the cases the library refuses are right, refused
    expect(report.checks.filter((c) => /\(refused\)/.test(c.name)).every((c) => c.passed)).toBe(true);
    // a shown fixture refused: the library does the edit
    expect(report.checks[1].message).toBe('your code returned -1 and changed nothing, but this case needs no refusing: the library does the edit');
    // points: the refused cases, and the shown fixtures left valid (their meshes untouched)
    expect(report.score).toBe(4 + 3);
  });

  it('goes into the Gradescope results as a fractional score, the total out of the same max_score', async () => {
    const partial = gradescope(await grade('bevel-vertex', 'wrong/bevel-refuses-boundary'));
    const right = gradescope(await grade('bevel-vertex', 'bevel-vertex'));
    expect(partial.max_score).toBe(right.max_score);
    expect(partial.tests.map((t) => t.name)).toEqual(checkNames(findExercise('bevel-vertex')!));
    expect(right.score).toBe(14);
    expect(partial.score).toBe(13.2);
    const test = partial.tests.find((t) => t.score !== 1)!;
    expect(test).toMatchObject({ name: 'hidden: a vertex on the boundary (4 edges): valid mesh', score: 0.8, max_score: 1, status: 'failed' });
    expect(test.output).toMatch(/^partial credit, 0\.8 of 1: your code refused this case cleanly/);
  });
});

describe("an instructor's exercise file", () => {
  const doc = (fixtures: unknown[], more: object = {}) => ({
    id: 'poke',
    title: 'Poke',
    kind: 'edit',
    answer: 'vertex',
    task: ['Poke face input.'],
    starter: 'export default function (mesh, f) {\n  return -1;\n}\n',
    fixtures,
    reference: 'reference.js',
    ...more,
  });
  const shown = { name: 'a quad', shapes: [['cube']], input: 0 };

  it('marks a fixture hidden with the rule it checks, and may give a mesh in OFF, named inputs and the refusal', () => {
    const exercise = parseExercise(
      doc([shown, { name: 'a pentagon', off: 'OFF\n5 1 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n', input: { face: 0, amount: 0.5 }, hidden: true, rule: 'Any face is poked.' }], { refusal: -1 }),
      'export default function () {}',
    );
    expect(exercise.refusal).toBe(-1);
    expect(exercise.fixtures[1]).toEqual({ name: 'a pentagon', off: expect.stringContaining('OFF'), input: { face: 0, amount: 0.5 }, hidden: true, rule: 'Any face is poked.' });
  });

  it('is refused, naming the field, for a hidden fixture without its rule, only hidden fixtures, or a refusal that is not -1 or false', () => {
    expect(() => parseExercise(doc([shown, { ...shown, hidden: true }]), '')).toThrow('exercise: "fixtures[1].rule" must say, in a sentence, the rule a hidden fixture checks');
    expect(() => parseExercise(doc([{ ...shown, hidden: true, rule: 'Quads are poked.' }]), '')).toThrow('exercise: "fixtures" must have one that is not hidden');
    expect(() => parseExercise(doc([shown], { refusal: 0 }), '')).toThrow('exercise: "refusal" must be -1 or false');
    expect(() => parseExercise(doc([{ ...shown, input: [1.5] }]), '')).toThrow('exercise: "fixtures[0].input" must be an integer id, a list of ids');
  });
});
