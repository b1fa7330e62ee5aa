import { expect, test } from '@playwright/test';
import { grid, writeSoup } from '../src/index.js';
import { appErrors, openApp, stats } from './helpers.js';


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

  test('an extrusion dragged in the view: up pulls the face further out, in one history entry; a click keeps it', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openApp(page, 'cube.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.evaluate(() => window.halfedgeLab.select('f2'));
    await page.locator('[data-edit="extrude-face"]').click();
    await expect.poll(async () => (await stats(page)).faces).toBe(10);
    await expect(page.locator('#status')).toContainText('Drag up or down in the view to set its offset');
    const first = (await page.evaluate(() => window.halfedgeLab.state().adjusting))!;
    expect(first).toMatchObject({ kind: 'extrude-face', field: 'offset' });
    const entries = (await page.evaluate(() => window.halfedgeLab.state().history!.items.length));
    // the mesh's extent: the face goes further out
    const extent = async () => {
      const { min, max } = (await stats(page)).boundingBox!;
      return Math.max(...max.map((m, i) => m - min[i]!));
    };
    const before = await extent();
    const box = (await page.locator('#viewport canvas').boundingBox())!;
    const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let dy = 10; dy <= 60; dy += 10) await page.mouse.move(x, y - dy);
    await page.mouse.up();
    await expect.poll(async () => (await page.evaluate(() => window.halfedgeLab.state().adjusting))?.value).toBeCloseTo(first.value * 1.6, 5);
    const state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.history!.items.length).toBe(entries);
    expect(state.history!.items[state.history!.index]!.label).toBe('extrude f2');
    expect(state.stats!.faces).toBe(10);
    expect(state.problems).toEqual([]);
    await expect.poll(extent).toBeGreaterThan(before + 0.5 * first.value);
    await page.screenshot({ path: testInfo.outputPath('extrude-dragged.png') });
    // a click keeps it: the next drag turns the camera again
    await page.mouse.click(box.x + 20, box.y + box.height - 20);
    expect(await page.evaluate(() => window.halfedgeLab.state().adjusting)).toBeNull();
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await stats(page)).faces).toBe(6);
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
