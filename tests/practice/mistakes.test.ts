import { describe, expect, it } from 'vitest';
import { findExercise, type GradeReport, gradeSolution, type ShapeCall } from '../../src/core/practice/index.js';
import { failures, grade, inProcess, solution } from './helpers.js';

const wrong = (name: string) => `wrong/${name}`;

describe('a wrong solution is told what is wrong', () => {
  it('a rewrite of every next pointer of 2,000 triangles that breaks the last: its write and line are named', async () => {
    // 6,130 halfedges, each next written again (and its prev), the last one skipping a halfedge
    const source = [
      'export default function (mesh) {',
      '  const halfedges = mesh.halfedges();',
      '  const last = halfedges.pop();',
      '  for (const h of halfedges) mesh.setNext(h, mesh.next(h));',
      '  mesh.setNext(last, mesh.next(mesh.next(last)));',
      '}',
    ].join('\n');
    const exercise = { ...findExercise('loop-subdivision')!, fixtures: [{ name: 'a grid of 2,000 triangles', shapes: [['grid', 40, 25]] as ShapeCall[] }] };
    const report = await gradeSolution(exercise, source, inProcess);
    const [grid] = report.fixtures;
    expect(grid.before.nHalfedges).toBe(6130);
    expect(grid.writes).toHaveLength(2 * 6130);
    const { write, line } = grid.firstBroken!;
    expect(write).toBe(grid.writes.length - 2);
    expect(grid.writes[write]).toMatchObject({ field: 'next', index: grid.before.halfedgeSlots - 1, line: 5 });
    expect(line).toBe(5);
    expect(failures(report)[0]).toMatch(new RegExp(`since write ${write + 1}, next\\(h6129\\) = h\\d+ at line 5 \\(\\d+ invariants are broken in all\\)$`));
  });

  it('a flip that forgets a vertex halfedge: the invariant, the write and the line that broke it', async () => {
    const report = await grade('flip-edge', wrong('flip-forgets-vertex'));
    const inside = report.fixtures.find((f) => f.fixture === 'an edge inside a disk')!;
    expect(inside.firstBroken).not.toBeNull();
    const { write, line, invariant, elements } = inside.firstBroken!;
    // the write that made a vertex's halfedge start elsewhere: an origin, written at line 23 or 24
    expect(inside.writes[write].field).toBe('origin');
    expect([23, 24]).toContain(line);
    expect(invariant).toMatch(/^v\d+'s halfedge h\d+ does not start at v\d+$/);
    expect(elements.vertices.length).toBeGreaterThan(0);
    expect(failures(report).join('\n')).toContain(`since write ${write + 1}, origin(h`);
    expect(inside.checks[0].message).toMatch(/To fix: the reference sets v6's halfedge to h22 \(or any other halfedge leaving v6\); your code never writes v6's halfedge, which is still h20$/);
    // the result has the right shape, only its vertex halfedges are wrong
    expect(inside.checks.find((c) => c.name.endsWith('same as the library'))!.passed).toBe(true);
  });

  it('a correct flip passes through broken states without being blamed for them', async () => {
    const report = await grade('flip-edge', 'flip-edge');
    expect(report.fixtures.every((f) => f.firstBroken === null)).toBe(true);
  });

  it('a split that leaves its new faces without a halfedge: blamed on the newFace() line', async () => {
    const report = await grade('split-edge', wrong('split-forgets-face'));
    const inside = report.fixtures[0];
    expect(inside.firstBroken!.invariant).toMatch(/^f\d+: halfedge h-1 is not a live halfedge$/);
    expect(inside.writes[inside.firstBroken!.write].field).toBe('newFace');
    expect(inside.firstBroken!.line).toBe(30);
  });

  it('an extrusion that never gives its new corners a halfedge: blamed on the first origin that starts from one', async () => {
    const report = await grade('extrude-face', wrong('extrude-forgets-corner-halfedge'));
    const cube = report.fixtures[0];
    const { write, line, invariant } = cube.firstBroken!;
    expect(invariant).toMatch(/^v(\d+) has no halfedge but 3 halfedges start from it$/);
    expect(cube.writes[write]).toMatchObject({ field: 'origin', line: 43 });
    expect(line).toBe(43);
    expect(failures(report)[0]).toMatch(/since write \d+, origin\(h\d+\) = v\d+ at line 43/);
    // the shape is right: only the handles are missing
    expect(cube.checks[1].passed).toBe(true);
  });

  it("a vertex bevel that leaves its new sides without the wedge's face: the loop that mixes a face and no face, and the line that linked it", async () => {
    const report = await grade('bevel-vertex', wrong('bevel-forgets-wedge-face'));
    const corner = report.fixtures[0];
    expect(corner.firstBroken!.invariant).toMatch(/^h\d+ is in f\d+ but next\(h\d+\) = h\d+ is in no face \(boundary\)$/);
    expect(corner.writes[corner.firstBroken!.write].field).toBe('next');
    expect(corner.firstBroken!.line).toBe(38);
    expect(failures(report).join('\n')).toMatch(/your mesh has 3 boundary loops; the library's has 0/);
  });

  it('an edge dissolve that deletes the halfedge its end still names: blamed on the deleteEdge line', async () => {
    const report = await grade('dissolve-edge', wrong('dissolve-edge-keeps-vertex-halfedge'));
    const inside = report.fixtures[0];
    expect(inside.firstBroken!.invariant).toMatch(/^v\d+'s halfedge h\d+ does not start at v\d+$/);
    expect(inside.writes[inside.firstBroken!.write]).toMatchObject({ field: 'deleteEdge', line: 39 });
    expect(failures(report)[0]).toContain('deleteEdge(e10) at line 39');
    // and what to do about it, the pointer the library sets that the code leaves naming a deleted halfedge
    expect(failures(report)[0]).toMatch(/To fix: the reference sets v6's halfedge to h22 \(or any other halfedge leaving v6\); your code never writes v6's halfedge, and deleteEdge\(e10\) at line 39 removed the one it had$/);
  });

  it('a face made a hole whose corners keep a halfedge that is not on the boundary: blamed on the first face(h) = -1', async () => {
    const report = await grade('make-boundary', wrong('make-boundary-forgets-corners'));
    const inside = report.fixtures[0];
    expect(inside.firstBroken!.invariant).toMatch(/^v\d+ is on the boundary \(h\d+ leaves it\) but its halfedge h\d+ is not a boundary halfedge$/);
    expect(failures(report)[0]).toMatch(/since write 1, face\(h\d+\) = -1 at line 28\. To fix: /);
    expect(failures(report)[0]).toMatch(/To fix: the reference sets v0's halfedge to h0 \(or any other boundary halfedge leaving v0\); your code never writes v0's halfedge, which is still h21$/);
  });

  it('a triangulation by fans passes every convex face and fails the hidden ones with their rules', async () => {
    const report = await grade('triangulate', wrong('triangulate-fan'));
    const failed = report.checks.filter((c) => !c.passed);
    expect(failed.every((c) => c.hidden)).toBe(true);
    expect(failed.map((c) => c.name)).toContain('hidden: an L-shaped hexagon: same as the library');
    expect(failed.find((c) => /L-shaped/.test(c.name))!.message).toMatch(/no triangle may fold over\.$/);
  });

  it('a degree that counts each edge twice: both answers said', async () => {
    const report = await grade('vertex-degree', wrong('degree-twice'));
    expect(failures(report)[0]).toContain("your code returned 6; the library's answer is 3");
    expect(report.passed).toBe(false);
  });

  it('a loop that never comes back: stopped by the read budget, with the cycle it went round', async () => {
    const started = Date.now();
    const report = await grade('vertex-degree', wrong('degree-endless'));
    expect(Date.now() - started).toBeLessThan(10_000);
    const message = failures(report)[0];
    expect(message).toMatch(/stopped at line 8: your code read 1,000,000 pointers without returning: its last reads went round (h\d+ → )+h\d+ again and again \(reading next\)/);
  });

  it('code that throws: the error and its line', async () => {
    const report = await grade('vertex-degree', wrong('throws'));
    expect(failures(report)[0]).toContain('your code threw TypeError at line 4: Cannot read properties of null');
  });

  it('a wrong id: what is missing and the line that asked', async () => {
    const source = 'export default function (mesh, v) {\n  return mesh.next(-1);\n}\n';
    const report = await gradeSolution(findExercise('vertex-degree')!, source, inProcess);
    expect(failures(report)[0]).toContain('next(-1): there is no halfedge h-1 (the mesh has h0 … h11); -1 means "none": check for it before following it at line 2');
  });

  it('a query that writes is failed for the write', async () => {
    const source = 'export default function (mesh, v) {\n  mesh.setPosition(v, [0, 0, 0]);\n  return 3;\n}\n';
    const report = await gradeSolution(findExercise('vertex-degree')!, source, inProcess);
    expect(failures(report)[0]).toContain('a query must leave the mesh as it is, but line 2 wrote position(v0) = [0, 0, 0]');
  });

  it('an edit that returns the right vertex but leaves the wrong mesh is failed on the mesh', async () => {
    // splits the edge but never cuts the faces: the new vertex is right, the faces are quads
    const source = solution('split-edge').replace(/if \(!mesh\.isBoundary\([ht]\)\) cut\([^;]*;/g, '');
    const report = await gradeSolution(findExercise('split-edge')!, source, inProcess);
    expect(failures(report).join('\n')).toMatch(/your mesh has \d+ vertices, \d+ edges and \d+ faces; the library's has/);
  });

  it('a one-ring in clockwise order is wrong, from any start', async () => {
    const source = solution('one-ring').replace('return ring;', 'return ring.reverse();');
    const report = await gradeSolution(findExercise('one-ring')!, source, inProcess);
    expect(failures(report).some((f) => f.includes('(any starting vertex is right; the order is not)'))).toBe(true);
  });
});

describe('a wrong edit is told what to fix: the first pointer the library sets that the code does not', () => {
  /** The right solution to `exercise` with `from` replaced by `to`, graded. */
  const gradeChanged = async (exercise: string, from: string, to: string) => {
    const source = solution(exercise).replace(from, to);
    expect(source).not.toBe(solution(exercise));
    return gradeSolution(findExercise(exercise)!, source, inProcess);
  };
  const fixOf = (report: GradeReport, fixture: string) => report.fixtures.find((f) => f.fixture === fixture)!.checks[0].message.split('. To fix: ')[1];

  it('a flip that forgets to move a halfedge into its new face: the face it never writes', async () => {
    const report = await gradeChanged('flip-edge', '  mesh.setFace(hn, f1);\n', '');
    expect(fixOf(report, 'an edge inside a disk')).toBe("the reference sets h17's face to f5; your code never writes h17's face, which is still f4");
  });

  it('a flip that starts a halfedge at the wrong corner: the write and its line', async () => {
    const report = await gradeChanged('flip-edge', 'mesh.setOrigin(h, d);', 'mesh.setOrigin(h, c);');
    expect(fixOf(report, 'an edge inside a disk')).toBe("the reference sets h20's origin to v1; your code sets it to v5: origin(h20) = v5 at line 34");
    // said on the comparison with the library too
    expect(report.fixtures[0].checks[1].message).toMatch(/is not a face of the library's result\. To fix: the reference sets h20's origin/);
  });

  it('a collapse that deletes the halfedge a corner still names: the deleteEdge that removed it', async () => {
    const report = await gradeChanged('collapse-edge', '    if (mesh.vertexHalfedge(c) === x) mesh.setVertexHalfedge(c, hp);\n', '');
    expect(fixOf(report, 'an edge inside a disk')).toBe(
      "the reference sets v5's halfedge to h18 (or any other halfedge leaving v5); your code never writes v5's halfedge, and deleteEdge(e8) at line 57 removed the one it had",
    );
  });

  it('a collapse on the boundary that gives the survivor an inner halfedge: the write, and the rule it breaks', async () => {
    const report = await gradeChanged('collapse-edge', 'around.find((g) => mesh.isBoundary(g)) ?? around[0]', 'around[0]');
    expect(fixOf(report, 'an edge on the boundary')).toBe(
      "the reference sets v10's halfedge to h37 (or any other boundary halfedge leaving v10); your code sets it to h38: vertexHalfedge(v10) = h38 at line 85",
    );
  });

  it('a split that leaves the far end naming the halfedge that now starts at the new vertex', async () => {
    const report = await gradeChanged('split-edge', '  if (mesh.vertexHalfedge(b) === t) mesh.setVertexHalfedge(b, gt);\n', '');
    expect(fixOf(report, 'an edge on the boundary')).toBe(
      "the reference sets v2's halfedge to h25 (or any other boundary halfedge leaving v2); your code never writes v2's halfedge, which is still h3",
    );
  });

  it('a split that leaves its old face naming a halfedge of the new one', async () => {
    const report = await gradeChanged('split-edge', '  mesh.setFaceHalfedge(f, x0);\n', '');
    expect(fixOf(report, 'an edge on the boundary')).toBe("the reference sets f0's halfedge to h26 (or any other halfedge of f0); your code never writes f0's halfedge, which is still h0");
  });

  it('a pointer the library leaves alone, written wrong: the write', async () => {
    // the flip also points c at a halfedge that no longer leaves it
    const report = await gradeChanged('flip-edge', '  return true;\n}', '  mesh.setVertexHalfedge(c, h);\n  return true;\n}');
    expect(fixOf(report, 'an edge inside a disk')).toMatch(
      /^the reference leaves v(\d+)'s halfedge as it was, h\d+ \(or any other halfedge leaving v\1\); your code sets it to h20: vertexHalfedge\(v\1\) = h20 at line 42$/,
    );
  });

  it('nothing on a hidden fixture, where no id is named', async () => {
    const report = await grade('make-boundary', wrong('make-boundary-forgets-corners'));
    const hidden = report.checks.filter((c) => c.hidden && !c.passed);
    expect(hidden.length).toBeGreaterThan(0);
    expect(hidden.every((c) => !c.message.includes('To fix'))).toBe(true);
    expect(report.checks.find((c) => !c.hidden && !c.passed)!.message).toContain('To fix');
  });
});
