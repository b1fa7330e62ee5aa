/**
 * A repair told over the view: one label in words per element (what the file had, what the repair
 * made), in two colours.
 */
import { readFileSync } from 'node:fs';
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { buildMesh, moebiusStrip, readMesh, type RepairKind, soupFromArrays } from '../../src/index.js';
import { colors, phaseColors } from '../../src/ui/colors.js';
import { repairStory } from '../../src/ui/repair-story.js';

/** The sample a lecturer opens: three faces on one edge, and two fans pinched at vertex 0. */
function nonManifoldSample() {
  const file = readMesh(readFileSync(new URL('../../public/models/non-manifold.obj', import.meta.url)), { fileName: 'non-manifold.obj' });
  return buildMesh(file.soup);
}

function incidentOf(report: ReturnType<typeof buildMesh>['report'], kind: RepairKind) {
  return report.repairs.find((r) => r.kind === kind)!.incidents[0]!;
}

const texts = (spec: ReturnType<typeof repairStory>) => spec.labels.map((label) => label.text);

describe('the story of a repair', () => {
  it('tells a three-faced edge in words: the file edge and the faces that keep it, then the face detached with its copies', () => {
    const { mesh, report } = nonManifoldSample();
    const story = repairStory(mesh, incidentOf(report, 'non-manifold-edge'), 'non-manifold-edge');
    expect(texts(story)).toEqual(['file edge 6–5 had 3 faces: f2 and f3 keep it', 'f4 detached, with its own copies v10 and v11']);
    expect(story.labels.map((label) => label.color)).toEqual([colors.problem, phaseColors.created]);
    // what the file had in the problem colour, what the repair made in the colour of what is created
    expect(story.faces).toEqual([
      { id: 2, color: colors.problem },
      { id: 3, color: colors.problem },
      { id: 4, color: phaseColors.created },
    ]);
    expect(story.vertices.filter((v) => v.color === phaseColors.created).map((v) => v.id)).toEqual([10, 11]);
    expect(story.labels.every((label) => label.sentence)).toBe(true);
  });

  it('tells a pinched vertex fan by fan, each label anchored in its own fan', () => {
    const { mesh, report } = nonManifoldSample();
    const story = repairStory(mesh, incidentOf(report, 'non-manifold-vertex'), 'non-manifold-vertex');
    expect(texts(story)).toEqual(['file vertex 0 joined 2 fans: this one keeps v0', 'this fan got its own copy, v12']);
    // v0 and v12 sit on one point; their labels do not
    const [kept, copy] = story.labels.map((label) => new Vector3(...label.at));
    expect(kept!.x).toBeGreaterThan(0); // v0's fan, face 0, lies at x > 0
    expect(copy!.x).toBeLessThan(0);
    expect(story.faces).toEqual([
      { id: 0, color: colors.problem },
      { id: 1, color: phaseColors.created },
    ]);
  });

  it('tells a seam of a Möbius strip as a cut, and any other repair with its own message', () => {
    const { mesh, report } = buildMesh(moebiusStrip(8));
    const seam = incidentOf(report, 'non-orientable');
    const [a, b] = seam.inputVertices!;
    const said = texts(repairStory(mesh, seam, 'non-orientable'));
    expect(said[0]).toBe(`file edge ${a}–${b} had its 2 faces run the same way along it: f${seam.faces![0]} keeps it`);
    expect(said[1]).toMatch(new RegExp(`^f${seam.faces![1]} detached, with its own copies v\\d+ and v\\d+$`));
    // two triangles listed against each other: the second is flipped
    const flipped = buildMesh(soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], [[0, 1, 2], [1, 2, 3]]));
    expect(texts(repairStory(flipped.mesh, incidentOf(flipped.report, 'reoriented-face'), 'reoriented-face'))).toEqual(['f1: face 1 flipped']);
  });

  it('leaves out what an edit has since deleted', () => {
    const { mesh, report } = nonManifoldSample();
    const incident = incidentOf(report, 'non-manifold-edge');
    mesh.fDeleted[4] = 1;
    expect(texts(repairStory(mesh, incident, 'non-manifold-edge'))).toEqual(['file edge 6–5 had 3 faces: f2 and f3 keep it']);
  });
});
