/**
 * `npm run bench [-- --json] [--only NAME] [--sizes 10000,100000]`
 *
 * Prints one row per case (or, with --json, one JSON object per line): our time, the peer's time
 * in the same run, and their ratio.
 */
import { type BenchCase, runCase } from './harness.js';
import { buildCases } from './cases/build.js';
import { cutCases } from './cases/cut.js';
import { parseCases } from './cases/parse.js';
import { subdivisionCases } from './cases/subdivision.js';

const caseGroups: Array<(sizes: number[]) => BenchCase[]> = [buildCases, parseCases, subdivisionCases, cutCases];

const args = process.argv.slice(2);
const json = args.includes('--json');
const only = valueOf('--only');
const sizes = (valueOf('--sizes') ?? '10000,100000,1000000').split(',').map(Number);

function valueOf(flag: string): string | undefined {
  const i = args.indexOf(flag);
  return i >= 0 ? args[i + 1] : undefined;
}

const cases = caseGroups.flatMap((group) => group(sizes)).filter((c) => !only || c.case.includes(only));
if (!json) {
  console.log('case'.padEnd(28) + 'size'.padStart(10) + 'ms'.padStart(10) + '  peer'.padEnd(24) + 'peer ms'.padStart(10) + 'ratio'.padStart(8) + '  notes');
}
for (const bench of cases) {
  const result = await runCase(bench);
  if (json) {
    console.log(JSON.stringify(result));
  } else {
    const notes = [
      result.bytesPerFace !== undefined ? `${result.bytesPerFace} B/face` : '',
      `peak RSS ${result.peakRssMB} MB`,
    ].filter(Boolean);
    console.log(
      result.case.padEnd(28) +
        String(result.size).padStart(10) +
        result.ms.toFixed(1).padStart(10) +
        ('  ' + (result.peer ?? '-')).padEnd(24) +
        (result.peerMs?.toFixed(1) ?? '-').padStart(10) +
        (result.ratio?.toFixed(2) ?? '-').padStart(8) +
        '  ' +
        notes.join(', '),
    );
  }
}
