/**
 * The pieces of "to fix": the order in which the library's edit writes its fields, and what is
 * not a mistake (a vertex's or a face's halfedge other than the library's, where any would do).
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, flipEdge, inWriteOrder, meshArrayIndex, validate } from '../../src/core/index.js';
import { findExercise, fixtureMesh, replayWrites, whatToFix } from '../../src/core/practice/index.js';
import { edgeBetween, square } from '../edits/helpers.js';
import { inProcess, solution } from './helpers.js';

const { heNext: NEXT, heVertex: ORIGIN } = meshArrayIndex;

describe('inWriteOrder', () => {
  it("lists a flip's fields in the order it first wrote them, and stops listing when it returns", () => {
    const mesh = buildMesh(square()).mesh;
    const e = edgeBetween(mesh, 0, 2);
    const h = 2 * e;
    const next = mesh.heNext[h];
    const { value, fields } = inWriteOrder(mesh, () => flipEdge(mesh, e));
    // every field the record says changed is listed, once
    const { array, index } = value.record!.pointers;
    for (let i = 0; i < array.length; i++) expect(fields).toContain(16 * index[i] + array[i]);
    expect(new Set(fields).size).toBe(fields.length);
    // the flip moves h's origin before it relinks the triangle h starts
    expect(fields.indexOf(16 * h + ORIGIN)).toBeLessThan(fields.indexOf(16 * next + NEXT));
    const listed = fields.length;
    flipEdge(mesh, e);
    expect(fields).toHaveLength(listed);
  });
});

describe('whatToFix', () => {
  it("names nothing where a solution picks another face's halfedge than the library, as the convention allows", async () => {
    const exercise = findExercise('flip-edge')!;
    const fixture = exercise.fixtures[0];
    const before = fixtureMesh(fixture);
    const source = solution('flip-edge').replace('mesh.setFaceHalfedge(f0, h);', 'mesh.setFaceHalfedge(f0, hp);').replace('mesh.setFaceHalfedge(f1, t);', 'mesh.setFaceHalfedge(f1, tp);');
    const [output] = await inProcess(source, [{ mesh: before, input: fixture.input }]);
    const yours = replayWrites(before.clone(), output.writes);
    const reference = before.clone();
    const { fields } = inWriteOrder(reference, () => flipEdge(reference, fixture.input as number));
    expect(validate(yours)).toEqual([]);
    // the handles differ, and that is no mistake
    expect(Array.from(yours.fHalfedge.subarray(0, yours.faceSlots))).not.toEqual(Array.from(reference.fHalfedge.subarray(0, reference.faceSlots)));
    expect(whatToFix(before, yours, output.writes, { mesh: reference, order: fields })).toBeNull();
  });
});
