import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { buildMesh, meshStats, readMesh, seededRandom } from '../src/index.js';
import type { EditRequest } from '../src/workers/protocol.js';
import { openApp } from './helpers.js';

test.describe('the worker session', () => {
  test('builds the same mesh in the worker as the library does in Node', async ({ page }) => {
    await openApp(page, 'sphere.ply');
    const file = readMesh(readFileSync('public/models/sphere.ply'), { fileName: 'sphere.ply' });
    const { mesh, report } = buildMesh(file.soup);
    const expected = meshStats(mesh, report);
    const stats = await page.evaluate(() => window.halfedgeLab.state().stats!);
    expect(stats).toEqual(JSON.parse(JSON.stringify(expected)));
    for (const h of [0, 17, 151, mesh.halfedgeSlots - 1]) {
      const record = await page.evaluate((name) => window.halfedgeLab.record(name), `h${h}`);
      expect(record).toMatchObject({ next: `h${mesh.heNext[h]}`, prev: `h${mesh.hePrev[h]}`, twin: `h${h ^ 1}`, origin: `v${mesh.heVertex[h]}` });
    }
  });

  test('shows a parse error with its place, and the previous mesh stays', async ({ page }) => {
    await openApp(page, 'cube.off');
    const bad = 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n';
    await page.locator('#file-input').setInputFiles({ name: 'broken.off', mimeType: 'text/plain', buffer: Buffer.from(bad) });
    await expect(page.locator('#status')).toHaveAttribute('role', 'alert');
    await expect(page.locator('#status')).toContainText('broken.off');
    await expect(page.locator('#status')).toContainText('line 6');
    await expect(page.locator('#status')).toContainText('previous mesh stays');
    const state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.file?.name).toBe('cube.off');
    expect(state.stats?.faces).toBe(6);
  });

  test('restarts a worker that died and restores the last good mesh', async ({ page }) => {
    await openApp(page, 'torus.off');
    await page.evaluate(() => window.halfedgeLab.select('h5'));
    await page.evaluate(() => window.halfedgeLab.simulateWorkerCrash());
    await expect(page.locator('#status')).toContainText('restarted with the last good mesh');
    const state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.stats?.faces).toBe(128);
    expect(state.selection).toBe('h5');
    // and the new worker works
    await page.evaluate(() => window.halfedgeLab.start({ kind: 'subdivide', scheme: 'catmull-clark' }));
    await page.evaluate(() => window.halfedgeLab.runToEnd());
    expect(await page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(4 * 128);
  });
});

test.describe('edits as patches', () => {
  test('keeps the page’s copy equal to the worker’s mesh through edits, undos, redos and phases, and picks on the edited mesh', async ({ page }) => {
    await openApp(page, 'sphere.ply');
    const random = seededRandom(20261125);
    const fingerprints = () => page.evaluate(() => window.halfedgeLab.fingerprints());
    for (let i = 0; i < 40; i++) {
      const roll = random();
      const stats = await page.evaluate(() => window.halfedgeLab.state().stats!);
      const edge = Math.floor(random() * stats.edges);
      const face = Math.floor(random() * stats.faces);
      const request = [
        { kind: 'flip-edge', edge },
        { kind: 'split-edge', edge, triangulate: true },
        { kind: 'collapse-edge', edge },
        { kind: 'poke-face', face },
      ][Math.floor(random() * 4)]!;
      if (roll < 0.6) await page.evaluate((r) => window.halfedgeLab.edit(r as EditRequest).catch(() => null), request);
      else if (roll < 0.75) await page.evaluate(() => window.halfedgeLab.undo());
      else if (roll < 0.85) await page.evaluate(() => window.halfedgeLab.redo());
      else {
        await page.evaluate(() => window.halfedgeLab.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 2 } }));
        await page.evaluate(() => window.halfedgeLab.step());
        await page.evaluate(() => window.halfedgeLab.runToEnd());
      }
      const { session, page: copy } = await fingerprints();
      expect(copy, `step ${i}`).toBe(session);
    }
    // the last edit's diff, as the automation documents it
    await page.evaluate(() => window.halfedgeLab.edit({ kind: 'poke-face', face: 0 }));
    expect(await page.evaluate(() => window.halfedgeLab.state().patched)).toBe(true);
    const diff = await page.evaluate(() => window.halfedgeLab.state().phase?.diff);
    expect(diff!.total).toBeGreaterThan(5);
    expect(diff!.changes[0]).toEqual({ field: expect.stringMatching(/^(heNext|hePrev|heVertex|heFace|vHalfedge|fHalfedge)$/), index: expect.any(Number), old: expect.any(Number), new: expect.any(Number) });
    // the full check arrives after the patch
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().pending)).toBe(false);
    expect(await page.evaluate(() => window.halfedgeLab.state().problems)).toEqual([]);
    // a click still finds a face of the edited mesh
    const box = (await page.locator('#viewport canvas').boundingBox())!;
    const picked = await page.evaluate(([x, y]) => window.halfedgeLab.pickAt(x!, y!, 'face'), [box.width / 2, box.height / 2]);
    expect(picked).toMatch(/^f\d+$/);
  });
});
