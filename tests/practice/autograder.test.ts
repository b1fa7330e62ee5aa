/**
 * The course autograder end to end, as an instructor and Gradescope use it: `autograder` writes the
 * zip of the example course (docs/examples/course), a reader written here unpacks it as Gradescope
 * does into ROOT/source, and `run_autograder` grades submissions in ROOT/submission with plain
 * Node, the bundled grader alone (no repository, no node_modules beside it).
 */
import { execFileSync } from 'node:child_process';
import { chmodSync, copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { crc32 as zlibCrc32, inflateRawSync } from 'node:zlib';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { checkNames, findExercise } from '../../src/core/practice/index.js';
import { loadCourse, parseCourse } from '../../src/cli/course.js';
import { sharePoints } from '../../src/cli/grader.js';
import { crc32, writeZip } from '../../src/cli/zip.js';
import { type CliRun, runCli } from '../cli.js';

const repo = join(import.meta.dirname, '../..');
const solutions = join(repo, 'tests/practice/solutions');

interface ZipFile {
  name: string;
  data: Uint8Array;
  mode: number;
}

/** A ZIP reader just big enough for the test: the end record, the central directory, each local header, stored or deflated data, checked against its CRC-32. */
function readZip(zip: Uint8Array): ZipFile[] {
  const view = new DataView(zip.buffer, zip.byteOffset, zip.byteLength);
  const end = zip.length - 22; // no archive comment
  expect(view.getUint32(end, true)).toBe(0x06054b50);
  const count = view.getUint16(end + 10, true);
  let at = view.getUint32(end + 16, true);
  const files: ZipFile[] = [];
  for (let i = 0; i < count; i++) {
    expect(view.getUint32(at, true)).toBe(0x02014b50);
    const method = view.getUint16(at + 10, true);
    const crc = view.getUint32(at + 16, true);
    const packed = view.getUint32(at + 20, true);
    const size = view.getUint32(at + 24, true);
    const nameLength = view.getUint16(at + 28, true);
    const skip = nameLength + view.getUint16(at + 30, true) + view.getUint16(at + 32, true);
    const mode = view.getUint32(at + 38, true) >>> 16;
    const local = view.getUint32(at + 42, true);
    const name = new TextDecoder().decode(zip.subarray(at + 46, at + 46 + nameLength));
    expect(view.getUint32(local, true)).toBe(0x04034b50);
    const start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
    const body = zip.subarray(start, start + packed);
    const data = method === 8 ? new Uint8Array(inflateRawSync(body)) : body;
    expect(data.length).toBe(size);
    expect(zlibCrc32(data)).toBe(crc);
    files.push({ name, data, mode });
    at += 46 + skip;
  }
  return files;
}

interface Results {
  score: number;
  output: string;
  tests: { name: string; score: number; max_score: number; status: string; output: string }[];
}

/** Gives `root/submission` the files (name in the submission → file of the repository), runs `run_autograder` as Gradescope would, and reads results.json. */
function runAutograder(root: string, files: Record<string, string>): Results {
  const submission = join(root, 'submission');
  rmSync(submission, { recursive: true, force: true });
  rmSync(join(root, 'results'), { recursive: true, force: true });
  mkdirSync(submission, { recursive: true });
  for (const [name, from] of Object.entries(files)) {
    mkdirSync(dirname(join(submission, name)), { recursive: true });
    copyFileSync(join(repo, from), join(submission, name));
  }
  execFileSync('sh', [join(root, 'source/run_autograder')], { cwd: root, env: { ...process.env, AUTOGRADER_ROOT: root }, encoding: 'utf8', timeout: 60_000 });
  return JSON.parse(readFileSync(join(root, 'results/results.json'), 'utf8')) as Results;
}

const points = (results: Results, exercise: string) =>
  // in hundredths, as they were shared
  results.tests
    .filter((t) => t.name.startsWith(`${exercise}: `))
    .reduce((sum, t) => ({ score: sum.score + Math.round(t.score * 100), max: sum.max + Math.round(t.max_score * 100) }), { score: 0, max: 0 });

describe('autograder: a course in a box', () => {
  let folder = '';
  let root = '';
  let files: ZipFile[] = [];
  let made: CliRun;
  let mixed: Results;
  let correct: Results;

  beforeAll(async () => {
    folder = mkdtempSync(join(tmpdir(), 'halfedge-autograder-'));
    made = await runCli('autograder', 'docs/examples/course/COURSE.json', '--out', join(folder, 'autograder.zip'));
    expect(made.stderr).toBe('');
    files = readZip(readFileSync(join(folder, 'autograder.zip')));
    // unpacked as Gradescope does, into ROOT/source, with the modes the zip gives
    root = join(folder, 'root');
    // a package.json around it that says CommonJS: the grader is a module all the same
    mkdirSync(root);
    writeFileSync(join(root, 'package.json'), '{ "type": "commonjs" }\n');
    for (const file of files) {
      const path = join(root, 'source', file.name);
      mkdirSync(dirname(path), { recursive: true });
      writeFileSync(path, file.data);
      chmodSync(path, file.mode & 0o777);
    }
    mixed = runAutograder(root, {
      'boundary-edges.js': 'docs/examples/boundary-edges/reference.js',
      'flip-edge.js': 'tests/practice/solutions/flip-edge.js',
      'split-edge.js': 'tests/practice/solutions/wrong/split-forgets-face.js',
      // no inset-vertex.js
      'collapse-edge.js': 'tests/practice/solutions/collapse-edge.js',
      'loop-subdivision.js': 'tests/practice/solutions/wrong/syntax.js',
    });
    correct = runAutograder(root, {
      'boundary-edges.js': 'docs/examples/boundary-edges/reference.js',
      'flip-edge.js': 'tests/practice/solutions/flip-edge.js',
      'split-edge.js': 'tests/practice/solutions/split-edge.js',
      // uploaded as a folder: found below the top
      'homework/inset-vertex.js': 'tests/practice/solutions/inset-vertex.js',
      'collapse-edge.js': 'tests/practice/solutions/collapse-edge.js',
      'loop-subdivision.js': 'tests/practice/solutions/loop-subdivision.js',
    });
  }, 120_000);

  afterAll(() => {
    if (folder) rmSync(folder, { recursive: true, force: true });
  });

  it('writes a zip with setup.sh and run_autograder at its root, executable, beside the grader, the course and the instructor exercise', () => {
    expect(made.status).toBe(0);
    expect(made.stdout).toContain('6 exercises, 67 tests, 30 points');
    expect(files.map((f) => f.name).sort()).toEqual([
      'course.json',
      'exercises/0-boundary-edges/exercise.json',
      'exercises/0-boundary-edges/reference.js',
      'exercises/0-boundary-edges/strip.off',
      'grader.mjs',
      'run_autograder',
      'setup.sh',
    ]);
    const mode = (name: string) => files.find((f) => f.name === name)!.mode;
    expect(mode('run_autograder')).toBe(0o100755);
    expect(mode('setup.sh')).toBe(0o100755);
    expect(mode('grader.mjs')).toBe(0o100644);
    const course = JSON.parse(new TextDecoder().decode(files.find((f) => f.name === 'course.json')!.data));
    expect(course.exercises[0]).toEqual({ exercise: 'exercises/0-boundary-edges/exercise.json', file: 'boundary-edges.js', points: 3 });
    expect(course.exercises[1]).toEqual({ id: 'flip-edge', file: 'flip-edge.js', points: 5 });
  });

  it('bundles a grader that imports nothing but Node itself', () => {
    const grader = new TextDecoder().decode(files.find((f) => f.name === 'grader.mjs')!.data);
    const imported = [...grader.matchAll(/^import\s[^'"]*["']([^'"]+)["']/gm)].map((m) => m[1]);
    expect(imported.length).toBeGreaterThan(0);
    expect(imported.every((name) => name.startsWith('node:'))).toBe(true);
    expect(grader).not.toMatch(/\brequire\(/);
  });

  it.skipIf(!hasUnzip())('writes a zip that unzip tests as sound', () => {
    expect(execFileSync('unzip', ['-tq', join(folder, 'autograder.zip')], { encoding: 'utf8' })).toContain('No errors detected');
  });

  it('scores a submission: right solutions in full, a wrong one in part, a missing and a broken file 0, with why', () => {
    expect(mixed.score).toBe(16.5);
    expect(points(mixed, 'boundary-edges')).toEqual({ score: 300, max: 300 });
    expect(points(mixed, 'flip-edge')).toEqual({ score: 500, max: 500 });
    expect(points(mixed, 'collapse-edge')).toEqual({ score: 600, max: 600 });
    // split-forgets-face leaves a face without its halfedge: every "valid mesh" fails, with the write that broke it
    const split = mixed.tests.filter((t) => t.name.startsWith('split-edge: '));
    expect(split.map((t) => t.status)).toEqual(Array.from({ length: 6 }, () => ['failed', 'passed']).flat());
    // 5 points over 12 checks: 500 hundredths are 41 each and 8 over, which go to the first 8
    expect(split.map((t) => t.max_score)).toEqual([...Array(8).fill(0.42), ...Array(4).fill(0.41)]);
    expect(split[0].output).toMatch(/breaks an invariant: .*, since write \d+/);
    const poke = mixed.tests.filter((t) => t.name.startsWith('inset-vertex: '));
    expect(poke).toHaveLength(checkNames(findExercise('inset-vertex')!).length);
    for (const test of poke) {
      expect(test).toMatchObject({ score: 0, status: 'failed' });
      expect(test.output).toContain("your submission has no file named inset-vertex.js: submit this exercise's solution as inset-vertex.js");
    }
    const loop = mixed.tests.filter((t) => t.name.startsWith('loop-subdivision: '));
    expect(loop.every((t) => t.score === 0 && t.output === 'loop-subdivision.js: line 2: syntax error: Unexpected token (column 31)')).toBe(true);
    expect(mixed.output.split('\n')).toEqual([
      'boundary-edges (boundary-edges.js): 3 of 3 points',
      'flip-edge (flip-edge.js): 5 of 5 points',
      'split-edge (split-edge.js): 2.5 of 5 points',
      expect.stringMatching(/^inset-vertex \(inset-vertex\.js\): 0 of 4 points; your submission has no file named inset-vertex\.js.*\(it has boundary-edges\.js, collapse-edge\.js/),
      'collapse-edge (collapse-edge.js): 6 of 6 points',
      'loop-subdivision (loop-subdivision.js): 0 of 7 points; loop-subdivision.js: line 2: syntax error: Unexpected token (column 31)',
    ]);
  });

  it('gives every test the same name and max_score whatever is submitted, adding up to the course points', () => {
    expect(correct.tests.map((t) => [t.name, t.max_score])).toEqual(mixed.tests.map((t) => [t.name, t.max_score]));
    expect(correct.tests.every((t) => t.status === 'passed')).toBe(true);
    expect(correct.score).toBe(30);
    const course = JSON.parse(readFileSync(join(repo, 'docs/examples/course/COURSE.json'), 'utf8')) as { exercises: { id?: string; points: number }[] };
    for (const { id, points: worth } of course.exercises) if (id) expect(points(correct, id).max).toBe(worth * 100);
    expect(correct.output).toContain('inset-vertex (inset-vertex.js): 4 of 4 points; graded homework/inset-vertex.js');
  });

  it('has a setup.sh that bash reads, and that does nothing where Node.js 20 or later is installed', () => {
    const setup = join(root, 'source/setup.sh');
    execFileSync('bash', ['-n', setup]);
    // apt-get and curl stand in for the network: called, they fail the test
    const stubs = join(folder, 'stubs');
    mkdirSync(stubs, { recursive: true });
    for (const tool of ['apt-get', 'curl']) {
      writeFileSync(join(stubs, tool), '#!/bin/sh\necho "$0 was called" >&2\nexit 99\n');
      chmodSync(join(stubs, tool), 0o755);
    }
    const run = execFileSync('bash', [setup], { env: { ...process.env, PATH: `${stubs}:${dirname(process.execPath)}:/usr/bin:/bin` }, encoding: 'utf8' });
    expect(run).toBe('');
  });
});

describe('autograder: the course file', () => {
  const bad = (doc: unknown) => () => parseCourse(doc, 'COURSE.json');
  it.each([
    [[], 'COURSE.json: (document): must be a JSON object'],
    [{}, 'COURSE.json: exercises: must be a non-empty list of exercises'],
    [{ exercises: [], title: 'x' }, 'COURSE.json: title: unknown field'],
    [{ exercises: [7] }, 'COURSE.json: exercises[0]: must be an object'],
    [{ exercises: [{ file: 'a.js', points: 1 }] }, 'COURSE.json: exercises[0]: give "id" (a built-in exercise) or "exercise"'],
    [{ exercises: [{ id: 'flip-edge', exercise: 'x.json', file: 'a.js', points: 1 }] }, 'COURSE.json: exercises[0]: give "id"'],
    [{ exercises: [{ id: 'flip-edges', file: 'a.js', points: 1 }] }, 'COURSE.json: exercises[0].id: unknown exercise "flip-edges" (built in: '],
    [{ exercises: [{ exercise: 'x.js', file: 'a.js', points: 1 }] }, 'COURSE.json: exercises[0].exercise: must be the path of an exercise .json file'],
    [{ exercises: [{ id: 'flip-edge', file: 'hw/a.js', points: 1 }] }, 'COURSE.json: exercises[0].file: must be a file name such as "flip-edge.js", without a folder'],
    [{ exercises: [{ id: 'flip-edge', points: 1 }] }, 'COURSE.json: exercises[0].file: must be a file name'],
    [{ exercises: [{ id: 'flip-edge', file: 'a.js', points: 1 }, { id: 'split-edge', file: 'a.js', points: 1 }] }, 'COURSE.json: exercises[1].file: "a.js" is already the file of exercises[0]'],
    [{ exercises: [{ id: 'flip-edge', file: 'a.js', points: 1 }, { id: 'split-edge', file: 'b.js', points: 1 }, { id: 'inset-vertex', file: 'c.js', points: -2 }] }, 'COURSE.json: exercises[2].points: must be a positive number'],
    [{ exercises: [{ id: 'flip-edge', file: 'a.js', points: '6' }] }, 'COURSE.json: exercises[0].points: must be a positive number'],
    [{ exercises: [{ id: 'flip-edge', file: 'a.js', points: 0.125 }] }, 'COURSE.json: exercises[0].points: must be a positive number in hundredths at most'],
    [{ exercises: [{ id: 'flip-edge', file: 'a.js', pionts: 6 }] }, 'COURSE.json: exercises[0].pionts: unknown field'],
  ])('refuses %j with its place: %s', (doc, message) => {
    expect(bad(doc)).toThrow(message);
  });

  it('takes the example course as written', () => {
    const course = parseCourse(JSON.parse(readFileSync(join(repo, 'docs/examples/course/COURSE.json'), 'utf8')), 'COURSE.json');
    expect(course.exercises.reduce((sum, e) => sum + e.points, 0)).toBe(30);
  });

  it('names the course file and the place for an exercise file it cannot read, or a course that is not JSON', () => {
    const folder = mkdtempSync(join(tmpdir(), 'halfedge-course-'));
    try {
      const course = join(folder, 'COURSE.json');
      writeFileSync(course, JSON.stringify({ exercises: [{ id: 'flip-edge', file: 'a.js', points: 2 }, { exercise: 'mine/exercise.json', file: 'b.js', points: 2 }] }));
      expect(() => loadCourse(course)).toThrow(`${course}: exercises[1].exercise: cannot read ${join(folder, 'mine/exercise.json')}: ENOENT`);
      mkdirSync(join(folder, 'mine'));
      writeFileSync(join(folder, 'mine/exercise.json'), JSON.stringify({ ...JSON.parse(readFileSync(join(repo, 'docs/examples/boundary-edges/exercise.json'), 'utf8')), reference: '../reference.js' }));
      writeFileSync(join(folder, 'reference.js'), 'export default function () { return 0; }\n');
      expect(() => loadCourse(course)).toThrow(`${course}: exercises[1].exercise: cannot read ${join(folder, 'mine/strip.off')}: ENOENT`);
      copyFileSync(join(repo, 'docs/examples/boundary-edges/strip.off'), join(folder, 'mine/strip.off'));
      expect(() => loadCourse(course)).toThrow(`${course}: exercises[1].exercise: ${join(folder, 'mine/exercise.json')}: "../reference.js" must be beside the exercise file or in a folder below it`);
      writeFileSync(course, JSON.stringify({ exercises: [{ id: 'flip-edge', file: 'a.js', points: 0.05 }] }));
      expect(() => loadCourse(course)).toThrow(`${course}: exercises[0].points: 0.05 cannot be shared among the exercise's 16 checks in hundredths: give it 0.16 or more`);
      writeFileSync(course, '{ "exercises": [ }');
      expect(() => loadCourse(course)).toThrow(`${course}: not JSON: `);
    } finally {
      rmSync(folder, { recursive: true, force: true });
    }
  });

  it('exits 2 with one located line on stderr for a bad course, before bundling anything', async () => {
    const folder = mkdtempSync(join(tmpdir(), 'halfedge-course-'));
    try {
      const course = join(folder, 'COURSE.json');
      writeFileSync(course, JSON.stringify({ exercises: [{ id: 'flip-edge', file: 'a.js', points: 2 }, { id: 'split-edge', file: 'b.js', points: 1 }, { id: 'inset-vertex', file: 'c.js', points: 0 }] }));
      const run = await runCli('autograder', course, '--out', join(folder, 'a.zip'));
      expect(run.status).toBe(2);
      expect(run.stderr).toBe(`halfedge-lab: ${course}: exercises[2].points: must be a positive number\n`);
      expect(run.stdout).toBe('');
    } finally {
      rmSync(folder, { recursive: true, force: true });
    }
  });
});

describe('autograder: points and the ZIP writer', () => {
  it('shares points among checks in hundredths that add up exactly', () => {
    expect(sharePoints(5, 6)).toEqual([84, 84, 83, 83, 83, 83]);
    expect(sharePoints(2.5, 4)).toEqual([63, 63, 62, 62]);
    expect(sharePoints(6, 10).reduce((a, b) => a + b)).toBe(600);
  });

  it('computes the CRC-32 of ZIP', () => {
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926);
    expect(crc32(new Uint8Array())).toBe(0);
  });

  it('writes entries that read back byte for byte, stored or deflated, with their modes', () => {
    const random = new Uint8Array(300).map((_, i) => (i * 7919 + 13) % 251); // does not shrink much
    const text = new TextEncoder().encode('halfedge '.repeat(200)); // shrinks
    const files = readZip(writeZip([{ name: 'a/random.bin', data: random }, { name: 'run', data: text, mode: 0o755 }, { name: 'empty', data: new Uint8Array() }]));
    expect(files.map((f) => [f.name, f.mode & 0o777, f.data.length])).toEqual([['a/random.bin', 0o644, 300], ['run', 0o755, 1800], ['empty', 0o644, 0]]);
    expect(files[0].data).toEqual(random);
    expect(files[1].data).toEqual(text);
  });

  it('refuses names that would unpack outside the folder, or twice', () => {
    const data = new Uint8Array(1);
    for (const name of ['../x', '/etc/x', 'a/../../x', 'a\\b', '']) expect(() => writeZip([{ name, data }])).toThrow(RangeError);
    expect(() => writeZip([{ name: 'a', data }, { name: 'a', data }])).toThrow('two ZIP entries are named "a"');
  });
});

function hasUnzip(): boolean {
  try {
    execFileSync('unzip', ['-v'], { stdio: 'ignore' });
    return true;
  } catch {
    return false;
  }
}
