import { describe, expect, it } from 'vitest';
import { findExercise, gradeSolution, type ShapeCall } from '../../src/core/practice/index.js';
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
  });

  it('a face made a hole whose corners keep a halfedge that is not on the boundary: blamed on the first face(h) = -1', async () => {
    const report = await grade('make-boundary', wrong('make-boundary-forgets-corners'));
    const inside = report.fixtures[0];
    expect(inside.firstBroken!.invariant).toMatch(/^v\d+ is on the boundary \(h\d+ leaves it\) but its halfedge h\d+ is not a boundary halfedge$/);
    expect(failures(report)[0]).toMatch(/since write 1, face\(h\d+\) = -1 at line 28$/);
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
