/**
 * The `grade` command end to end, as an instructor runs it: a child process, whose solutions run in
 * a locked-down worker thread with a memory limit. Each case is a real process (about a second).
 */
import { describe, expect, it } from 'vitest';
import { runCli } from '../cli.js';

const grade = (...args: string[]) => runCli('grade', ...args);

const wrong = (name: string) => `tests/practice/solutions/wrong/${name}.js`;

describe('grade on the command line', () => {
  it('exits 0 when every check passes, and prints a Gradescope results.json with --json', async () => {
    const { status, stdout } = await grade('collapse-edge', 'tests/practice/solutions/collapse-edge.js', '--json');
    expect(status).toBe(0);
    const results = JSON.parse(stdout);
    expect(results.score).toBe(16);
    expect(results.max_score).toBe(16);
    expect(results.tests[0]).toEqual({ name: 'an edge inside a disk: valid mesh', score: 1, max_score: 1, status: 'passed', output: 'passed' });
  });

  it('exits 1 with the failing checks, the broken invariant and its line', async () => {
    const { status, stdout } = await grade('flip-edge', wrong('flip-forgets-vertex'), '--json');
    expect(status).toBe(1);
    const results = JSON.parse(stdout);
    expect(results.score).toBeLessThan(results.max_score);
    const failed = results.tests.filter((t: { status: string }) => t.status === 'failed');
    expect(failed[0].output).toMatch(/does not start at v\d+, since write \d+, origin\(h\d+\) = v\d+ at line 2[34]/);
  });

  it('exits 2 with one located line when the solution cannot load', async () => {
    const syntax = await grade('vertex-degree', wrong('syntax'));
    expect(syntax.status).toBe(2);
    expect(syntax.stderr.trim()).toBe('halfedge-lab: tests/practice/solutions/wrong/syntax.js: line 2: syntax error: Unexpected token (column 31)');
    const imports = await grade('vertex-degree', wrong('imports'));
    expect(imports.status).toBe(2);
    expect(imports.stderr).toContain('line 1: a solution cannot import anything');
    expect((await grade('no-such-exercise', wrong('syntax'))).stderr).toContain("unknown exercise 'no-such-exercise'");
  });

  it('gives a solution that cannot load the same tests and max_score as one that runs, each failed with why', async () => {
    const runs = JSON.parse((await grade('collapse-edge', 'tests/practice/solutions/collapse-edge.js', '--json')).stdout);
    const refused = await grade('collapse-edge', wrong('syntax'), '--json');
    expect(refused.status).toBe(2);
    const results = JSON.parse(refused.stdout);
    expect(results.max_score).toBe(runs.max_score);
    expect(results.score).toBe(0);
    expect(results.tests.map((t: { name: string }) => t.name)).toEqual(runs.tests.map((t: { name: string }) => t.name));
    expect(results.tests[0].output).toContain('syntax error');
  });

  it('lists every built-in exercise id, one per line, with --list', async () => {
    const { status, stdout } = await grade('--list');
    expect(status).toBe(0);
    const ids = stdout.trim().split('\n');
    expect(ids).toContain('flip-edge');
    expect(ids).toContain('collapse-edge');
    for (const id of ['inset-vertex', 'extrude-face', 'bevel-vertex', 'bevel-edge', 'dissolve-edge', 'dissolve-vertex', 'collapse-face', 'make-boundary', 'weld-edges', 'triangulate', 'catmull-clark']) {
      expect(ids).toContain(id);
    }
    expect(new Set(ids).size).toBe(ids.length);
  });

  it('grades poke-face, the older id of inset-vertex, as inset-vertex', async () => {
    const { status, stdout } = await grade('poke-face', 'tests/practice/solutions/inset-vertex.js');
    expect(status).toBe(0);
    expect(stdout).toContain('12 of 12 checks pass; 12 of 12 points');
  });

  it('scores a hard case refused cleanly 0.8 a check in results.json, out of the same max_score, and exits 1', async () => {
    const { status, stdout } = await grade('bevel-vertex', wrong('bevel-refuses-boundary'), '--json');
    expect(status).toBe(1);
    const results = JSON.parse(stdout);
    expect(results.max_score).toBe(14);
    expect(results.score).toBe(13.2);
    expect(results.tests.filter((t: { score: number }) => t.score === 0.8)).toHaveLength(4);
  });

  it('stops code that never returns within the time limit, and does not run the rest', async () => {
    const { status, stdout, ms } = await grade('vertex-degree', wrong('spin'));
    expect(status).toBe(1);
    expect(ms).toBeLessThan(15_000);
    expect(stdout).toContain('your code ran for 2.5 s without returning and without reading the mesh');
    expect(stdout).toContain('not run: your code did not return on an earlier fixture');
  });

  it('stops code that allocates without bound at the memory limit', async () => {
    const { status, stdout } = await grade('vertex-degree', wrong('allocates'));
    expect(status).toBe(1);
    // the sandbox's count of its arrays, or the worker thread's own limit, whichever comes first,
    // stops the first fixture; on a busy machine a later one may reach the clock before 256 MB
    const firstStop = stdout.split('\n').find((line) => line.trim().startsWith('stopped:'));
    expect(firstStop).toMatch(/used more than 256 MB of memory/);
  });

  it('tells code that reaches for the page or the network the line it did so', async () => {
    expect((await grade('vertex-degree', wrong('document'))).stdout).toContain('your code threw ReferenceError at line 2: document is not defined');
    expect((await grade('vertex-degree', wrong('fetch'))).stdout).toContain('your code threw Error at line 2: fetch is not available to a solution');
  });

  it("grades against an instructor's exercise file (the one docs/practice.md shows)", async () => {
    const { status, stdout } = await grade('docs/examples/boundary-edges/exercise.json', 'docs/examples/boundary-edges/reference.js');
    expect(status).toBe(0);
    expect(stdout).toContain('pass  a strip read from a file: answer');
    const wrongAnswer = await grade('docs/examples/boundary-edges/exercise.json', 'tests/practice/solutions/euler-characteristic.js');
    expect(wrongAnswer.status).toBe(1);
  });
});
