import { expect, test } from '@playwright/test';
import { openApp, textOutside } from './helpers.js';

const tabs = ['Inspect', 'Operate', 'Quiz', 'Practice', 'File'] as const;

for (const [width, height] of [
  [1280, 720],
  [1024, 768],
] as const) {
  test.describe(`presentation mode at ${width} × ${height}`, () => {
    test.beforeEach(async ({ page }) => {
      await page.setViewportSize({ width, height });
    });

    test('every tab shows all of its text inside the window', async ({ page }, testInfo) => {
      await openApp(page, 'torus.off');
      await page.keyboard.press('m');
      await page.evaluate(() => window.halfedgeLab.select('h0'));
      for (const tab of tabs) {
        await page.getByRole('tab', { name: tab }).click();
        await page.waitForTimeout(300);
        await page.screenshot({ path: testInfo.outputPath(`${tab}.png`) });
        expect(await textOutside(page), tab).toEqual([]);
      }
    });

    test('a long walk keeps its last step in sight, and a refused walk says why in the window', async ({ page }, testInfo) => {
      await openApp(page, 'disk.off');
      await page.keyboard.press('m');
      // an inner halfedge, then a long walk around faces and across edges
      const inner = await page.evaluate(() => {
        for (let h = 0; ; h++) if (window.halfedgeLab.record(`h${h}`).face.startsWith('f') && window.halfedgeLab.record(`h${h ^ 1}`).face.startsWith('f')) return h;
      });
      await page.evaluate((h) => window.halfedgeLab.select(`h${h}`), inner);
      for (const key of ['n', 'n', 't', 'n', 'p', 't', 'n', 'n', 't', 'r', 'l', 'n']) await page.keyboard.press(key);
      const last = await page.evaluate(() => window.halfedgeLab.state().breadcrumb.at(-1)!.to);
      await expect(page.locator('#breadcrumb')).toContainText(new RegExp(`${last}$`));
      await expect(page.locator('#breadcrumb')).toBeInViewport({ ratio: 1 });
      await page.screenshot({ path: testInfo.outputPath('walk.png') });
      expect(await textOutside(page)).toEqual([]);
      // a boundary halfedge has no face: the refusal is said where the room looks
      const boundary = await page.evaluate(() => {
        for (let h = 0; ; h++) if (!window.halfedgeLab.record(`h${h}`).face.startsWith('f')) return h;
      });
      await page.evaluate((h) => window.halfedgeLab.select(`h${h}`), boundary);
      await page.keyboard.press('f');
      await expect(page.locator('#status')).toContainText('is a boundary halfedge');
      await expect(page.locator('#status')).toBeInViewport({ ratio: 1 });
      await page.screenshot({ path: testInfo.outputPath('refused.png') });
      expect(await textOutside(page)).toEqual([]);
    });

    test('stepping keeps the Step buttons and the first pointer changes in sight', async ({ page }, testInfo) => {
      await openApp(page, 'torus.off');
      await page.keyboard.press('m');
      await page.getByRole('tab', { name: 'Operate' }).click();
      await page.locator('[data-operation="catmull-clark"]').click();
      for (let phase = 1; phase <= 4; phase++) {
        await page.keyboard.press('s');
        await expect(page.locator('.phase-title')).toContainText(`phase ${phase} of 4`);
        await page.screenshot({ path: testInfo.outputPath(`phase-${phase}.png`) });
        expect(await textOutside(page), `phase ${phase}`).toEqual([]);
        await expect(page.getByRole('button', { name: /^Back to the previous phase/ })).toBeInViewport({ ratio: 1 });
        const rows = page.locator('.stepper-panel .diff-table tbody tr');
        if ((await rows.count()) > 0) {
          await expect(page.locator('.stepper-panel .diff > p')).toBeInViewport({ ratio: 1 });
          await expect(rows.nth(2)).toBeInViewport({ ratio: 1 });
        }
      }
    });
  });
}
