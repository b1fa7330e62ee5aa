/**
 * A repair told over the view: one label in words per element (what the file had, what the repair
 * made), in two colours, and a camera that sees every face of it, none edge-on.
 */
import { readFileSync } from 'node:fs';
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { buildMesh, faceNormal, moebiusStrip, readMesh, type RepairKind, soupFromArrays } from '../../src/index.js';
import { colors, phaseColors } from '../../src/ui/colors.js';
import { incidentBounds } from '../../src/ui/framing.js';
import { labelPoint } from '../../src/ui/scene/label-point.js';
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
    const [kept, copy] = story.labels.map((label) => new Vector3(...labelPoint(mesh, label.on)));
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

describe('the view of a repair', () => {
  const from = new Vector3(0.55, 0.45, 1).normalize();
  /** How far from edge-on each face is seen (1: face on). */
  const seen = (mesh: ReturnType<typeof buildMesh>['mesh'], faces: number[], facing: Vector3) =>
    faces.map((f) => Math.abs(new Vector3(...faceNormal(mesh, f)).dot(facing)));

  it('sees the three faces of an edge from between them, none of them edge-on', () => {
    const { mesh, report } = nonManifoldSample();
    const { facing, box, radius } = incidentBounds(mesh, incidentOf(report, 'non-manifold-edge'), 'non-manifold-edge', from);
    // three pages 120° apart: no way sees all three better than 30° off edge-on; this one nearly does
    for (const cosine of seen(mesh, [2, 3, 4], facing!)) expect(cosine).toBeGreaterThan(Math.sin((25 * Math.PI) / 180));
    // from the camera's side, and not along the edge, where the pages would be lines
    expect(facing!.dot(from)).toBeGreaterThan(0);
    expect(Math.abs(facing!.z)).toBeLessThan(0.7);
    // the whole book, and nothing of the pinch far below it
    expect(box.min.y).toBeCloseTo(1.14);
    expect(radius).toBeLessThan(2);
  });

  it('sees the fans of a pinched vertex face on', () => {
    const { mesh, report } = nonManifoldSample();
    const { facing, box } = incidentBounds(mesh, incidentOf(report, 'non-manifold-vertex'), 'non-manifold-vertex', from);
    expect(facing!.toArray()).toEqual([0, 0, 1]);
    expect(box.max.y).toBeCloseTo(0.5);
  });

  it('sees two tetrahedra tip to tip from the side, where both fans of the shared vertex show', () => {
    const corners = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1];
    const first = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    // the second outward, then inside out (so both fans face the same way): the view is the same
    for (const second of [[[0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]], [[0, 5, 4], [0, 4, 6], [0, 6, 5], [4, 5, 6]]]) {
      const { mesh, report } = buildMesh(soupFromArrays(corners, [...first, ...second]));
      const { facing } = incidentBounds(mesh, incidentOf(report, 'non-manifold-vertex'), 'non-manifold-vertex', from);
      // the line through the two fans runs along (1, 1, 1): looked at square to it
      expect(facing!.dot(new Vector3(1, 1, 1).normalize())).toBeCloseTo(0);
      expect(facing!.dot(from)).toBeGreaterThan(0);
    }
  });
});
