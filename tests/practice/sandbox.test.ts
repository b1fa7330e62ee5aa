import { describe, expect, it } from 'vitest';
import { buildMesh, cube, disk, tetrahedron } from '../../src/core/index.js';
import {
  budgetFor,
  BudgetError,
  compareMeshes,
  DEFAULT_BUDGET,
  describeWrite,
  findExercise,
  fixtureMesh,
  parseExercise,
  practiceMesh,
  replayWrites,
  SolutionError,
  solutionBody,
} from '../../src/core/practice/index.js';
import { flipEdge } from '../../src/core/edits/index.js';
import { grade } from './helpers.js';

const meshOf = (soup: Parameters<typeof buildMesh>[0]) => buildMesh(soup).mesh;

describe('a solution is read before it runs', () => {
  it('a syntax error is refused at its line and column', () => {
    expect(() => solutionBody('export default function (mesh) {\n  return mesh.next(0;\n}\n')).toThrow(new SolutionError('syntax error: Unexpected token (column 21)', 2));
  });

  it('no default export, two of them, another export, or an import is refused', () => {
    expect(() => solutionBody('function f() {}')).toThrow(/no `export default`/);
    expect(() => solutionBody('export default 1;\nexport default 2;')).toThrow(new SolutionError("syntax error: Duplicate export 'default' (column 8)", 2));
    expect(() => solutionBody('export const x = 1;\nexport default () => x;')).toThrow(/only `export default` is understood/);
    expect(() => solutionBody("import fs from 'node:fs';\nexport default () => 1;")).toThrow(new SolutionError('a solution cannot import anything: everything it needs is the mesh API', 1));
    expect(() => solutionBody("export default async () => {\n  const fs = await import('node:fs');\n};")).toThrow(/line 2: a solution cannot import/);
    expect(() => solutionBody('export default () => import.meta.url;')).toThrow(/cannot import/);
    // new.target is not an import
    expect(() => solutionBody('export default function f() { return new.target; }')).not.toThrow();
  });

  it('keeps every line where the student wrote it', () => {
    const body = solutionBody('// one\n// two\nexport default function (mesh) {\n  return 1;\n}\n');
    expect(body.split('\n')[3]).toBe('  return 1;');
    expect(new Function(body)()()).toBe(1);
  });
});

describe('the mesh API', () => {
  it('logs every write with its line, and the log replays onto the mesh it was given', () => {
    const before = meshOf(disk(1));
    const mesh = before.clone();
    let line = 10;
    const { api, trace } = practiceMesh(mesh, () => line++);
    api.setNext(0, 2);
    const v = api.newVertex([1, 2, 3]);
    api.setVertexHalfedge(v, 4);
    expect(trace.writes.map(describeWrite)).toEqual(['next(h0) = h2', 'prev(h2) = h0', 'newVertex() → v7', 'vertexHalfedge(v7) = h4']);
    expect(trace.writes.map((w) => w.line)).toEqual([10, 11, 12, 13]);
    expect(trace.writes[0]).toMatchObject({ field: 'next', index: 0, old: before.heNext[0], new: 2 });
    const replayed = replayWrites(before.clone(), trace.writes);
    expect([...replayed.heNext]).toEqual([...mesh.heNext]);
    expect([...replayed.vHalfedge]).toEqual([...mesh.vHalfedge]);
    expect(replayed.position(v)).toEqual([1, 2, 3]);
  });

  it('refuses ids that are not there, deleted elements and malformed positions', () => {
    const mesh = meshOf(tetrahedron());
    const { api } = practiceMesh(mesh, () => null);
    expect(() => api.next(12)).toThrow('next(12): there is no halfedge h12 (the mesh has h0 … h11)');
    expect(() => api.face(1.5)).toThrow('face(…) was given 1.5 where a halfedge id (an integer) belongs');
    expect(() => api.position('v1' as unknown as number)).toThrow('position(…) was given the string "v1" where a vertex id (an integer) belongs');
    api.deleteFace(2);
    expect(() => api.faceHalfedge(2)).toThrow('faceHalfedge(f2): f2 has been deleted');
    expect(() => api.setPosition(0, [1, 2])).toThrow('setPosition(…) was given an array of 2 where a position [x, y, z] of three finite numbers belongs');
    expect(() => api.newVertex([0, Number.NaN, 0])).toThrow(/three finite numbers/);
  });

  it('stops a walk round a cycle, naming the cycle', () => {
    const mesh = meshOf(tetrahedron());
    const { api } = practiceMesh(mesh, () => null, { reads: 1000, milliseconds: 10_000, newElements: 10 });
    const walk = () => {
      let h = 0;
      for (;;) h = api.next(h);
    };
    const error = (() => {
      try {
        walk();
      } catch (e) {
        return e;
      }
    })();
    expect(error).toBeInstanceOf(BudgetError);
    expect(() => {
      throw error;
    }).toThrow(/read 1,000 pointers without returning: its last reads went round h\d+ → h\d+ → h\d+ → h\d+ again and again \(reading next\)/);
  });

  it('stops a loop that keeps making elements', () => {
    const { api } = practiceMesh(meshOf(tetrahedron()), () => null, { reads: 1e6, milliseconds: 10_000, newElements: 100 });
    expect(() => {
      for (;;) api.newEdge();
    }).toThrow('your code made more than 100 new edges: far more than this exercise needs (a loop that keeps adding?)');
  });

  it('stops on the clock too, when a budget of time runs out while reading', () => {
    let now = 0;
    const { api } = practiceMesh(meshOf(tetrahedron()), () => null, { reads: 1e9, milliseconds: 2000, newElements: 10 }, () => (now += 1));
    expect(() => {
      for (let h = 0; ; h = (h + 1) % 12) api.twin(h);
    }).toThrow(/ran for 2 s without returning/);
  });

  it('gives a small fixture the default budget and a large one more, in proportion to its halfedges', () => {
    expect(budgetFor(meshOf(tetrahedron()))).toEqual(DEFAULT_BUDGET);
    // 19,600 quads: 78,400 halfedges
    const large = fixtureMesh({ name: 'a torus', shapes: [['torus', 140, 140]] });
    expect(budgetFor(large)).toEqual({ reads: 7_840_000, milliseconds: 156_800, newElements: 156_800 });
  });
});

