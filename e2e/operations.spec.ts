import { readFileSync } from 'node:fs';
import { expect, type Page, test } from '@playwright/test';
import { cube, mergeSoups, torus, writeSoup } from '../src/index.js';
import { clickCanvas, openApp, openAppAt, stats } from './helpers.js';


type Box = { left: number; top: number; right: number; bottom: number };
const area = (r: Box) => Math.max(0, r.right - r.left) * Math.max(0, r.bottom - r.top);
const overlap = (a: Box, b: Box) =>
  area({ left: Math.max(a.left, b.left), top: Math.max(a.top, b.top), right: Math.min(a.right, b.right), bottom: Math.min(a.bottom, b.bottom) });

/**
 * The view tells a repair: exactly these labels, in words; each inside the view, none over another
 * by more than a sliver (4 % of the smaller); and each of `faces` (corners by name) seen on screen
 * at no less than a quarter of the largest one's size, so none is edge-on.
 */
async function expectStory(page: Page, words: string[], faces: string[][]): Promise<void> {
  const labels = page.locator('#viewport .label');
  await expect(labels).toHaveText(words);
  await expect(page.locator('#viewport')).not.toContainText(/non-manifold-(edge|vertex)/);
  const boxes = await labels.evaluateAll((tags) => tags.map((tag) => tag.getBoundingClientRect().toJSON() as Box));
  const view = await page.locator('#viewport').evaluate((node) => node.getBoundingClientRect().toJSON() as Box);
  for (const [i, r] of boxes.entries()) {
    expect(r.left >= view.left && r.right <= view.right && r.top >= view.top && r.bottom <= view.bottom, `label ${i} inside the view`).toBe(true);
  }
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      expect(overlap(boxes[i]!, boxes[j]!), `labels ${i} and ${j}`).toBeLessThanOrEqual(0.04 * Math.min(area(boxes[i]!), area(boxes[j]!)));
    }
  }
  const sizes = await page.evaluate(
    (corners) =>
      corners.map(([a, b, c]) => {
        const [p, q, r] = [a, b, c].map((v) => window.halfedgeLab.screenPosition(v!));
        return Math.abs((q!.x - p!.x) * (r!.y - p!.y) - (r!.x - p!.x) * (q!.y - p!.y)) / 2;
      }),
    faces,
  );
  for (const [i, size] of sizes.entries()) expect(size, `face ${faces[i]!.join(' ')} seen edge-on`).toBeGreaterThan(0.25 * Math.max(...sizes));
}
const valid = (page: Page) => page.locator('#hud [data-valid]').getAttribute('data-valid');
/** Where the page draws each element, on the canvas. */
const drawnAt = (page: Page, names: string[]) => page.evaluate((names) => names.map((name) => window.halfedgeLab.screenPosition(name)), names);
type Point = { x: number; y: number };
const distance = (p: Point, q: Point) => Math.hypot(p.x - q.x, p.y - q.y);
/** The pairs of points drawn on the same spot, as their indices. */
const samePlace = (points: Point[]) => points.flatMap((p, i) => points.flatMap((q, j) => (j > i && distance(p, q) < 0.01 ? [[i, j] as const] : [])));
/** How far apart the two points of each pair are drawn. */
const gaps = (points: Point[], pairs: ReadonlyArray<readonly [number, number]>) => pairs.map(([i, j]) => distance(points[i]!, points[j]!));

