/**
 * The edit-sequence fuzzer, a short run: random meshes through random sequences of every edit and
 * operation, each checked (see `fuzz/edits.ts`). `npm run fuzz -- --only edits` runs it long.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { editCommands, editSequenceTarget, editsTarget, Step } from '../../fuzz/edits.js';

const SEED = 20261125;
const CASES = 1500;

describe(`the edit-sequence fuzzer (seed ${SEED})`, () => {
  it(`finds no failure in ${CASES} sequences`, () => {
    const failures: string[] = [];
    for (let index = 0; index < CASES; index++) {
      const outcome = editsTarget.runCase(SEED, index);
      if (outcome.kind === 'failure') failures.push(`case ${index}: ${outcome.reason}\n  ${outcome.input}`);
    }
    expect(failures).toEqual([]);
  });

  // the fuzzer must not pass by not looking: an edit that breaks a pointer, and one that says
  // it changed nothing while it moved a vertex's halfedge, are each caught and shrunk to one step
  it('catches a broken edit and shrinks the sequence to it', () => {
    const breakNext = fc.constant(null).map(
      () => new Step('break', (mesh) => ({ name: 'break next(h0)', refusal: null, apply: () => void (mesh.heNext[0] = mesh.heNext[2]) })),
    );
    const target = editSequenceTarget([...editCommands, breakNext]);
    const failures = Array.from({ length: 40 }, (_, i) => target.runCase(SEED, i)).filter((o) => o.kind === 'failure');
    expect(failures.length).toBeGreaterThan(0);
    for (const failure of failures) {
      expect(failure).toMatchObject({ reason: expect.stringMatching(/^break next\(h0\) left an invalid mesh: /) });
      expect(failure.kind === 'failure' && failure.input).toMatch(/^[^;]+; break next\(h0\)   \[fast-check seed -?\d+, path [\d:]+\]$/);
    }
  });

  it('catches an edit whose report leaves out a pointer it wrote', () => {
    const silent = fc.constant(null).map(
      () =>
        new Step('silent', (mesh) => {
          const v = [...mesh.vertices()].find((u) => mesh.vertexDegree(u) > 1 && !mesh.isBoundaryVertex(u));
          if (v === undefined) return null;
          const other = mesh.hePrev[mesh.vHalfedge[v]] ^ 1;
          const apply = () => {
            mesh.vHalfedge[v] = other;
            return { changes: [], record: null, created: {}, removed: {} };
          };
          return { name: `silent v${v}`, refusal: null, apply };
        }),
    );
    const target = editSequenceTarget([silent]);
    const failures = Array.from({ length: 20 }, (_, i) => target.runCase(SEED, i)).filter((o) => o.kind === 'failure');
    expect(failures.length).toBeGreaterThan(0);
    for (const failure of failures) {
      expect(failure).toMatchObject({ reason: expect.stringMatching(/^silent v\d+ reported other pointer changes than it made$/) });
    }
  });
});
