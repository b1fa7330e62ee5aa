import { describe, expect, it } from 'vitest';
import { findExercise, gradeSolution } from '../../src/core/practice/index.js';
import { failures, grade, inProcess, solution } from './helpers.js';

const wrong = (name: string) => `wrong/${name}`;

describe('a wrong solution is told what is wrong', () => {
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