test.describe('stepping operations, history and export', () => {
  test('opens a valid file through the file input, then refuses a broken one keeping the first', async ({ page }) => {
    await openApp(page, 'cube.off');
    await page.locator('#file-input').setInputFiles({ name: 'torus.obj', mimeType: 'text/plain', buffer: Buffer.from(writeSoup(torus(6, 4), 'obj')) });
    await expect.poll(async () => (await stats(page)).faces).toBe(24);
    await page.locator('#file-input').setInputFiles({ name: 'broken.ply', mimeType: 'text/plain', buffer: Buffer.from('ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n2\n') });
    await expect(page.locator('#error-panel')).toBeVisible();
    await expect(page.locator('#error-message')).toContainText('ply:');
    expect((await stats(page)).faces).toBe(24);
    await page.getByRole('button', { name: 'Dismiss the error' }).click();
    await expect(page.locator('#error-panel')).toBeHidden();
  });

  test('shows text from a file as text, never as markup', async ({ page }) => {
    await openApp(page, 'cube.off');
    const hostile = '<img src=x onerror="window.injected=1"><b>bold</b>';
    const ply = `ply\nformat ascii 1.0\ncomment ${hostile}\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n`;
    await page.locator('#file-input').setInputFiles({ name: `${hostile}.ply`, mimeType: 'text/plain', buffer: Buffer.from(ply) });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(1);
    await page.getByRole('tab', { name: 'File' }).click();
    await page.locator('#file-info summary', { hasText: 'Comments in the file' }).click();
    await expect(page.locator('#file-info')).toContainText(hostile);
    expect(await page.locator('#file-info img, #file-info b, #status img').count()).toBe(0);
    expect(await page.evaluate(() => (window as unknown as { injected?: number }).injected)).toBeUndefined();
  });

  test('lists what the builder repaired, and each entry shows where', async ({ page }, testInfo) => {
    await openApp(page, 'non-manifold.obj');
    await page.getByRole('tab', { name: 'File' }).click();
    const repairs = page.locator('#file-info [data-repair]');
    await expect(repairs).toHaveCount(2);
    await page.locator('[data-repair="non-manifold-vertex"] summary').click();
    await page.getByRole('button', { name: /^Show: vertex 0 joined 2 fans/ }).click();
    // the copy of the pinched vertex is selected, and both copies are marked
    const selection = await page.evaluate(() => window.halfedgeLab.state().selection);
    expect(selection).toMatch(/^v\d+$/);
    await expect(page.locator('#status')).toContainText('vertex 0 joined 2 fans');
    // told in words, fan by fan: the file's vertex, and the mesh's copies
    await expect(page.locator('.labels')).toContainText('file vertex 0 joined 2 fans: this one keeps v0');
    await expect(page.locator('.labels')).toContainText('this fan got its own copy, v12');
    await page.screenshot({ path: testInfo.outputPath('repairs.png') });
  });

  // framed on its culprit, the sample was a pile of six overlapping labels with raw slugs
  // ("non-manifold-edge f3"), clipped at the top of the view, and the pinched fan seen edge-on
  for (const [width, height] of [
    [1280, 720],
    [1024, 768],
  ] as const) {
    for (const presentation of [false, true]) {
      test(`at ${width} × ${height}${presentation ? ' in presentation mode' : ''}, tells each repair of the non-manifold sample in words, labels apart and in view, faces not edge-on`, async ({
        page,
      }, testInfo) => {
        await page.setViewportSize({ width, height });
        await openApp(page, 'non-manifold.obj');
        if (presentation) await page.keyboard.press('m');
        const name = `${width}x${height}${presentation ? '-presentation' : ''}`;
        await page.waitForTimeout(700);
        await expectStory(page, ['file edge 6–5 had 3 faces: f2 and f3 keep it', 'f4 detached, with its own copies v10 and v11'], [
          ['v5', 'v7', 'v6'],
          ['v5', 'v6', 'v8'],
          ['v10', 'v11', 'v9'],
        ]);
        await page.screenshot({ path: testInfo.outputPath(`story-edge-${name}.png`) });

        await page.getByRole('tab', { name: 'File' }).click();
        await page.locator('[data-repair="non-manifold-vertex"] summary').click();
        await page.getByRole('button', { name: /^Show: vertex 0 joined 2 fans/ }).click();
        await page.waitForTimeout(700);
        await expectStory(page, ['file vertex 0 joined 2 fans: this one keeps v0', 'this fan got its own copy, v12'], [
          ['v0', 'v1', 'v2'],
          ['v12', 'v3', 'v4'],
        ]);
        await page.screenshot({ path: testInfo.outputPath(`story-pinch-${name}.png`) });
      });
    }
  }

  // two tetrahedra sharing a vertex opened with "Opened …" and a green check, V = 8 where the file
  // has 7, and the split vertex hidden behind a face: the repair was easy to miss
  test('says on opening that a file was repaired, frames the culprit, and leads to the list', async ({ page }, testInfo) => {
    await openApp(page, 'disk.off');
    const tetrahedra =
      'OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n' +
      '3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 5 4\n3 0 4 6\n3 0 6 5\n3 4 5 6\n';
    expect(await page.evaluate((text) => window.halfedgeLab.open(new TextEncoder().encode(text), 'two-tetrahedra.off'), tetrahedra)).toBe(true);
    const status = page.locator('#status');
    await expect(status).toContainText('Opened two-tetrahedra.off, repaired: 1 vertex joined several separate fans of faces');
    // the copy of the shared vertex is selected and in sight
    const selection = (await page.evaluate(() => window.halfedgeLab.state().selection))!;
    expect(selection).toBe('v7');
    // (the camera glides there)
    await expect.poll(() => page.evaluate((v) => window.halfedgeLab.screenPosition(v).visible, selection)).toBe(true);
    await page.waitForTimeout(700);
    await page.screenshot({ path: testInfo.outputPath('repaired-on-open.png') });
    await status.getByRole('button', { name: 'Show the repairs' }).click();
    await expect(page.locator('#pane-file')).toBeVisible();
    await expect(page.locator('#file-info [data-repair="non-manifold-vertex"]')).toHaveAttribute('open', '');
  });

  test('steps Loop subdivision phase by phase with the invariants holding after each', async ({ page }, testInfo) => {
    await openApp(page, 'tetrahedron.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.locator('[data-operation="loop"]').click();
    await expect(page.locator('.phase-title')).toContainText('Loop subdivision: ready');
    // V, E, F after each phase: split edges (hexagons), cut corners, then positions only
    const expected = [
      [10, 12, 4],
      [10, 24, 16],
      [10, 24, 16],
      [10, 24, 16],
    ];
    for (let phase = 1; phase <= 4; phase++) {
      await page.getByRole('button', { name: 'Step one phase (S)' }).click();
      await expect.poll(async () => (await page.evaluate(() => window.halfedgeLab.state().version))).toBeGreaterThan(0);
      await expect(page.locator('.phase-title')).toContainText(phase < 4 ? `phase ${phase} of 4` : 'done');
      const { vertices, edges, faces } = await stats(page);
      expect([vertices, edges, faces]).toEqual(expected[phase - 1]);
      expect(await valid(page)).toBe('true');
      await page.screenshot({ path: testInfo.outputPath(`loop-phase-${phase}.png`) });
    }
    const history = await page.evaluate(() => window.halfedgeLab.state().history!);
    expect(history.items.map((i) => i.label)).toEqual(['open tetrahedron.off', 'Loop subdivision']);
  });

  test('steps a capped plane cut phase by phase into two closed pieces', async ({ page }, testInfo) => {
    await openApp(page, 'torus.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    for (const [coefficient, value] of [['a', '0'], ['b', '1'], ['c', '0'], ['d', '0.05']]) {
      await page.getByRole('spinbutton', { name: `Plane coefficient ${coefficient}` }).fill(value);
    }
    await page.getByRole('button', { name: 'Show plane' }).click();
    await page.screenshot({ path: testInfo.outputPath('cut-plane.png') });
    await page.locator('[data-operation="cut"]').click();
    for (let phase = 1; phase <= 6; phase++) {
      await page.getByRole('button', { name: 'Step one phase (S)' }).click();
      await expect(page.locator('.phase-title')).toContainText(phase < 6 ? `phase ${phase} of 6` : 'done');
      expect(await valid(page)).toBe('true');
    }
    await page.screenshot({ path: testInfo.outputPath('cut-done.png') });
    const after = await stats(page);
    // a torus cut across its ring: two bent tubes, each closed by two caps
    expect(after.components).toBe(2);
    expect(after.closed).toBe(true);
    expect(after.genus).toBe(0);
  });

  test('pulls the two capped sides of a cut torus apart in the view, leaving the mesh as it is', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openApp(page, 'torus.off');
    const explode = page.locator('#explode');
    const lab = <T,>(run: () => T | Promise<T>) => page.evaluate(run);
    // one part: nothing to pull apart, and the button says so
    await expect(explode).toHaveAttribute('aria-disabled', 'true');
    await expect(explode).toHaveAccessibleName('Explode parts (not available: the mesh is one connected part: there is nothing to pull apart)');

    // the plane y = −0.05, both sides kept and capped (the panel's defaults), stepped to the end
    await page.getByRole('tab', { name: 'Operate' }).click();
    for (const [coefficient, value] of [['a', '0'], ['b', '1'], ['c', '0'], ['d', '0.05']]) {
      await page.getByRole('spinbutton', { name: `Plane coefficient ${coefficient}` }).fill(value);
    }
    await page.locator('[data-operation="cut"]').click();
    for (let phase = 1; phase <= 6; phase++) await page.getByRole('button', { name: 'Step one phase (S)' }).click();
    await expect(page.locator('.phase-title')).toContainText('done');
    // the status line says how to see the caps, which lie face to face
    await expect(page.locator('#status')).toContainText('press B to see them pulled apart');
    // the cap faces: those the last phase made
    const caps = await lab(() => window.halfedgeLab.state().phase!.diff!.changes.filter((c) => c.field === 'fHalfedge' && c.old === -1).map((c) => c.index));
    expect(caps.length).toBeGreaterThanOrEqual(4);
    const corners = await page.evaluate((faces) => {
      const { record } = window.halfedgeLab;
      const corners = new Set<string>();
      for (const f of faces) {
        const start = record(`f${f}`).halfedge!;
        let h = start;
        do {
          corners.add(record(h).origin!);
          h = record(h).next!;
        } while (h !== start);
      }
      return [...corners];
    }, caps);
    // each side has its own copy of every corner of the cut, drawn on the other side's
    const twins = samePlace(await drawnAt(page, corners));
    expect(twins.flat().sort((a, b) => a - b)).toEqual(corners.map((_, i) => i));
    await stats(page); // the full counts, which follow the last phase's patch
    const before = await lab(async () => ({ stats: window.halfedgeLab.state().stats, fingerprints: await window.halfedgeLab.fingerprints() }));
    expect(before.fingerprints.page).toBe(before.fingerprints.session);

    await expect(explode).toHaveAccessibleName('Explode parts');
    await explode.click();
    await expect(explode).toHaveAttribute('aria-pressed', 'true');
    expect(await lab(() => window.halfedgeLab.state().exploded)).toBe(true);
    await expect(page.locator('#status')).toContainText('the mesh itself has not moved');
    // a link carries it: another page opens on the cut torus pulled apart, each corner where it is drawn here
    const link = await lab(() => window.halfedgeLab.shareLink());
    expect(link).toContain('&explode=on');
    const second = await page.context().newPage();
    await second.setViewportSize({ width: 1280, height: 720 });
    await openAppAt(second, link);
    await expect.poll(() => second.evaluate(() => window.halfedgeLab.state().exploded)).toBe(true);
    const here = await drawnAt(page, corners);
    const there = await drawnAt(second, corners);
    for (let i = 0; i < corners.length; i++) expect(distance(here[i]!, there[i]!)).toBeLessThan(2);
    await second.close();
    // the copies of each corner now stand well apart on screen…
    const { height } = (await page.locator('#viewport canvas').boundingBox())!;
    for (const gap of gaps(await drawnAt(page, corners), twins)) expect(gap).toBeGreaterThan(0.05 * height);
    // …and the mesh has not moved: the same counts, and the session and the page hold the same arrays
    const after = await lab(async () => ({ stats: window.halfedgeLab.state().stats, fingerprints: await window.halfedgeLab.fingerprints() }));
    expect(after).toEqual(before);

    // a click where a cap is drawn picks it, and its arrows pick their halfedges
    const seen = await page.evaluate(async (faces) => {
      const lab = window.halfedgeLab;
      const picked: number[] = [];
      for (const f of faces) {
        const { x, y } = lab.screenPosition(`f${f}`);
        if ((await lab.pickAt(x, y, 'face')) === `f${f}`) picked.push(f);
      }
      return picked;
    }, caps);
    // the camera looks from above: the caps of the side below face it, two of the four
    expect(seen.length).toBeGreaterThanOrEqual(2);
    const cap = seen[0]!;
    const { x, y } = await page.evaluate((f) => window.halfedgeLab.screenPosition(`f${f}`), cap);
    await page.getByRole('combobox', { name: 'What a click picks' }).selectOption('face');
    await clickCanvas(page, x, y);
    expect(await lab(() => window.halfedgeLab.state().selection)).toBe(`f${cap}`);
    const arrow = await lab(() => window.halfedgeLab.record(window.halfedgeLab.state().selection!).halfedge!);
    const at = await page.evaluate((h) => window.halfedgeLab.screenPosition(h), arrow);
    expect(await page.evaluate(({ x, y }) => window.halfedgeLab.pickAt(x, y, 'halfedge'), at)).toBe(arrow);
    await page.screenshot({ path: testInfo.outputPath('exploded-cut-1280x720.png') });
    await page.setViewportSize({ width: 1024, height: 768 });
    await page.keyboard.press('Home');
    await page.screenshot({ path: testInfo.outputPath('exploded-cut-1024x768.png') });
    // close up, the arrows of the selected cap lie on it where it is drawn
    await page.keyboard.press('z');
    await page.screenshot({ path: testInfo.outputPath('exploded-cap-close-up.png') });

    // B puts the parts back where they are
    await page.keyboard.press('b');
    expect(await lab(() => window.halfedgeLab.state().exploded)).toBe(false);
    await expect(explode).toHaveAttribute('aria-pressed', 'false');
    for (const gap of gaps(await drawnAt(page, corners), twins)) expect(gap).toBeLessThan(0.01);
    // on again, then undo the cut: one part, so the view is not exploded and the button says why
    expect(await lab(() => window.halfedgeLab.explode(true))).toBe(true);
    await page.keyboard.press('Control+z');
    await expect.poll(() => lab(() => window.halfedgeLab.state().exploded)).toBe(false);
    await expect(explode).toHaveAttribute('aria-disabled', 'true');
    expect(await lab(() => window.halfedgeLab.explode(true))).toBe(false);
    await expect(page.locator('#status')).toHaveText('No exploded view: the mesh is one connected part: there is nothing to pull apart.');
  });

  test('pulls the parts of a model of several apart from its centre, until another model opens', async ({ page }) => {
    await openApp(page, 'cube.off');
    // two unit cubes side by side, touching along x = 1
    const cubes = mergeSoups([cube(), cube()]);
    for (let i = 3 * 8; i < cubes.positions.length; i += 3) cubes.positions[i]! += 1;
    expect(await page.evaluate((bytes) => window.halfedgeLab.open(bytes, 'two-cubes.obj'), [...writeSoup(cubes, 'obj')])).toBe(true);
    const vertices = Array.from({ length: 16 }, (_, v) => `v${v}`);
    // the four corners of each cube on the face they share, drawn on the other cube's
    const twins = samePlace(await drawnAt(page, vertices));
    expect(twins).toHaveLength(4);
    await page.keyboard.press('b');
    expect(await page.evaluate(() => window.halfedgeLab.state().exploded)).toBe(true);
    for (const gap of gaps(await drawnAt(page, vertices), twins)) expect(gap).toBeGreaterThan(20);
    await page.evaluate(() => window.halfedgeLab.openSample('torus.off'));
    expect(await page.evaluate(() => window.halfedgeLab.state().exploded)).toBe(false);
    await expect(page.locator('#explode')).toHaveAttribute('aria-pressed', 'false');
  });

  test('says the exploded view is for meshes of up to 150,000 triangles on a larger one', async ({ page }) => {
    await openApp(page, 'cube.off');
    // 78,400 quads: 156,800 triangles, picked in a worker
    const base64 = Buffer.from(writeSoup(torus(280, 280), 'ply-binary')).toString('base64');
    expect(await page.evaluate((text) => window.halfedgeLab.open(Uint8Array.from(atob(text), (c) => c.charCodeAt(0)), 'fine-torus.ply'), base64)).toBe(true);
    await expect(page.locator('#explode')).toHaveAccessibleName('Explode parts (not available: it is for meshes of up to 150,000 triangles, and this one has 156,800)');
    expect(await page.evaluate(() => window.halfedgeLab.explode(true))).toBe(false);
    await expect(page.locator('#status')).toHaveText('No exploded view: it is for meshes of up to 150,000 triangles, and this one has 156,800.');
  });

  test('says what an edit did in the status line, and where an undo went back to', async ({ page }) => {
    await openApp(page, 'disk.off');
    await expect(page.locator('#status')).toHaveText('Opened disk.off.');
    // an inner edge of the disk: both of its halfedges have a face
    const edge = await page.evaluate(() => {
      const inner = (h: number) => window.halfedgeLab.record(`h${h}`).face.startsWith('f');
      for (let h = 0; ; h += 2) if (inner(h) && inner(h + 1)) return h >> 1;
    });
    await page.evaluate((h) => window.halfedgeLab.select(`h${h}`), 2 * edge);
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.getByRole('button', { name: 'Flip edge' }).click();
    await expect(page.locator('#status')).toHaveText(new RegExp(`^Flip e${edge}: \\d+ pointers changed\\. Ctrl\\+Z undoes it\\.$`));
    // the count said is the edit's pointer diff
    const total = await page.evaluate(() => window.halfedgeLab.state().phase!.diff!.total);
    expect(total).toBeGreaterThan(0);
    await expect(page.locator('#status')).toContainText(`: ${total} pointers changed`);
    await page.keyboard.press('Control+z');
    await expect(page.locator('#status')).toHaveText('Back to disk.off as opened.');
  });

  test('marks an operation that does not apply, with the reason, and undoes back to the start', async ({ page }) => {
    await openApp(page, 'cube.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    const loop = page.locator('[data-operation="loop"]');
    await expect(loop).toHaveAttribute('aria-disabled', 'true');
    await expect(loop).toHaveAttribute('title', /triangles/);
    await loop.click({ force: true }); // a click on it does nothing
    expect(await page.evaluate(() => window.halfedgeLab.state().stepping)).toBeNull();
    // two operations, then undo both
    await page.locator('[data-operation="catmull-clark"]').click();
    await page.getByRole('button', { name: 'Run to end (G)' }).click();
    await expect.poll(async () => (await stats(page)).faces).toBe(24);
    await page.evaluate(() => window.halfedgeLab.select('f3'));
    await page.locator('[data-edit="poke-face"]').click();
    await expect.poll(async () => (await stats(page)).faces).toBe(27);
    await expect(page.locator('.diff-table')).toBeVisible();
    await page.keyboard.press('Control+z');
    await expect.poll(async () => (await stats(page)).faces).toBe(24);
    await page.getByRole('button', { name: 'Undo (Ctrl+Z)' }).click();
    await expect.poll(async () => (await stats(page)).faces).toBe(6);
    await expect(page.getByRole('button', { name: 'Undo (Ctrl+Z) (not available: nothing to undo)' })).toBeVisible();
    // the timeline jumps forward again
    await page.getByRole('button', { name: 'Go back to: poke f3' }).click();
    await expect.poll(async () => (await stats(page)).faces).toBe(27);
  });

  test('smooths and decimates from the Operate panel, stepping with a colour map', async ({ page }, testInfo) => {
    await openApp(page, 'bunny.ply');
    await page.getByRole('tab', { name: 'Operate' }).click();
    const before = await stats(page);
    await page.getByRole('spinbutton', { name: 'Faces to keep' }).fill('1000');
    await page.locator('[data-operation="decimate"]').click();
    await page.getByRole('button', { name: 'Step one phase (S)' }).click();
    await expect(page.locator('.phase-title')).toContainText('compute quadrics');
    await expect(page.locator('#values-legend')).toBeVisible();
    await page.getByRole('button', { name: 'Step one phase (S)' }).click();
    await page.screenshot({ path: testInfo.outputPath('decimation-batch.png') });
    await page.getByRole('button', { name: 'Run to end (G)' }).click();
    await expect.poll(async () => (await stats(page)).faces).toBeLessThanOrEqual(1000);
    const after = await stats(page);
    expect([after.genus, after.closed, await valid(page)]).toEqual([before.genus, before.closed, 'true']);
    await expect(page.locator('#values-legend')).toBeHidden();

    // cotangent weights need triangles: fine here; a quad mesh says why not
    await page.getByRole('combobox', { name: 'Smoothing method' }).selectOption('taubin');
    await page.getByRole('spinbutton', { name: 'Smoothing iterations' }).fill('3');
    await page.locator('[data-operation="smooth"]').click();
    await page.getByRole('button', { name: 'Run to end (G)' }).click();
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().history?.items.at(-1)?.label)).toBe('Taubin smoothing, 3 iterations');
    expect((await stats(page)).faces).toBe(after.faces);
    await page.evaluate(() => window.halfedgeLab.openSample('cube.off'));
    await page.getByRole('combobox', { name: 'Smoothing method' }).selectOption('cotan');
    await expect(page.locator('[data-operation="smooth"]')).toHaveAttribute('title', /needs triangles/);
    await expect(page.locator('[data-operation="decimate"]')).toHaveAttribute('aria-disabled', 'true');
  });

  test('exports the edited mesh and opens the exported file again', async ({ page }) => {
    await openApp(page, 'tetrahedron.off');
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.locator('[data-operation="sqrt3"]').click();
    await page.getByRole('button', { name: 'Run to end (G)' }).click();
    await expect.poll(async () => (await stats(page)).faces).toBe(12);
    const downloading = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Export the mesh as OFF' }).click();
    const download = await downloading;
    expect(download.suggestedFilename()).toBe('tetrahedron-edited.off');
    const bytes = readFileSync((await download.path())!);
    await page.locator('#file-input').setInputFiles({ name: 'again.off', mimeType: 'text/plain', buffer: bytes });
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('again.off');
    const reopened = await stats(page);
    expect([reopened.vertices, reopened.edges, reopened.faces, reopened.genus]).toEqual([8, 18, 12, 0]);
    // the tables as JSON, and a picture of the view
    const tables = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Export the halfedge tables as JSON' }).click();
    const json = JSON.parse(readFileSync((await (await tables).path())!, 'utf8'));
    expect(json.halfedges).toHaveLength(2 * 18);
    const picture = page.waitForEvent('download');
    await page.getByRole('button', { name: 'Export a PNG of the view' }).click();
    const png = readFileSync((await (await picture).path())!);
    expect(png.subarray(1, 4).toString()).toBe('PNG');
  });
});

