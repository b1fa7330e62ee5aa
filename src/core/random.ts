/**
 * A small seeded random source (mulberry32): the same seed gives the same numbers everywhere, so
 * noisy test meshes, fuzzed files and quiz questions can be replayed exactly.
 * @example const next = seededRandom(7); const noise = next() - 0.5;
 */
export function seededRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
