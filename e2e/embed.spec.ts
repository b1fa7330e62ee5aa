/**
 * Embedding: two `<halfedge-view>` elements on a plain page (the package's built element, as a
 * course page would load it) stay independent, and the page's `?embed` mode in an iframe shows
 * only the view and the chosen panels, still driven by the keyboard.
 */
import { existsSync, readFileSync } from 'node:fs';
import { extname, join, normalize } from 'node:path';
import { expect, type Page, test } from '@playwright/test';
import type { HalfedgeViewElement } from '../src/ui/element.js';

/** The element as `npm run build:element` leaves it (the test server's command builds it first, so it is always there). */
const ELEMENT_DIR = 'dist/element';

const types: Record<string, string> = { '.js': 'text/javascript', '.html': 'text/html' };

/** A course page of its own, outside the app: `/course/…` is this page and the element's files. */
async function serveCoursePage(page: Page, html: string): Promise<string[]> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => void (message.type() === 'error' && errors.push(message.text())));
  await page.route('**/course/**', (route) => {
    const path = new URL(route.request().url()).pathname.replace(/^\/course\//, '');
    if (path === 'index.html') return route.fulfill({ body: html, contentType: 'text/html' });
    const file = normalize(join(ELEMENT_DIR, path));
    if (!file.startsWith(ELEMENT_DIR) || !existsSync(file)) return route.fulfill({ status: 404 });
    return route.fulfill({ body: readFileSync(file), contentType: types[extname(file)] ?? 'application/octet-stream' });
  });
  return errors;
}

const twoViews = `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8" />
    <title>Lecture 4: halfedges</title>
    <script type="module" src="/course/element.js"></script>
    <style>halfedge-view { width: 620px; height: 380px; margin: 8px; display: inline-block; }</style>
  </head>
  <body>
    <h1>Walking the pointers</h1>
    <halfedge-view id="one" src="/models/torus.off" select="h17" panels="walk,inspector"></halfedge-view>
    <!-- scaled, as reveal.js scales a slide: picking must follow -->
    <div style="transform: scale(0.75); transform-origin: 0 0">
      <halfedge-view id="two" src="/models/cube.off" select="h3" naming="target"></halfedge-view>
    </div>
  </body>
</html>`;

/** `.lab` of the element of an id, once its first mesh is drawn. */
async function labsReady(page: Page, ...ids: string[]): Promise<void> {
  await page.waitForFunction(() => customElements.get('halfedge-view') !== undefined);
  for (const id of ids) await page.evaluate((id) => (document.getElementById(id) as HalfedgeViewElement).lab.ready, id);
}

function stateOf(page: Page, id: string) {
  return page.evaluate((id) => (document.getElementById(id) as HalfedgeViewElement).lab.state(), id);
}

