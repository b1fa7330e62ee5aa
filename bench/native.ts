/**
 * `npm run bench -- --native [--json] [--rounds 3] [--only OP] [--small]`
 *
 * Our library beside CGAL and OpenMesh (`../shared/native-peers`, see its README) on the meshes
 * that folder generates, read from the same files. Case by case, each round runs our side and then
 * the natives' (`run.sh OP MESH`), so a drift in the machine's speed hits all of them alike; the
 * figure of each side is the median of its rounds. Every side runs in a process of its own with
 * the natives' policy: the input prepared outside the timed region, one warm-up, then the median
 * of 5 runs (3 when the warm-up took over 3 s, 1 over 30 s); our side is `native-child.mjs`, on
 * the library as built (`dist/`), through its Node entry; for the operations that hand work to a
 * helper thread there, a third side runs ours on one thread (`oneThread` in the JSON). Peak
 * memory is each process's largest resident set. Decimation also runs meshoptimizer's `simplify`
 * (WebAssembly) to the same face count, and for ours and meshoptimizer's says how far the result
 * strays from the input (`distance`: the largest and the mean distance from the input's vertices
 * to the result's surface). Remeshing runs CGAL's `isotropic_remeshing` and ours to the target the
 * issue states (the input's mean edge length times 0.7 on the icosphere, 0.5 on the torus, whose
 * quads both sides triangulate alike first, untimed), 3 iterations, and gives each side's edge
 * lengths after (`spread`: min, mean, max, and the share within 4/5 … 4/3 of the target).
 *
 * Without the native peers set up (`run.sh setup`), it says so and prints no native rows.
 */
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { round } from './harness.js';

const here = dirname(fileURLToPath(import.meta.url));
const peersDir = resolve(process.env.NATIVE_PEERS ?? join(here, '../../shared/native-peers'));
const peersEnv = process.env.NATIVE_PEERS_ENV ?? '/tmp/native-peers';

type NativeOp = 'build' | 'read' | 'loop' | 'cc' | 'clip_cap' | 'decimate' | 'remesh';

/** One comparison: an operation of `run.sh` on one of its meshes. */
interface NativeCase {
  op: NativeOp;
  mesh: string;
  /** Remeshing: the target edge length as a multiple of the input's mean (`REMESH_TARGET_FACTOR`). */
  factor?: number;
}

/** The operations whose default call in Node hands work to a helper thread: also run on one thread. */
const threaded: NativeOp[] = ['loop', 'cc'];

const allCases: NativeCase[] = [
  { op: 'build', mesh: 'ico_1280k' },
  { op: 'build', mesh: 'torus_1m' },
  { op: 'read', mesh: 'ico_1280k' },
  { op: 'read', mesh: 'ico_1280k.ply' },
  { op: 'read', mesh: 'ico_1280k.off' },
  { op: 'loop', mesh: 'ico_1280k' },
  { op: 'cc', mesh: 'ico_1280k' },
  { op: 'cc', mesh: 'torus_1m' },
  { op: 'clip_cap', mesh: 'ico_1280k' },
  { op: 'decimate', mesh: 'ico_1280k' },
  { op: 'remesh', mesh: 'ico_80k', factor: 0.7 },
  { op: 'remesh', mesh: 'torus_100k', factor: 0.5 },
];

/** What one process measured: ours, meshoptimizer's, or a line of `run.sh`. */
interface Measured {
  lib: string;
  ms: number;
  peakMB: number;
  /** Faces of the input (ours only) and of the result. */
  inFaces?: number;
  outFaces: number;
  /** Decimation, ours and meshoptimizer's: how far the result strays from the input (`surface-distance.mjs`). */
  distance?: { max: number; mean: number };
  /** Remeshing: the result's edge lengths, and the share within 4/5 … 4/3 of the target. */
  spread?: Spread;
}

interface Spread {
  min: number;
  mean: number;
  max: number;
  within: number;
}

/** The edge lengths CGAL's note gives after remeshing ("length min … mean … max …, within 4/5..4/3 of the target …"). */
function spreadOfNote(note: string | undefined): Spread | undefined {
  const match = /length min (\S+) mean (\S+) max (\S+), within 4\/5\.\.4\/3 of the target (\S+);/.exec(note ?? '');
  if (!match) return undefined;
  const [min, mean, max, within] = match.slice(1).map(Number);
  return { min: min!, mean: mean!, max: max!, within: within! };
}

