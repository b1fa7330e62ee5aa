/** The sample models in public/models are exactly what `npm run models` makes, and all load cleanly. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { modelBytes, modelIndex, sampleModels } from '../scripts/make-models.js';
import { buildMesh, meshStats, readMesh, validate } from '../src/index.js';

const folder = join(import.meta.dirname, '../public/models');

describe('sample models', () => {
  it('lists every model in index.json', () => {
    expect(readFileSync(join(folder, 'index.json'), 'utf8')).toBe(modelIndex());
  });

  it.each(sampleModels.map((m) => [m.file, m] as const))('%s is what the generator writes, and builds valid', (file, model) => {
    const committed = readFileSync(join(folder, file));
    expect(Buffer.from(modelBytes(model)).equals(committed)).toBe(true);
    const { mesh, report } = buildMesh(readMesh(committed, { fileName: file }).soup);
    expect(validate(mesh)).toEqual([]);
    const stats = meshStats(mesh, report);
    if (file === 'moebius.obj') expect(stats.orientable).toBe(false);
    if (file === 'non-manifold.obj') expect(stats.manifold).toBe(false);
    if (file === 'torus.off') expect(stats.genus).toBe(1);
    if (file === 'double-torus.off') expect(stats.genus).toBe(2);
  });
});
