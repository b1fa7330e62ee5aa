/**
 * What a fuzz target is: a stream of cases, each one derived from (seed, index) alone, so a case
 * that fails, hangs or kills its process is replayed from those two numbers. The runner
 * (`npm run fuzz`) hands slices of the indices to child processes and watches each case's time;
 * the tests run a few thousand cases in process.
 */

/** How one case ended. Everything that is neither a clean refusal nor an accepted, valid result is a failure. */
export type CaseOutcome =
  /** A `ParseError` for a file, or the library's own refusal (a predicate's reason, a `TopologyError`). */
  | { kind: 'refused'; reason: string }
  /** Accepted, and every check after it held (`validate()`, save and reload to the same mesh). */
  | { kind: 'accepted' }
  /** Anything else: another exception, an invalid mesh, a round trip that changed the mesh. */
  | { kind: 'failure'; reason: string; input: string };

export interface FuzzTarget<Outcome extends CaseOutcome | Promise<CaseOutcome> = CaseOutcome | Promise<CaseOutcome>> {
  /** Short name used on the command line (`--only NAME`) and in reports. */
  name: string;
  /**
   * Runs case `index` of the stream seeded by `seed`. Catches what the case throws: never throws
   * (or rejects) itself. Asynchronous for readers whose decoders are (glTF).
   */
  runCase(seed: number, index: number): Outcome;
}

/**
 * A case's own seed: seed and index mixed (a multiply-xorshift hash), so neighbouring
 * indices give unrelated runs and (seed, index) alone replays one.
 */
export function caseSeed(seed: number, index: number): number {
  let x = Math.imul(seed ^ 0x9e3779b9, 0x85ebca6b) ^ Math.imul(index + 1, 0xc2b2ae35);
  x = Math.imul(x ^ (x >>> 16), 0x7feb352d);
  x = Math.imul(x ^ (x >>> 15), 0x846ca68b);
  return (x ^ (x >>> 16)) | 0;
}