/** The environment of both sides of a case: remeshing's target factor. */
function caseEnvironment(c: NativeCase): NodeJS.ProcessEnv {
  return c.factor === undefined ? process.env : { ...process.env, REMESH_TARGET_FACTOR: String(c.factor) };
}

/** Whether `run.sh` can run without installing anything. */
function nativePeersReady(): boolean {
  return existsSync(join(peersDir, 'run.sh')) && existsSync(join(peersEnv, 'bin/cgal_bench')) && existsSync(join(peersEnv, 'bin/openmesh_bench'));
}

function meshPath(mesh: string): string {
  return execFileSync(join(peersDir, 'run.sh'), ['mesh-path', mesh], { encoding: 'utf8' }).trim();
}

function runNatives(c: NativeCase): Measured[] {
  const output = execFileSync(join(peersDir, 'run.sh'), [c.op, c.mesh], {
    encoding: 'utf8',
    stdio: ['ignore', 'pipe', 'ignore'],
    maxBuffer: 1 << 20,
    env: caseEnvironment(c),
  });
  return output
    .trim()
    .split('\n')
    .map((line) => JSON.parse(line) as { lib: string; median_ms?: number; self_maxrss_kb?: number; out_faces?: number; skip?: string; note?: string })
    .filter((line) => line.skip === undefined && line.median_ms !== undefined)
    .map((line) => {
      const spread = c.op === 'remesh' ? spreadOfNote(line.note) : undefined;
      return { lib: line.lib, ms: line.median_ms!, peakMB: Math.round(line.self_maxrss_kb! / 1024), outFaces: line.out_faces!, ...(spread ? { spread } : {}) };
    });
}

/**
 * Our side in plain Node on the built library, as a user's program would run it (a loader that
 * compiles TypeScript on the fly would add its own memory to the peak).
 */
function runOurs(c: NativeCase, file: string, lib: 'ours' | 'ours-one-thread' | 'meshoptimizer'): Measured {
  const output = execFileSync(process.execPath, ['--expose-gc', join(here, 'native-child.mjs'), c.op, file, lib], {
    encoding: 'utf8',
    maxBuffer: 1 << 20,
    stdio: ['ignore', 'pipe', 'inherit'],
    env: caseEnvironment(c),
  });
  return JSON.parse(output.trim().split('\n').at(-1)!) as Measured;
}

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  const n = sorted.length;
  return n % 2 ? sorted[n >> 1]! : (sorted[n / 2 - 1]! + sorted[n / 2]!) / 2;
}

/** The median of each library's rounds. */
function medians(rounds: Measured[][]): Measured[] {
  const libs = [...new Set(rounds.flat().map((m) => m.lib))];
  return libs.map((lib) => {
    const runs = rounds.flat().filter((m) => m.lib === lib);
    return { ...runs[0]!, ms: round(median(runs.map((m) => m.ms))), peakMB: Math.round(median(runs.map((m) => m.peakMB))) };
  });
}

