/**
 * The benchmark harness. A case times our code and, where one exists, a JavaScript peer doing the
 * same job on the same input in the same run, so the ratio means something on a shared machine
 * whose absolute speed drifts. Times are the median of several runs after a warm-up.
 */

export interface BenchCase {
  /** Stable name, e.g. `build-sphere`. */
  case: string;
  /** Faces in the input (the scale the targets are stated in). */
  size: number;
  /** Builds the inputs; not timed. */
  prepare?: () => void | Promise<void>;
  /** Our implementation. Its result may be inspected by `bytes`. */
  run: () => unknown;
  /** Bytes held by our result (for memory-per-face targets). */
  bytes?: (result: unknown) => number;
  peer?: { name: string; run: () => unknown };
  /** Repetitions (default 5); a warm-up run comes first. */
  repeat?: number;
}

export interface BenchResult {
  case: string;
  size: number;
  ms: number;
  peer: string | null;
  peerMs: number | null;
  /** ms / peerMs: below 1 means faster than the peer. */
  ratio: number | null;
  bytesPerFace?: number;
  /** Largest resident set seen while the case ran, in MB. */
  peakRssMB: number;
}

export async function runCase(bench: BenchCase): Promise<BenchResult> {
  await bench.prepare?.();
  const repeat = bench.repeat ?? 5;
  let peakRss = process.memoryUsage().rss;
  const time = (fn: () => unknown): { ms: number; result: unknown } => {
    let result = fn(); // warm-up
    const times: number[] = [];
    for (let i = 0; i < repeat; i++) {
      const start = performance.now();
      result = fn();
      times.push(performance.now() - start);
      peakRss = Math.max(peakRss, process.memoryUsage().rss);
    }
    times.sort((a, b) => a - b);
    return { ms: times[times.length >> 1]!, result };
  };
  const ours = time(bench.run);
  const bytesPerFace = bench.bytes ? bench.bytes(ours.result) / bench.size : undefined;
  const peer = bench.peer ? time(bench.peer.run) : null;
  return {
    case: bench.case,
    size: bench.size,
    ms: round(ours.ms),
    peer: bench.peer?.name ?? null,
    peerMs: peer ? round(peer.ms) : null,
    ratio: peer ? round(ours.ms / peer.ms, 3) : null,
    ...(bytesPerFace === undefined ? {} : { bytesPerFace: round(bytesPerFace, 1) }),
    peakRssMB: Math.round(peakRss / 2 ** 20),
  };
}

function round(x: number, digits = 1): number {
  const f = 10 ** digits;
  return Math.round(x * f) / f;
}
