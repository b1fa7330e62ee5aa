import { expect, type Page, test } from '@playwright/test';
import { mergeSoups, soupFromArrays, torus, writeSoup } from '../src/index.js';
import { openApp } from './helpers.js';

const state = (page: Page) => page.evaluate(() => window.halfedgeLab.state());

/** Opens a mesh written here through the file input, as a student uploads one. */
async function upload(page: Page, name: string, bytes: Uint8Array, faces: number): Promise<void> {
  await page.locator('#file-input').setInputFiles({ name, mimeType: 'text/plain', buffer: Buffer.from(bytes) });
  await expect.poll(async () => (await state(page)).stats?.faces).toBe(faces);
}

test.describe('the words of the lecture', () => {
  test('says boundary loops, not holes, and gives two separate tori the genus 1 + 1', async ({ page }) => {
    await openApp(page, 'torus.off');
    const hud = page.locator('#hud');
    await expect(hud).toContainText('boundary loops');
    await expect(hud).not.toContainText('holes');
    await expect(hud.locator('[data-count="boundary loops"]')).toHaveText('0');
    await expect(hud.locator('[data-count="genus"]')).toHaveText('1');

    // a plane cuts a torus into pieces of genus 0 at most: two tori come from a file
    const second = torus(8, 6);
    for (let i = 0; i < second.positions.length; i += 3) second.positions[i] += 3;
    await upload(page, 'two-tori.off', writeSoup(mergeSoups([torus(8, 6), second]), 'off'), 96);
    const { stats } = await state(page);
    expect([stats!.components, stats!.genus, stats!.genusPerPart]).toEqual([2, 2, [1, 1]]);
    await expect(hud.locator('[data-count="genus"]')).toHaveText('1 + 1');
    await expect(hud.locator('.count', { has: page.locator('[data-count="genus"]') })).toContainText('genus');
  });

  test('lists the boundary loops with their lengths, and frames one', async ({ page }) => {
    await openApp(page, 'annulus.off');
    const { boundaryLoops, stats } = await state(page);
    expect(boundaryLoops).toHaveLength(2);
    expect(boundaryLoops.reduce((sum, loop) => sum + loop.length, 0)).toBe(stats!.boundaryEdges);
    // each loop: its halfedge has no face, and next comes back to it after `length` steps
    const walked = await page.evaluate((loops) => {
      const lab = window.halfedgeLab;
      return loops.map(({ halfedge }) => {
        const names = [`h${halfedge}`];
        for (let h = lab.record(names[0]!).next!; h !== names[0]; h = lab.record(h).next!) names.push(h);
        return { faceless: names.every((h) => lab.record(h).face!.startsWith('none')), length: names.length };
      });
    }, boundaryLoops);
    expect(walked).toEqual(boundaryLoops.map(({ length }) => ({ faceless: true, length })));
    const list = page.getByRole('list', { name: 'Boundary loops' });
    for (const [i, { length }] of boundaryLoops.entries()) await expect(list).toContainText(`loop ${i + 1}: ${length} edges`);

    // the inner rim, the loop drawn smaller, is smaller than the mesh: framing it brings the camera closer
    const spread = (loop: number) =>
      page.evaluate((h) => {
        const lab = window.halfedgeLab;
        const names = [`h${h}`];
        for (let g = lab.record(names[0]!).next!; g !== names[0]; g = lab.record(g).next!) names.push(g);
        const points = names.map((name) => lab.screenPosition(name));
        const xs = points.map((p) => p.x);
        const canvas = document.querySelector('#viewport canvas')!.getBoundingClientRect();
        const inView = points.every((p) => p.visible && p.x >= 0 && p.y >= 0 && p.x <= canvas.width && p.y <= canvas.height);
        return { width: Math.max(...xs) - Math.min(...xs), inView };
      }, boundaryLoops[loop]!.halfedge);
    const widths = [(await spread(0)).width, (await spread(1)).width];
    const inner = widths[0]! < widths[1]! ? 0 : 1;
    await page.getByRole('button', { name: `Frame boundary loop ${inner + 1}` }).click();
    const after = await spread(inner);
    expect(after.inView).toBe(true);
    expect(after.width).toBeGreaterThan(1.3 * widths[inner]!);
    expect((await state(page)).selection).toBe(`h${boundaryLoops[inner]!.halfedge}`);
    expect(await page.evaluate(() => window.halfedgeLab.frameBoundaryLoop(5))).toBe(false);
  });

  test('keeps a long list of loops short: the first three and how many more', async ({ page }) => {
    await openApp(page, 'cube.off');
    // five separate triangles: five boundary loops of three edges
    const positions = [...Array(5).keys()].flatMap((i) => [2 * i, 0, 0, 2 * i + 1, 0, 0, 2 * i, 1, 0]);
    const faces = [...Array(5).keys()].map((i) => [3 * i, 3 * i + 1, 3 * i + 2]);
    await upload(page, 'five.off', writeSoup(soupFromArrays(positions, faces), 'off'), 5);
    expect((await state(page)).boundaryLoops).toHaveLength(5);
    const list = page.getByRole('list', { name: 'Boundary loops' });
    await expect(list.getByRole('button')).toHaveCount(3);
    await expect(list).toContainText('and 2 more');
    await expect(page.locator('#hud [data-count="genus"]')).toHaveText('0 + 0 + 0 + 0 + …');
  });
});

test.describe('the cutting plane', () => {
  for (const end of ['step', 'cancel'] as const) {
    test(`is hidden once the cut ends (${end === 'step' ? 'stepped to its end' : 'cancelled'})`, async ({ page }) => {
      await openApp(page, 'torus.off');
      await page.getByRole('tab', { name: 'Operate' }).click();
      await page.getByRole('spinbutton', { name: 'Plane coefficient c' }).fill('1');
      await page.getByRole('spinbutton', { name: 'Plane coefficient b' }).fill('0');
      const show = page.getByRole('button', { name: 'Show plane' });
      await show.click();
      expect((await state(page)).planeShown).toBe(true);
      await page.locator('[data-operation="cut"]').click();
      await expect.poll(async () => (await state(page)).stepping).not.toBeNull();
      if (end === 'step') {
        while ((await state(page)).stepping) await page.evaluate(() => window.halfedgeLab.step());
      } else await page.evaluate(() => window.halfedgeLab.cancel());
      expect((await state(page)).planeShown).toBe(false);
      await expect(show).toHaveAttribute('aria-pressed', 'false');
    });
  }

  test('is hidden when another mesh is opened', async ({ page }) => {
    await openApp(page, 'torus.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.getByRole('button', { name: 'Show plane' }).click();
    expect((await state(page)).planeShown).toBe(true);
    await page.getByRole('combobox', { name: /sample/i }).selectOption('cube.off');
    await expect.poll(async () => (await state(page)).file?.name).toBe('cube.off');
    expect((await state(page)).planeShown).toBe(false);
  });
});