test.describe('two <halfedge-view> elements on one page', () => {
  test('open their own meshes, take the keys only when focused, and walk independently', async ({ page }) => {
    const errors = await serveCoursePage(page, twoViews);
    const workers: string[] = [];
    page.on('worker', (worker) => workers.push(worker.url()));
    await page.goto('/course/index.html');
    await labsReady(page, 'one', 'two');
    // each view's own workers, from beside element.js (not from the app's site)
    expect(workers.length).toBeGreaterThanOrEqual(2);
    for (const url of workers) expect(url).toContain('/course/assets/');
    // each opened its own src and selected its own select, in its own naming
    await expect.poll(async () => (await stateOf(page, 'one')).selection).toBe('h17');
    await expect.poll(async () => (await stateOf(page, 'two')).selection).toBe('h3');
    expect((await stateOf(page, 'one')).file?.name).toBe('torus.off');
    expect((await stateOf(page, 'two')).file?.name).toBe('cube.off');
    expect((await stateOf(page, 'one')).convention).toBe('origin');
    expect((await stateOf(page, 'two')).convention).toBe('target');

    // the first shows its walk and inspector panels; the second only the view
    const one = page.locator('#one');
    const two = page.locator('#two');
    await expect(one.getByRole('button', { name: /walk to next/i })).toBeVisible();
    await expect(one.locator('#record')).toContainText('h17');
    await expect(one.getByRole('toolbar')).toBeHidden();
    await expect(one.locator('#legend')).toBeHidden();
    // stacked in the order named: the walk above the record
    const walkTop = (await one.locator('#walk-title').boundingBox())!.y;
    expect(walkTop).toBeLessThan((await one.locator('#record').boundingBox())!.y);
    await expect(two.locator('.side')).toBeHidden();
    await expect(two.locator('#viewport canvas')).toBeVisible();

    // keys go to the focused view: N in the first walks to next(h17), the second stays on h3
    const next = await page.evaluate(() => (document.getElementById('one') as HalfedgeViewElement).lab.record('h17').next);
    // what the page around hears (a deck's N is "next slide")
    await page.evaluate(() => {
      const heard: string[] = [];
      (window as unknown as { heard: string[] }).heard = heard;
      document.addEventListener('keydown', (event) => heard.push(event.key));
    });
    await page.locator('#one').focus();
    await page.keyboard.press('n');
    await expect.poll(async () => (await stateOf(page, 'one')).selection).toBe(next);
    await page.keyboard.press('ArrowRight');
    expect(await page.evaluate(() => (window as unknown as { heard: string[] }).heard)).toEqual(['ArrowRight']);
    expect((await stateOf(page, 'two')).selection).toBe('h3');
    expect((await stateOf(page, 'two')).breadcrumb).toEqual([{ move: null, to: 'h3' }]);

    // a click on the second (scaled to 3/4) picks what is under the pointer and gives it the
    // focus: T then walks there, and the first stays put
    const { twin, at } = await page.evaluate(() => {
      const lab = (document.getElementById('two') as HalfedgeViewElement).lab;
      lab.select(null);
      return { twin: lab.record('h3').twin, at: lab.screenPosition('h3') };
    });
    const box = (await two.locator('#viewport canvas').boundingBox())!;
    const scale = box.width / (await two.locator('#viewport canvas').evaluate((canvas) => canvas.clientWidth));
    expect(scale).toBeCloseTo(0.75, 2);
    await page.mouse.click(box.x + at.x * scale, box.y + at.y * scale);
    await expect.poll(async () => (await stateOf(page, 'two')).selection).toBe('h3');
    await page.keyboard.press('t');
    await expect.poll(async () => (await stateOf(page, 'two')).selection).toBe(twin);
    expect((await stateOf(page, 'one')).selection).toBe(next);

    // attributes changed later take effect on their own view only
    await page.evaluate(() => (document.getElementById('one') as HalfedgeViewElement).setAttribute('naming', 'target'));
    await expect.poll(async () => (await stateOf(page, 'one')).convention).toBe('target');
    expect((await stateOf(page, 'two')).convention).toBe('target');
    await page.evaluate(() => (document.getElementById('two') as HalfedgeViewElement).setAttribute('src', '/models/tetrahedron.off'));
    await expect.poll(async () => (await stateOf(page, 'two')).file?.name).toBe('tetrahedron.off');
    expect((await stateOf(page, 'one')).file?.name).toBe('torus.off');
    expect(errors).toEqual([]);
  });

  test('select set again to the same value selects again, after the lecturer deselected', async ({ page }) => {
    const errors = await serveCoursePage(page, twoViews);
    await page.goto('/course/index.html');
    await labsReady(page, 'one');
    await expect.poll(async () => (await stateOf(page, 'one')).selection).toBe('h17');
    await page.locator('#one').focus();
    await page.keyboard.press('Escape');
    await expect.poll(async () => (await stateOf(page, 'one')).selection).toBeNull();
    // a slide script that shows the same element again
    await page.evaluate(() => document.getElementById('one')!.setAttribute('select', 'h17'));
    await expect.poll(async () => (await stateOf(page, 'one')).selection).toBe('h17');
    expect(errors).toEqual([]);
  });

  test('a src that is not there is said on the view, and the page lives on', async ({ page }) => {
    await serveCoursePage(page, twoViews.replace('/models/cube.off', '/models/no-such-mesh.off'));
    await page.goto('/course/index.html');
    await labsReady(page, 'one');
    await expect(page.locator('#two').getByRole('alert').filter({ hasText: 'no-such-mesh.off' }).first()).toBeVisible();
    expect((await stateOf(page, 'two')).file).toBeNull();
    expect((await stateOf(page, 'one')).file?.name).toBe('torus.off');
  });
});

