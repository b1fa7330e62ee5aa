/**
 * The fuzz runner sees what a case cannot report itself: a hang (its watchdog) and a crash (the
 * child's death), each with its case index, and goes on with the next case in a new child.
 */
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { describe, expect, it } from 'vitest';

const root = path.resolve(import.meta.dirname, '../..');

function runFuzz(args: string[]) {
  return spawnSync(process.execPath, ['--import', 'tsx', 'fuzz/run.ts', ...args], { cwd: root, encoding: 'utf8', timeout: 60_000 });
}

describe('npm run fuzz', () => {
  it('reports a failure, a hang and a crash by case index, runs every other case, and exits 1', () => {
    const run = runFuzz(['--target-module', 'tests/fuzz/planted-targets.ts', '--count', '8', '--jobs', '1', '--timeout-ms', '1500', '--json']);
    expect(run.status).toBe(1);
    const summary = JSON.parse(run.stdout.trim());
    expect(summary).toMatchObject({ target: 'planted', cases: 8, accepted: 4, refused: 1 }); // 0, 2, 4, 6 and 7
    expect(summary.failures.map((f: { index: number; reason: string }) => [f.index, f.reason.split(':')[0]])).toEqual([
      [1, 'planted failure'],
      [3, 'hang'],
      [5, 'crash'],
    ]);
  });

  it('replays one case in the process and prints it', () => {
    const run = runFuzz(['--target-module', 'tests/fuzz/planted-targets.ts', '--only', 'planted', '--replay', '1']);
    expect(run.status).toBe(1);
    expect(JSON.parse(run.stdout)).toEqual({ target: 'planted', seed: 1, index: 1, kind: 'failure', reason: 'planted failure', input: 'case 1' });
  });

  it('refuses an unknown target by name, listing the known ones', () => {
    const run = runFuzz(['--only', 'nothing', '--count', '1']);
    expect(run.status).toBe(2);
    expect(run.stderr).toContain("fuzz: no target named 'nothing' (targets: readers, corpus, edits, gltf)");
  });
});
