/**
 * The benchmark harness. A case times our code and, where one exists, a JavaScript peer doing the
 * same job on the same input in the same run, so the ratio means something on a shared machine
 * whose absolute speed drifts. Times are the median of several runs after a warm-up.
 *
 * Each side of each case runs in a process of its own, so the peak memory reported is that of
 * the case alone (inputs, result and everything in between), and one case's garbage or compiled
 * code cannot slow the next. The policy is the native harnesses' (`native.ts`), so that the two
 * benchmarks time alike: inputs prepared outside the timed region, a collection of the garbage
 * before each run (the children run with `--expose-gc`), one warm-up, then the median.
 */

import type { HalfedgeMesh } from '../src/core/mesh.js';

export interface BenchCase {
  /** Stable name, e.g. `build-sphere`. */
  case: string;
  /** Faces in the input (the scale the targets are stated in). Known without building anything. */
  size: number;
  /**
   * Builds the inputs of one side (each side runs in its own process); not timed. Heavy work
   * belongs here, not in the case's factory.
   */
  prepare?: (side: Side) => void | Promise<void>;
  /** Before each run of either side (the warm-up too), untimed: e.g. a fresh copy of an input the run changes. */
  beforeEach?: () => void;
  /** Our implementation. Its result may be inspected by `bytes`. */
  run: () => unknown;
  /** Bytes held by our result (for memory-per-face targets). */
  bytes?: (result: unknown) => number;
  peer?: { name: string; run: () => unknown };
  /** Repetitions (default 5, odd so the median is a run); a warm-up run comes first. */
  repeat?: number;
}

/**
 * For a case whose operation changes the mesh it is given: before each run (`renew`, the case's
 * `beforeEach`), the last run's copy is let go and collected, then a new copy of the input made,
 * as the natives' `m = in` frees their last result before copying. Holding a copy for every run
 * instead kept four more meshes alive through the timing (at a million faces, 400 MB).
 */
export class FreshCopy {
  private input: HalfedgeMesh | null = null;
  private copy: HalfedgeMesh | null = null;

  /** The mesh every run starts from. */
  from(mesh: HalfedgeMesh): void {
    this.input = mesh;
  }

  /** Before a run; nothing on the peer's side, which never takes the mesh. */
  readonly renew = (): void => {
    if (!this.input) return;
    this.copy = null;
    globalThis.gc?.();
    this.copy = this.input!.clone();
  };

  /** This run's copy, to change. */
  take(): HalfedgeMesh {
    const copy = this.copy;
    if (!copy) throw new Error('a run took its copy twice, or before renew()');
    this.copy = null;
    return copy;
  }
}

/** What one side of a case measured, in its own process. */
export interface SideResult {
  ms: number;
  /** Largest resident set of the process, in MB. */
  peakMB: number;
  bytesPerFace?: number;
}

export interface BenchResult {
  case: string;
  size: number;
  ms: number;
  peer: string | null;
  peerMs: number | null;
  /** ms / peerMs: below 1 means faster than the peer. */
  ratio: number | null;
  peakMB: number;
  peerPeakMB: number | null;
  bytesPerFace?: number;
}

export type Side = 'ours' | 'peer';

/** Prepares and times one side of a case (in the current process). */
export async function measure(bench: BenchCase, side: Side): Promise<SideResult> {
  await bench.prepare?.(side);
  const run = side === 'ours' ? bench.run : bench.peer!.run;
  const once = () => {
    bench.beforeEach?.();
    globalThis.gc?.(); // the last run's garbage is not this run's cost
    const start = performance.now();
    const result = run();
    return { ms: performance.now() - start, result };
  };
  let { result } = once(); // warm-up
  const times: number[] = [];
  for (let i = 0; i < (bench.repeat ?? 5); i++) {
    const timed = once();
    times.push(timed.ms);
    result = timed.result;
  }
  times.sort((a, b) => a - b);
  return {
    ms: round(times[times.length >> 1]!),
    peakMB: Math.round(process.resourceUsage().maxRSS / 1024),
    ...(side === 'ours' && bench.bytes ? { bytesPerFace: round(bench.bytes(result) / bench.size) } : {}),
  };
}

export function combine(bench: BenchCase, ours: SideResult, peer: SideResult | null): BenchResult {
  return {
    case: bench.case,
    size: bench.size,
    ms: ours.ms,
    peer: bench.peer?.name ?? null,
    peerMs: peer?.ms ?? null,
    ratio: peer ? round(ours.ms / peer.ms, 3) : null,
    peakMB: ours.peakMB,
    peerPeakMB: peer?.peakMB ?? null,
    ...(ours.bytesPerFace === undefined ? {} : { bytesPerFace: ours.bytesPerFace }),
  };
}

export function round(x: number, digits = 1): number {
  const f = 10 ** digits;
  return Math.round(x * f) / f;
}
