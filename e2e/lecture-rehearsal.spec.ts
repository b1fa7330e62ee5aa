/**
 * A whole lecture, rehearsed as a lecturer gives it: one page, no reload, presentation mode and
 * the keyboard first, at both projector sizes. A real file opened from the picker, a walk, Catmull-
 * Clark stepped to its last phase and back, a capped cut pulled apart, a quiz question, a share
 * link. After every step nothing of the side panel is outside the window, and the page logs no error.
 */
import { readFileSync } from 'node:fs';
import { expect, type Page, test } from '@playwright/test';
import { appErrors, askClickable, clickCanvas, onCanvas, openApp, textOutside } from './helpers.js';

const state = (page: Page) => page.evaluate(() => window.halfedgeLab.state());

/** A halfedge whose arrow a click at its drawn point picks, with nothing over that point. */
async function clickableArrow(page: Page): Promise<{ name: string; x: number; y: number }> {
  for (let h = 0; h < 512; h += 7) {
    const at = await page.evaluate((name) => window.halfedgeLab.screenPosition(name), `h${h}`);
    if (!at.visible || !(await onCanvas(page, at.x, at.y))) continue;
    if ((await page.evaluate(([x, y]) => window.halfedgeLab.pickAt(x!, y!), [at.x, at.y])) === `h${h}`) return { name: `h${h}`, x: at.x, y: at.y };
  }
  throw new Error('no arrow can be clicked');
}

for (const [width, height] of [
  [1280, 720],
  [1024, 768],
] as const) {
  test(`a whole lecture at ${width} × ${height}, in one page`, async ({ page, context }, testInfo) => {
    test.setTimeout(120_000);
    await page.setViewportSize({ width, height });
    await openApp(page, 'disk.off');
    const shot = (name: string) => page.screenshot({ path: testInfo.outputPath(`${name}.png`) });
    const panelFits = async (step: string) => expect(await textOutside(page), step).toEqual([]);

    // a real file from the picker, then presentation mode by its key at once
    await page.locator('#file-input').setInputFiles({ name: 'torus.off', mimeType: 'text/plain', buffer: readFileSync(new URL('../public/models/torus.off', import.meta.url)) });
    await expect(page.locator('#status')).toHaveText('Opened torus.off.');
    await page.keyboard.press('m');
    await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
    await panelFits('opened');

    // click an arrow (one the view shows clear of the overlays, once presentation mode has framed
    // the mesh again), then walk by the keys; the breadcrumb's last step is in sight
    await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
    const arrow = await clickableArrow(page);
    await clickCanvas(page, arrow.x, arrow.y);
    await expect.poll(async () => (await state(page)).selection).toBe(arrow.name);
    for (const key of ['n', 't', 'n', 'n', 't', 'r']) await page.keyboard.press(key);
    const walked = (await state(page)).breadcrumb;
    expect(walked).toHaveLength(7);
    await expect(page.locator('#breadcrumb')).toHaveText(new RegExp(`${walked.at(-1)!.to}$`));
    await expect(page.locator('#breadcrumb')).toBeInViewport({ ratio: 1 });
    await panelFits('walked');
    await shot('walk');

    // Catmull-Clark, stepped to its last phase, which stays; back a phase, forward, undo
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.locator('[data-operation="catmull-clark"]').click();
    for (let phase = 1; phase <= 4; phase++) await page.keyboard.press('s');
    const legend = page.locator('#legend');
    await expect(legend).toContainText('phase 4 of 4 (done): move the old vertices');
    await expect(legend.locator('.legend-phase')).toBeInViewport({ ratio: 1 });
    expect((await state(page)).stats!.faces).toBe(512);
    await panelFits('last phase');
    await shot('last-phase');
    await page.keyboard.press('Shift+S');
    await expect(legend).toContainText('phase 3 of 4');
    await expect(page.locator('.stepper-panel .diff-table tbody tr').first()).toBeInViewport({ ratio: 1 });
    await panelFits('previous phase');
    await page.keyboard.press('s');
    await expect(legend).toContainText('phase 4 of 4 (done)');
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await state(page)).stats!.faces).toBe(128);

    // a capped cut through the ring, both halves kept and pulled apart to show the caps
    await page.getByRole('spinbutton', { name: 'Plane coefficient b' }).fill('1');
    await page.getByRole('spinbutton', { name: 'Plane coefficient c' }).fill('0');
    await page.getByRole('combobox', { name: 'Which side to keep' }).selectOption('both');
    await page.locator('[data-operation="cut"]').click();
    await page.keyboard.press('g');
    await expect.poll(async () => (await state(page)).stats?.components).toBe(2);
    // the run's progress bar went with the run: nothing is left over the view
    await expect(page.locator('#progress')).toBeHidden();
    await expect(page.locator('#hud [data-count="genus"]')).toHaveText('0 + 0');
    expect((await state(page)).planeShown).toBe(false);
    await page.keyboard.press('b');
    await expect.poll(async () => (await state(page)).exploded).toBe(true);
    await panelFits('cut apart');
    await shot('cut-apart');

    // a quiz question, answered by clicking the element it asks for
    await page.keyboard.press('q');
    await expect(page.locator('.quiz-question')).toContainText('Which');
    const question = await askClickable(page);
    await clickCanvas(page, question.x, question.y);
    await expect(page.locator('.quiz-verdict')).toContainText('Right');
    await panelFits('quiz');
    await shot('quiz');

    // a link cannot carry a file of the lecturer's own, and says so; on the sample it reproduces the mesh
    await page.getByRole('button', { name: 'Copy a link to this view' }).click();
    await expect(page.locator('#status')).toContainText('without the model');
    const menu = page.getByRole('combobox', { name: 'Sample model' });
    await menu.focus();
    await menu.selectOption('torus.off');
    await expect.poll(async () => (await state(page)).stats?.faces).toBe(128);
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.locator('[data-operation="cut"]').click();
    await page.keyboard.press('g');
    await expect.poll(async () => (await state(page)).stats?.components).toBe(2);
    const link = await page.evaluate(() => window.halfedgeLab.shareLink());
    expect(link).toContain('model=torus.off');
    const fingerprint = (await page.evaluate(() => window.halfedgeLab.fingerprints())).session;
    const second = await context.newPage();
    await second.goto(link);
    await second.waitForFunction(() => window.halfedgeLab !== undefined);
    await second.evaluate(() => window.halfedgeLab.ready);
    await expect.poll(async () => (await second.evaluate(() => window.halfedgeLab.fingerprints())).session, { timeout: 30_000 }).toBe(fingerprint);

    expect(appErrors(page)).toEqual([]);
  });
}
