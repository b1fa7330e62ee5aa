/**
 * The glTF reader fuzzer, a short run (`npm run fuzz -- --only gltf` runs it long): mutated `.glb`
 * and `.gltf` files must each read into a valid mesh that saves and reads back the same, or be
 * refused with a `ParseError`.
 */
import { describe, expect, it } from 'vitest';
import { checkGltf, gltfSamples, gltfTarget } from '../../fuzz/gltf.js';

const SEED = 20261125;

describe(`the glTF reader fuzzer (seed ${SEED})`, () => {
  it('finds no failure in 1500 mutations of the files the library writes, and refuses most of them', async () => {
    const target = gltfTarget();
    const failures: string[] = [];
    let refused = 0;
    for (let index = 0; index < 1500; index++) {
      const outcome = await target.runCase(SEED, index);
      if (outcome.kind === 'failure') failures.push(`case ${index}: ${outcome.reason}\n  ${outcome.input}`);
      if (outcome.kind === 'refused') refused++;
    }
    expect(failures).toEqual([]);
    expect(refused).toBeGreaterThan(300);
  }, 120_000);

  it('reads every sample as it is, and refuses each cut short', async () => {
    for (const { name, bytes } of await gltfSamples()) {
      expect(await checkGltf(name, bytes)).toEqual({ kind: 'accepted' });
      const step = Math.max(1, Math.floor(bytes.length / 40));
      for (let end = 0; end < bytes.length; end += step) expect((await checkGltf(name, bytes.subarray(0, end))).kind, `${name} cut at ${end}`).toBe('refused');
    }
  });
});
