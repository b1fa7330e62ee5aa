/**
 * The tests that measure time (a frame counter while a file loads, a clock on an endless loop)
 * or move tens of megabytes into the page. They run last, after every other browser test (the
 * `timed` project in playwright.config.ts), so that nothing else the suite does is still winding
 * down when their clocks start.
 */
import { expect, test } from '@playwright/test';
import { uvSphere, writeSoup } from '../src/index.js';
import { openApp, openAppAt } from './helpers.js';

// the clock on an endless loop first: after the large files, the browser is still collecting them
test.describe('practice mode', () => {
  test('an endless loop is stopped within 3 s while the page keeps drawing', async ({ page }) => {
    await openAppAt(page, '/?exercise=vertex-degree');
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    const frames = page.evaluate(
      () =>
        new Promise<number>((resolve) => {
          let count = 0;
          const start = performance.now();
          const tick = () => (performance.now() - start < 2000 ? (count++, requestAnimationFrame(tick)) : resolve(count));
          requestAnimationFrame(tick);
        }),
    );
    await page.evaluate((code) => window.halfedgeLab.practice.setCode(code), 'export default function (mesh, v) {\n  while (true) {}\n}\n');
    // from the press of Run: typing the code is not the loop's time
    const started = Date.now();
    await page.getByRole('button', { name: 'Run the solution' }).click();
    await expect(page.locator('.practice-summary')).toHaveText('0 of 4 checks pass.', { timeout: 10_000 });
    expect(Date.now() - started).toBeLessThan(3500);
    expect(await frames).toBeGreaterThan(20);
    await expect(page.locator('.practice-checks')).toContainText('your code ran for 2.5 s without returning');
  });
});

test.describe('loading a large file', () => {
  test('keeps the page drawing while a large file is parsed off the main thread', async ({ page }) => {
    await openApp(page, 'tetrahedron.off');
    const big = writeSoup(uvSphere(400, 800), 'ply'); // 638k triangles of ascii PLY
    const framesBefore = await page.evaluate(() => window.halfedgeLab.state().frames);
    await page.locator('#file-input').setInputFiles({ name: 'big-sphere.ply', mimeType: 'application/octet-stream', buffer: Buffer.from(big) });
    // while the loader works, the progress bar shows and the frame counter keeps moving
    await expect(page.locator('#progress')).toBeVisible();
    const during: number[] = [];
    while (await page.locator('#progress').isVisible()) {
      during.push(await page.evaluate(() => window.halfedgeLab.state().frames));
      await page.waitForTimeout(100);
    }
    expect(during.length).toBeGreaterThan(2);
    expect(during.at(-1)!).toBeGreaterThan(during[0]! + 5);
    expect(during[0]!).toBeGreaterThan(framesBefore - 1);
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(2 * 800 * 399);
    // a mesh this large is picked by the picking worker: a click in the middle finds a face
    const box = (await page.locator('#viewport canvas').boundingBox())!;
    const picked = await page.evaluate(([x, y]) => window.halfedgeLab.pickAt(x!, y!, 'face'), [box.width / 2, box.height / 2]);
    expect(picked).toMatch(/^f\d+$/);
    await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().selection)).toMatch(/^[hvf]\d+$/);
  });

  test('cancels a load in progress, keeping the previous mesh', async ({ page }) => {
    await openApp(page, 'cube.off');
    // ascii, so that reading it takes long enough to cancel, and no larger than that needs
    const big = writeSoup(uvSphere(300, 600), 'ply');
    await page.locator('#file-input').setInputFiles({ name: 'huge.ply', mimeType: 'application/octet-stream', buffer: Buffer.from(big) });
    await page.getByRole('button', { name: 'Cancel' }).click();
    await expect(page.locator('#status')).toContainText('previous mesh stays');
    const state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.file?.name).toBe('cube.off');
    expect(state.stats?.faces).toBe(6);
  });
});