describe('a fixture', () => {
  it('has up to 20,000 faces, from shapes whose sides reach that far', () => {
    expect(fixtureMesh({ name: 'a grid', shapes: [['grid', 100, 100]] }).nFaces).toBe(20_000);
    expect(() => fixtureMesh({ name: 'a torus', shapes: [['torus', 150, 150]] })).toThrow('fixture "a torus" has 22500 faces; a fixture has at most 20000');
    expect(() => fixtureMesh({ name: 'a strip', shapes: [['strip', 151]] })).toThrow('shape strip: its arguments must be numbers up to 150 (a fixture has at most 20,000 faces)');
  });
});

describe('the comparison with the library', () => {
  it('a flipped mesh is not the unflipped one, and says which face differs', () => {
    const a = meshOf(disk(1));
    const b = a.clone();
    flipEdge(b, 0);
    expect(compareMeshes(a, a.clone())).toBeNull();
    expect(compareMeshes(b, a)).toMatch(/^your f\d+ \(v\d+ → v\d+ → v\d+\) is not a face of the library's result$/);
  });

  it('ids of the same mesh may differ; positions within a millionth may too', () => {
    const a = meshOf(cube());
    const b = a.clone();
    b.setPosition(0, ...(b.position(0).map((x) => x + 1e-9) as [number, number, number]));
    expect(compareMeshes(b, a)).toBeNull();
    b.setPosition(0, 5, 5, 5);
    expect(compareMeshes(b, a)).toBe("your v0 is at (5, 5, 5), where the library's mesh has no vertex");
  });

  it('finds each vertex near its place whichever way it moved, and none a few millionths away', () => {
    // the cube's diagonal is √3: a millionth of it is the tolerance; every vertex moved along one diagonal direction or another
    const a = meshOf(cube());
    const tolerance = 1e-6 * Math.sqrt(3);
    const moved = (by: number) => {
      const b = a.clone();
      for (const v of b.vertices()) b.setPosition(v, ...(b.position(v).map((x, axis) => x + (((v >> axis) & 1) === 1 ? by : -by) / Math.sqrt(3)) as [number, number, number]));
      return b;
    };
    expect(compareMeshes(moved(0.9 * tolerance), a)).toBeNull();
    expect(compareMeshes(moved(3 * tolerance), a)).toMatch(/where the library's mesh has no vertex$/);
  });
});

describe("an instructor's exercise file", () => {
  it('is read with its reference, and refused field by field', () => {
    const doc = { id: 'x', title: 'X', kind: 'query', answer: 'exact', task: ['t'], starter: 's', fixtures: [{ name: 'a', shapes: [['disk', 1]] }] };
    expect(parseExercise(doc, 'export default () => 1;')).toMatchObject({ id: 'x', hints: [], reference: 'export default () => 1;' });
    expect(() => parseExercise({ ...doc, kind: 'quiz' }, '')).toThrow('exercise: "kind" must be "query" or "edit"');
    expect(() => parseExercise({ ...doc, fixtures: [{ name: 'a', shapes: [['blob']] }] }, '')).toThrow();
    expect(() => parseExercise({ ...doc, fixtures: [{ name: 'a', input: 'v1', shapes: [['disk', 1]] }] }, '')).toThrow('exercise: "fixtures[0].input" must be an integer id');
    expect(() => parseExercise([], '')).toThrow('exercise: "(document)" must be a JSON object');
  });

  it('a reference given as source is run like a solution and compared with', async () => {
    const exercise = findExercise('euler-characteristic')!;
    const report = await grade('euler-characteristic', 'euler-characteristic');
    expect(report.passed).toBe(true);
    const { gradeSolution } = await import('../../src/core/practice/index.js');
    const { inProcess, solution } = await import('./helpers.js');
    const asSource = { ...exercise, reference: solution('euler-characteristic') };
    expect((await gradeSolution(asSource, solution('euler-characteristic'), inProcess)).passed).toBe(true);
    expect((await gradeSolution(asSource, solution('wrong/euler-wrong'), inProcess)).passed).toBe(false);
  });
});