test.describe('stepping seen on a projector', () => {
  for (const [width, height] of [
    [1280, 720],
    [1024, 768],
  ]) {
    test(`at ${width} × ${height}, the view names the phase and what its colours mean`, async ({ page }, testInfo) => {
      await page.setViewportSize({ width, height });
      await openApp(page, 'tetrahedron.off');
      await page.getByRole('tab', { name: 'Operate' }).click();
      await page.locator('[data-operation="loop"]').click();
      await page.keyboard.press('s');
      const legend = page.locator('#legend');
      await expect(legend).toContainText('Loop subdivision — phase 1 of 4: split every edge');
      // what this phase's marks mean, and only that: splitting moves no vertex
      for (const meaning of ['created', 'rewired']) await expect(legend).toContainText(meaning);
      await expect(legend).not.toContainText('moved');
      await expect(legend).not.toContainText('prev');
      await expect(page.locator('#status')).toContainText('phase 1 of 4');
      // the phase's name is on screen, inside the view, not below the fold
      const box = (await legend.locator('.legend-phase').boundingBox())!;
      const view = (await page.locator('#viewport').boundingBox())!;
      expect(box.y + box.height).toBeLessThanOrEqual(Math.min(height, view.y + view.height));
      expect(box.x + box.width).toBeLessThanOrEqual(view.x + view.width);
      await page.screenshot({ path: testInfo.outputPath(`stepping-${width}x${height}.png`) });
      // the last Step ends the operation, and its phase stays: card, colours, diff, and the stepper
      for (let phase = 2; phase <= 4; phase++) await page.keyboard.press('s');
      await expect(legend).toContainText('Loop subdivision — phase 4 of 4 (done): move the old vertices');
      await expect(legend).toContainText('moved');
      await expect(legend.locator('.legend-phase')).toBeInViewport();
      expect(await page.evaluate(() => window.halfedgeLab.state().ended)).toEqual({ label: 'Loop subdivision', phases: 4, total: 4 });
      await expect(page.locator('.stepper-panel .diff')).toContainText(/pointer|No pointer changed/);
      await page.screenshot({ path: testInfo.outputPath(`last-phase-${width}x${height}.png`) });
      expect((await stats(page)).faces).toBe(16);
      // Previous phase: the phase before, its mesh and marks; Step goes forward to the end again
      await page.keyboard.press('Shift+S');
      await expect(legend).toContainText('Loop subdivision — phase 3 of 4: place the edge points');
      expect(await page.evaluate(() => window.halfedgeLab.state().stepping)).toEqual({ label: 'Loop subdivision', phases: 3, total: 4 });
      await page.keyboard.press('s');
      await expect(legend).toContainText('phase 4 of 4 (done)');
      // Undo after the end undoes the whole operation
      await page.keyboard.press('Control+z');
      await expect.poll(async () => (await stats(page)).faces).toBe(4);
      await expect(legend).toContainText('prev');
      // run to the end: the legend explains the pointer colours again
      await page.locator('[data-operation="loop"]').click();
      await page.keyboard.press('g');
      await expect(legend).toContainText('prev');
      await expect(legend).not.toContainText('rewired');
    });
  }
});
