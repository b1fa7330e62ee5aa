/**
 * Ready for a lecture: the key help over everything and whole on a projector, the keys at once
 * after a file is opened, the glTF export's triangles said before saving, and the Practice tab
 * without stray errors (a second Ctrl+Enter, the editor under the page's Content-Security-Policy,
 * a solution that runs out of memory told so).
 */
import { expect, type Page, test } from '@playwright/test';
import { appErrors, openApp, openAppAt } from './helpers.js';

/**
 * Where the key help stands: whether it is what shows at its own centre and over every label of
 * the view, and whether its last key, scrolled to, is in its list, on screen and uncovered.
 */
function helpPlacement(page: Page) {
  return page.evaluate(() => {
    // the labels let clicks through to the view, and so does elementFromPoint: for this look
    // they catch the pointer, as they would a click if they were drawn over the help
    const layer = document.querySelector<HTMLElement>('#viewport .labels')!;
    layer.style.pointerEvents = 'auto';
    const inHelp = (x: number, y: number) => document.getElementById('help-overlay')!.contains(document.elementFromPoint(x, y));
    const card = document.querySelector('.help-card')!.getBoundingClientRect();
    const labels = [...document.querySelectorAll('#viewport .label')]
      .map((label) => label.getBoundingClientRect())
      .filter((box) => box.width > 0 && box.right > 0 && box.bottom > 0 && box.left < innerWidth && box.top < innerHeight);
    const labelsOnTop = labels.filter((box) => !inHelp(box.left + box.width / 2, box.top + box.height / 2)).length;
    layer.style.pointerEvents = '';
    const rows = [...document.querySelectorAll('#help-keys .key-row')];
    const last = rows.at(-1)!;
    last.scrollIntoView({ block: 'nearest' });
    const list = document.getElementById('help-keys')!.getBoundingClientRect();
    const row = last.getBoundingClientRect();
    return {
      onTopAtCentre: inHelp(card.left + card.width / 2, card.top + card.height / 2),
      labels: labels.length,
      labelsOnTop,
      lastText: last.textContent,
      lastInList: row.top >= list.top - 1 && row.bottom <= list.bottom + 1,
      lastOnScreen: row.top >= 0 && row.bottom <= innerHeight && row.left >= 0 && row.right <= innerWidth,
      lastUncovered: last.contains(document.elementFromPoint(row.left + 10, row.top + row.height / 2)),
    };
  });
}

test.describe('the key help', () => {
  for (const [width, height] of [
    [1280, 720],
    [1024, 768],
  ] as const) {
    for (const presentation of [false, true]) {
      test(`at ${width} × ${height}${presentation ? ' in presentation mode' : ''}, it is drawn over the labels and every key can be reached`, async ({ page }, testInfo) => {
        await page.setViewportSize({ width, height });
        await openApp(page, 'torus.off');
        await page.evaluate(() => window.halfedgeLab.select('h17'));
        if (presentation) {
          await page.keyboard.press('m');
          await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
        }
        await page.keyboard.press('z'); // the selection framed: its labels in the middle of the view
        await expect(page.locator('#viewport .label').first()).toBeVisible();
        await page.keyboard.press('?');
        await expect(page.getByRole('dialog', { name: 'Keys' })).toBeVisible();
        const placement = await helpPlacement(page);
        expect(placement.labels).toBeGreaterThan(0);
        expect(placement).toMatchObject({ onTopAtCentre: true, labelsOnTop: 0, lastText: expect.stringContaining('this help'), lastInList: true, lastOnScreen: true, lastUncovered: true });
        await expect(page.getByRole('button', { name: 'Close the key help' })).toBeInViewport({ ratio: 1 });
        await page.screenshot({ path: testInfo.outputPath('help.png') });
        await page.keyboard.press('Escape');
        await expect(page.getByRole('dialog', { name: 'Keys' })).toBeHidden();
      });
    }
  }
});