test('?embed in an iframe shows only the view and the chosen panels, and takes the keys', async ({ page }) => {
  await serveCoursePage(
    page,
    `<!doctype html><title>Course page</title><h1>The halfedge of a torus</h1>
     <iframe title="Halfedge Lab" width="760" height="420" src="/?embed&panels=inspector,walk,legend&model=torus.off&select=h17&naming=target"></iframe>`,
  );
  await page.goto('/course/index.html');
  const frame = page.frameLocator('iframe');
  const lab = page.frames().find((f) => f.url().includes('embed'))!;
  await lab.waitForFunction(() => window.halfedgeLab !== undefined);
  await lab.evaluate(() => window.halfedgeLab.ready);
  await expect.poll(() => lab.evaluate(() => window.halfedgeLab.state().selection)).toBe('h17');
  expect(await lab.evaluate(() => window.halfedgeLab.state().convention)).toBe('target');

  await expect(frame.getByRole('toolbar')).toBeHidden();
  await expect(frame.getByRole('tablist')).toBeHidden();
  await expect(frame.getByRole('button', { name: /walk to next/i })).toBeVisible();
  await expect(frame.locator('#record')).toBeVisible();
  await expect(frame.locator('#legend')).toBeVisible();
  await expect(frame.locator('#hud')).toBeHidden();
  for (const hidden of ['#operations', '#quiz', '#file-info', '#traversal', '#tables']) await expect(frame.locator(hidden)).toBeHidden();

  const next = await lab.evaluate(() => window.halfedgeLab.record('h17').next);
  await frame.getByRole('button', { name: /walk to next/i }).focus();
  await page.keyboard.press('n');
  await expect.poll(() => lab.evaluate(() => window.halfedgeLab.state().selection)).toBe(next);
});

test('?embed with a model that is not there says so on the view, beside a panel it does not know', async ({ page }) => {
  await serveCoursePage(page, `<!doctype html><title>Course page</title><iframe title="Halfedge Lab" width="760" height="420" src="/?embed&panels=walk,wlak&model=no-such-model.off"></iframe>`);
  await page.goto('/course/index.html');
  const frame = page.frameLocator('iframe');
  const lab = page.frames().find((f) => f.url().includes('embed'))!;
  await lab.waitForFunction(() => window.halfedgeLab !== undefined);
  await lab.evaluate(() => window.halfedgeLab.ready);
  await expect(frame.locator('#status')).toContainText('This link names a sample that is not here (no-such-model.off)');
  await expect(frame.locator('#status')).toContainText('Unknown panel wlak');
  await expect(frame.locator('#status')).toBeVisible();
  await expect(frame.locator('#status')).toHaveAttribute('role', 'alert');
});

test('a 600 × 460 ?embed with the legend and the counts keeps them compact and frames the torus in the rest', async ({ page }, testInfo) => {
  await serveCoursePage(page, `<!doctype html><title>Slide</title><iframe title="Halfedge Lab" width="600" height="460" style="border:0" src="/?embed&panels=legend,hud&model=torus.off&select=h17"></iframe>`);
  await page.goto('/course/index.html');
  const frame = page.frameLocator('iframe');
  const lab = page.frames().find((f) => f.url().includes('embed'))!;
  await lab.waitForFunction(() => window.halfedgeLab !== undefined);
  await lab.evaluate(() => window.halfedgeLab.ready);
  await expect.poll(() => lab.evaluate(() => window.halfedgeLab.state().selection)).toBe('h17');
  await page.waitForTimeout(300);
  await page.screenshot({ path: testInfo.outputPath('embed-600x460.png') });
  const view = (await frame.locator('#viewport').boundingBox())!;
  const legend = (await frame.locator('#legend').boundingBox())!;
  const hud = (await frame.locator('#hud').boundingBox())!;
  // the short forms, on compact lines: together the two cover well under a third of the view
  await expect(frame.locator('#hud')).toContainText('✓ valid');
  expect((legend.width * legend.height + hud.width * hud.height) / (view.width * view.height)).toBeLessThan(0.2);
  // every vertex in the view, below the overlays, and the torus centred across the view
  const points = await lab.evaluate(() => {
    const { vertices } = window.halfedgeLab.state().stats!;
    return Array.from({ length: vertices }, (_, v) => window.halfedgeLab.screenPosition(`v${v}`));
  });
  const xs = points.map((p) => p.x);
  const ys = points.map((p) => p.y);
  expect(Math.min(...xs)).toBeGreaterThanOrEqual(0);
  expect(Math.max(...xs)).toBeLessThanOrEqual(view.width);
  expect(Math.max(...ys)).toBeLessThanOrEqual(view.height);
  expect(Math.min(...ys)).toBeGreaterThan(Math.max(legend.y + legend.height, hud.y + hud.height) - view.y - 4);
  const centre = (Math.min(...xs) + Math.max(...xs)) / 2;
  expect(Math.abs(centre - view.width / 2)).toBeLessThan(0.08 * view.width);
});