export async function runNativeComparison(args: string[]): Promise<void> {
  const valueOf = (flag: string) => {
    const i = args.indexOf(flag);
    return i >= 0 ? args[i + 1] : undefined;
  };
  const json = args.includes('--json');
  if (!nativePeersReady()) {
    console.log(`native peers not set up (${peersDir}/run.sh setup, into ${peersEnv}): no native rows`);
    return;
  }
  execFileSync('npx', ['tsc', '-p', 'tsconfig.lib.json'], { cwd: join(here, '..'), stdio: 'inherit' });
  const rounds = Number(valueOf('--rounds') ?? 3);
  const only = valueOf('--only');
  // --small: the same cases a size down (a quick look; the targets are stated at the largest)
  const small = args.includes('--small');
  const cases = allCases
    .filter((c) => !only || c.op === only)
    .map((c) => (small ? { op: c.op, mesh: c.mesh.replace('ico_1280k', 'ico_320k').replace('torus_1m', 'torus_100k') } : c));
  console.error(`load average at start: ${readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ')}`);
  if (!json) console.log(header());
  for (const c of cases) {
    const file = meshPath(c.mesh);
    const perRound: Measured[][] = [];
    for (let r = 0; r < rounds; r++) {
      const sides = [runOurs(c, file, 'ours'), ...runNatives(c)];
      if (threaded.includes(c.op)) sides.push(runOurs(c, file, 'ours-one-thread'));
      if (c.op === 'decimate') sides.push(runOurs(c, file, 'meshoptimizer'));
      perRound.push(sides);
    }
    const [ours, ...others] = medians(perRound);
    const oneThread = others.find((p) => p.lib === 'ours-one-thread');
    const peers = others.filter((p) => p !== oneThread);
    const natives = peers.filter((p) => p.lib !== 'meshoptimizer');
    const best = natives.reduce((a, b) => (b.ms < a.ms ? b : a));
    const bestMemory = Math.min(...natives.map((p) => p.peakMB));
    const result = {
      case: `native-${c.op}-${c.mesh}${c.factor === undefined ? '' : `-x${c.factor}`}`,
      size: ours!.inFaces!,
      ms: ours!.ms,
      peer: best.lib,
      peerMs: best.ms,
      ratio: round(ours!.ms / best.ms, 3),
      peakMB: ours!.peakMB,
      peerPeakMB: bestMemory,
      memoryRatio: round(ours!.peakMB / bestMemory, 2),
      peers: peers.map((p) => ({ ...p, ratio: round(ours!.ms / p.ms, 3) })),
      ...(oneThread ? { oneThread: { ms: oneThread.ms, ratio: round(oneThread.ms / best.ms, 3), peakMB: oneThread.peakMB } } : {}),
      outFaces: ours!.outFaces,
      ...(ours!.distance ? { distance: ours!.distance } : {}),
      ...(ours!.spread ? { spread: ours!.spread } : {}),
    };
    console.log(json ? JSON.stringify(result) : row(result));
  }
  console.error(`load average at end: ${readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ')}`);
}

function header(): string {
  return ['case'.padEnd(30), 'faces'.padStart(9), 'ms'.padStart(9), '  best native'.padEnd(14), 'its ms'.padStart(9), 'ratio'.padStart(7), 'MB'.padStart(6), 'its MB'.padStart(7), '  others'].join('');
}

function row(r: {
  case: string;
  size: number;
  ms: number;
  peer: string;
  peerMs: number;
  ratio: number;
  peakMB: number;
  peerPeakMB: number;
  peers: Array<Measured & { ratio: number }>;
  oneThread?: { ms: number; ratio: number; peakMB: number };
  distance?: Measured['distance'];
  spread?: Spread;
}): string {
  return [
    r.case.padEnd(30),
    String(r.size).padStart(9),
    r.ms.toFixed(0).padStart(9),
    ('  ' + r.peer).padEnd(14),
    r.peerMs.toFixed(0).padStart(9),
    r.ratio.toFixed(2).padStart(7),
    String(r.peakMB).padStart(6),
    String(r.peerPeakMB).padStart(7),
    '  ' + r.peers.map((p) => `${p.lib} ${p.ms.toFixed(0)} ms ${p.peakMB} MB (×${p.ratio.toFixed(2)})${strays(p)}${lengths(p)}`).join(', '),
    r.distance ? `; ours${strays(r)}` : '',
    r.spread ? `; ours${lengths(r)}` : '',
    r.oneThread ? `; ours on one thread ${r.oneThread.ms.toFixed(0)} ms ${r.oneThread.peakMB} MB (×${r.oneThread.ratio.toFixed(2)})` : '',
  ].join('');
}

/** " edges min … mean … max …, within 4/5…4/3 L …" for a side that remeshed, else nothing. */
function lengths(m: { spread?: Spread }): string {
  const s = m.spread;
  return s ? ` edges min ${s.min} mean ${s.mean} max ${s.max}, within 4/5…4/3 L ${s.within}` : '';
}

/** " strays max … mean …" for a side that measured it, else nothing. */
function strays(m: { distance?: { max: number; mean: number } }): string {
  return m.distance ? ` strays max ${m.distance.max.toExponential(2)} mean ${m.distance.mean.toExponential(2)}` : '';
}
