import { readersTarget, corpusTarget } from './fuzz/readers.js';
const N = Number(process.argv[2] ?? 2000);
for (const t of [readersTarget, corpusTarget]) {
  const t0 = performance.now();
  const counts: Record<string, number> = {};
  const classes = new Map<string, string>();
  for (let i = 0; i < N; i++) {
    const o = t.runCase(1, i);
    counts[o.kind] = (counts[o.kind] ?? 0) + 1;
    if (o.kind === 'failure') { const k = o.reason.split('\n')[0].replace(/\d+/g, 'N').slice(0, 110); if (!classes.has(k)) classes.set(k, `#${i} ${o.input.slice(0, 200)}`); }
  }
  console.log(t.name, counts, ((performance.now() - t0) / N).toFixed(3), 'ms/case');
  for (const [k, v] of classes) console.log('  ', k, '\n      ', v);
}
