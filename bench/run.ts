/**
 * `npm run bench [-- --json] [--only NAME] [--sizes 10000,100000,1000000]`
 * `npm run bench -- --native [--json] [--rounds 3] [--only OP] [--small]`: beside CGAL and
 * OpenMesh, see `native.ts`.
 *
 * Prints one row per case (or, with --json, one JSON object per line): our time, the peer's time
 * in the same run, their ratio, and the peak memory of each. Every side of every case runs in a
 * child process of this script (`--child CASE SIZE SIDE`). What is timed is the built package
 * (`library.ts`): the library is built first, so a run always measures the code as it stands.
 */
import { execFileSync } from 'node:child_process';
import { type BenchCase, type BenchResult, combine, measure, type SideResult } from './harness.js';
import { runNativeComparison } from './native.js';

const args = process.argv.slice(2);
const valueOf = (flag: string) => {
  const i = args.indexOf(flag);
  return i >= 0 ? args[i + 1] : undefined;
};

const childAt = args.indexOf('--child');
// build the package the cases time (its output to stderr, so that --json's lines stay alone on stdout)
if (childAt < 0) execFileSync('npm', ['run', '--silent', 'build:lib'], { stdio: ['ignore', 2, 2] });
// the cases load the built package, so they are loaded after it is built
const caseGroups: Array<(sizes: number[]) => BenchCase[]> = await Promise.all([
  import('./cases/build.js').then((m) => m.buildCases),
  import('./cases/parse.js').then((m) => m.parseCases),
  import('./cases/subdivision.js').then((m) => m.subdivisionCases),
  import('./cases/cut.js').then((m) => m.cutCases),
  import('./cases/smooth-decimate.js').then((m) => m.smoothDecimateCases),
  import('./cases/practice.js').then((m) => m.practiceCases),
]);
if (args.includes('--native')) {
  await runNativeComparison(args);
} else if (childAt >= 0) {
  // one side of one case, in this process: print what it measured
  const [name, size, side] = args.slice(childAt + 1);
  const bench = caseGroups.flatMap((group) => group([Number(size)])).find((c) => c.case === name)!;
  console.log(JSON.stringify(await measure(bench, side as 'ours' | 'peer')));
} else {
  const json = args.includes('--json');
  const only = valueOf('--only');
  const sizes = (valueOf('--sizes') ?? '10000,100000,1000000').split(',').map(Number);
  if (!json) console.log(header());
  for (const size of sizes) {
    for (const bench of caseGroups.flatMap((group) => group([size]))) {
      if (only && !bench.case.includes(only)) continue;
      const ours = runSide(bench, size, 'ours');
      const peer = bench.peer ? runSide(bench, size, 'peer') : null;
      const result = combine(bench, ours, peer);
      console.log(json ? JSON.stringify(result) : row(result));
    }
  }
}

/** Runs one side of a case in a child process of this same script. */
function runSide(bench: BenchCase, size: number, side: 'ours' | 'peer'): SideResult {
  const output = execFileSync(process.execPath, [...process.execArgv, '--expose-gc', process.argv[1]!, '--child', bench.case, String(size), side], {
    encoding: 'utf8',
    maxBuffer: 1 << 20,
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  return JSON.parse(output.trim().split('\n').at(-1)!) as SideResult;
}

function header(): string {
  return ['case'.padEnd(24), 'faces'.padStart(9), 'ms'.padStart(9), '  peer'.padEnd(22), 'peer ms'.padStart(9), 'ratio'.padStart(7), 'peak MB'.padStart(9), 'peer MB'.padStart(9), '  notes'].join('');
}

function row(r: BenchResult): string {
  return [
    r.case.padEnd(24),
    String(r.size).padStart(9),
    r.ms.toFixed(1).padStart(9),
    ('  ' + (r.peer ?? '-')).padEnd(22),
    (r.peerMs?.toFixed(1) ?? '-').padStart(9),
    (r.ratio?.toFixed(3) ?? '-').padStart(7),
    String(r.peakMB).padStart(9),
    String(r.peerPeakMB ?? '-').padStart(9),
    r.bytesPerFace !== undefined ? `  ${r.bytesPerFace} B/face` : '',
  ].join('');
}