test('the keys, the toolbar buttons, the help and the automation come from one table of commands', async ({ page }) => {
  await openApp(page, 'torus.off');
  const listed = await page.evaluate(() => window.halfedgeLab.commands());
  const topView = listed.find((c) => c.name === 'top-view')!;
  expect(topView).toMatchObject({ keys: ['o'], label: 'Top view', unavailable: null });
  // the button's name, key and tooltip are the table's
  const button = page.locator('#top-view');
  await expect(button).toHaveAccessibleName('Top view');
  await expect(button).toHaveAttribute('aria-keyshortcuts', 'O');
  await expect(button).toHaveAttribute('title', `${topView.help.charAt(0).toUpperCase()}${topView.help.slice(1)} (O)`);
  // the command runs as its key and its button do
  expect(await page.evaluate(() => window.halfedgeLab.command('top-view'))).toBeNull();
  await expect(button).toHaveAttribute('aria-pressed', 'true');
  await page.keyboard.press('o');
  await expect(button).toHaveAttribute('aria-pressed', 'false');
  // one part: the exploded view does not apply, and running it says why
  const why = await page.evaluate(() => window.halfedgeLab.command('explode'));
  expect(why).toMatch(/one connected part/);
  await expect(page.locator('#status')).toHaveText(`Explode parts is not available: ${why}.`);
  await expect(page.evaluate(() => window.halfedgeLab.command('fly'))).rejects.toThrow(/there is no command 'fly' \(commands: walk-next, /);
  // under the target naming, the help's V line says the vertex it walks to is the target
  await page.evaluate(() => window.halfedgeLab.setConvention('target'));
  await page.keyboard.press('?');
  await expect(page.locator('#help-keys .key-row', { hasText: /^V/ })).toHaveText('Vtarget: the vertex the halfedge points to');
  await expect(page.locator('#help-keys .key-row', { hasText: /^R/ })).toContainText('rotate clockwise around the vertex the halfedge starts from');
  expect(await page.locator('#help-keys .key-row').count()).toBe(listed.filter((c) => c.keys.length > 0).length);
});

test('after a file is opened from the picker, the keys work at once', async ({ page }) => {
  await openApp(page, 'disk.off');
  const input = page.locator('#file-input');
  // where choosing a file leaves the focus: on the picker's input
  await input.focus();
  await input.setInputFiles({ name: 'triangle.off', mimeType: 'text/plain', buffer: Buffer.from('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n') });
  await expect(page.locator('#status')).toHaveText('Opened triangle.off.');
  await page.keyboard.press('m');
  await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
  expect(appErrors(page)).toEqual([]);
});

test('after a sample is chosen from the menu, the keys are the view\'s: M is presentation mode, not the Möbius strip', async ({ page }) => {
  await openApp(page, 'disk.off');
  // where choosing from the menu leaves the focus: on the menu
  const menu = page.getByRole('combobox', { name: 'Sample model' });
  await menu.focus();
  await menu.selectOption('cube.off');
  await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('cube.off');
  await page.keyboard.press('m');
  await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
  expect(await page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('cube.off');
});

test('the glTF export says, before saving, how many polygons become how many triangles', async ({ page }, testInfo) => {
  for (const [width, height] of [
    [1280, 720],
    [1024, 768],
  ] as const) {
    await page.setViewportSize({ width, height });
    await openApp(page, 'torus.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    const note = page.locator('#gltf-note');
    await expect(note).toHaveText('glTF holds only triangles: the 128 quads become 256 triangles. The other formats keep the faces as they are.');
    await expect(page.getByRole('button', { name: 'Export the mesh as glTF (.glb)' })).toHaveAccessibleDescription(/the 128 quads become 256 triangles/);
    for (const presentation of [false, true]) {
      if (presentation) await page.keyboard.press('m');
      await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', String(presentation));
      await note.scrollIntoViewIfNeeded();
      await expect(note).toBeInViewport({ ratio: 1 });
      await page.screenshot({ path: testInfo.outputPath(`gltf-${width}x${height}${presentation ? '-presentation' : ''}.png`) });
    }
  }
  // a mesh of triangles only: nothing to say
  expect(await page.evaluate(() => window.halfedgeLab.openSample('tetrahedron.off'))).toBe(true);
  await expect(page.locator('#gltf-note')).toBeHidden();
  expect(appErrors(page)).toEqual([]);
});

test.describe('Practice', () => {
  test('opening the tab logs no Content-Security-Policy error, and Ctrl+Enter twice runs once without a page error', async ({ page }) => {
    await openApp(page, 'disk.off');
    const pageErrors: string[] = [];
    page.on('pageerror', (error) => pageErrors.push(error.message));
    const consoleErrors: string[] = [];
    page.on('console', (message) => void (message.type() === 'error' && consoleErrors.push(message.text())));
    await page.getByRole('tab', { name: 'Practice' }).click();
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    await page.locator('.practice-editor .cm-content').click();
    expect(consoleErrors.filter((text) => /Content.Security.Policy/i.test(text))).toEqual([]);

    await page.keyboard.press('Control+Enter');
    await page.keyboard.press('Control+Enter');
    await expect(page.locator('.practice-summary')).toHaveText(/checks pass\.$/, { timeout: 15_000 });
    expect(pageErrors).toEqual([]);
    expect(appErrors(page)).toEqual([]);
  });

  test('a solution that allocates without bound is told it used too much memory', async ({ page }) => {
    await openAppAt(page, '/?exercise=vertex-degree');
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    await page.evaluate(() =>
      window.halfedgeLab.practice.setCode('export default function (mesh, v) {\n  const all = [];\n  for (;;) all.push(new Array(1e5).fill(v));\n}\n'),
    );
    const result = await page.evaluate(() => window.halfedgeLab.practice.run());
    expect(result.checks[0].message).toMatch(/memory/);
    expect(result.checks[0].message).not.toMatch(/loop/);
    await expect(page.locator('.practice-checks')).toContainText('memory');
    expect(appErrors(page)).toEqual([]);
  });
});
