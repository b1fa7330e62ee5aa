import { expect, type Page, test } from '@playwright/test';
import { grid, writeSoup } from '../src/index.js';
import { appErrors, openApp } from './helpers.js';

const stats = (page: Page) => page.evaluate(() => window.halfedgeLab.state().stats!);

test.describe("the assignment's local operations in Operate", () => {
  test('extrude, bevel, collapse a face and make a hole from the buttons, each undone, at 1280 × 720', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openApp(page, 'cube.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    // with nothing selected, each button says what to select
    await expect(page.locator('[data-edit="extrude-face"]')).toHaveAttribute('title', 'select a face or a halfedge inside one first');
    await expect(page.locator('[data-edit="bevel-vertex"]')).toHaveAttribute('title', 'select a vertex or a halfedge from it first');
    for (const [select, kind, faces] of [
      ['f2', 'extrude-face', 10],
      ['v3', 'bevel-vertex', 7],
      ['e5', 'bevel-edge', 7],
      ['f2', 'collapse-face', 5],
      ['f2', 'make-boundary', 5],
      ['e5', 'dissolve-edge', 5],
    ] as const) {
      await page.evaluate((s) => window.halfedgeLab.select(s), select);
      await page.locator(`[data-edit="${kind}"]`).click();
      await expect.poll(async () => (await stats(page)).faces, `${kind} on ${select}`).toBe(faces);
      await expect(page.locator('#hud [data-valid]')).toHaveAttribute('data-valid', 'true');
      await expect(page.locator('.diff-table')).toBeVisible();
      if (kind === 'extrude-face') await page.screenshot({ path: testInfo.outputPath('extruded.png') });
      await page.keyboard.press('Control+z');
      await expect.poll(async () => (await stats(page)).faces).toBe(6);
    }
    // a boundary-free cube has nothing to weld: the button says why
    await page.evaluate(() => window.halfedgeLab.select('e0'));
    await expect(page.locator('[data-edit="weld-edges"]')).toHaveAttribute('title', /not on the boundary/);
    expect(appErrors(page)).toEqual([]);
  });

  test('welds in two steps: the first boundary edge, then the second, rolling a strip into a ring', async ({ page }) => {
    await openApp(page, 'disk.off');
    await page.locator('#file-input').setInputFiles({ name: 'strip.off', mimeType: 'text/plain', buffer: Buffer.from(writeSoup(grid(3, 1, true), 'off')) });
    await expect.poll(async () => (await stats(page)).faces).toBe(3);
    await page.getByRole('tab', { name: 'Operate' }).click();
    // the free ends: the edges 0–4 and 3–7
    const [left, right] = await page.evaluate(() => {
      const edgeOf = (a: string, b: string) => {
        for (let e = 0; e < 10; e++) {
          const h = window.halfedgeLab.record(`h${2 * e}`);
          const ends = [h.origin, window.halfedgeLab.record(h.next).origin];
          if (ends.includes(a) && ends.includes(b)) return `e${e}`;
        }
        throw new Error(`no edge ${a}–${b}`);
      };
      return [edgeOf('v0', 'v4'), edgeOf('v3', 'v7')];
    });
    await page.evaluate((e) => window.halfedgeLab.select(e), left);
    await page.locator('[data-edit="weld-edges"]').click();
    await expect(page.locator('#status')).toContainText(`Weld: ${left} is the first edge`);
    // the first edge again is not a second edge
    await expect(page.locator('[data-edit="weld-edges"]')).toHaveAttribute('aria-disabled', 'true');
    await page.evaluate((e) => window.halfedgeLab.select(e), right);
    await expect(page.locator('[data-edit="weld-edges"]')).toHaveAttribute('aria-label', `Weld ${left} to the selected edge`);
    await page.locator('[data-edit="weld-edges"]').click();
    await expect.poll(async () => (await stats(page)).boundaryLoops).toBe(2);
    expect([(await stats(page)).vertices, (await stats(page)).faces]).toEqual([6, 3]);
    await expect(page.locator('#hud [data-valid]')).toHaveAttribute('data-valid', 'true');
  });
});
