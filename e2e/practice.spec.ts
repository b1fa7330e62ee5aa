import { readFileSync } from 'node:fs';
import { expect, type Page, test } from '@playwright/test';
import { appErrors, openApp, openAppAt, solution, typeAndRun } from './helpers';

test.describe('practice mode', () => {
  test('at 1280 × 720 the view, at least 20 lines of code and the writes of a run are in sight together', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openAppAt(page, '/?exercise=flip-edge');
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    await typeAndRun(page, readFileSync(new URL('../tests/practice/solutions/wrong/flip-forgets-vertex.js', import.meta.url), 'utf8'));
    await expect(page.locator('.practice-summary')).toContainText('checks pass', { timeout: 15_000 });
    await page.screenshot({ path: testInfo.outputPath('practice-1280x720.png') });
    // the editor's box (its text scrolls inside it) holds 20 lines, all of it on screen
    const editor = (await page.locator('.practice-editor').boundingBox())!;
    const line = (await page.locator('.practice-editor .cm-line').first().boundingBox())!;
    expect(editor.height / line.height).toBeGreaterThanOrEqual(20);
    await expect(page.locator('.practice-editor')).toBeInViewport({ ratio: 1 });
    await expect(page.getByRole('button', { name: 'Run the solution' })).toBeInViewport({ ratio: 1 });
    await expect(page.locator('.practice-write-list li.current')).toBeInViewport({ ratio: 0.95 });
    await expect(page.locator('.practice-broken')).toBeInViewport();
    const view = (await page.locator('#viewport').boundingBox())!;
    expect(view.width).toBeGreaterThan(500);
    expect(view.height).toBeGreaterThan(300);
  });

  test('?exercise=flip-edge: a correct flip passes, a wrong one is told its first broken invariant, and its writes can be stepped', async ({ page }, testInfo) => {
    await openAppAt(page, '/?exercise=flip-edge');
    await expect(page.locator('#tab-practice')).toHaveAttribute('aria-selected', 'true');
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    await expect(page.locator('.practice-task h3')).toHaveText('Flip an edge');
    // the view shows the mesh the exercise is about before any code has run
    await expect(page.locator('#status')).toHaveText('Practice: Flip an edge, an edge inside a disk, input 10.');
    const history = await page.evaluate(() => window.halfedgeLab.state().history!);
    expect(history.items[history.index].label).toBe('practice: Flip an edge, an edge inside a disk, input 10');
    expect(history.items[history.index - 1].source.kind).toBe('open'); // undo goes back to the mesh the page had

    await typeAndRun(page, solution('flip-edge'));
    await expect(page.locator('.practice-summary')).toHaveText('All 16 checks pass.', { timeout: 15_000 });
    expect(await page.evaluate(async () => (await window.halfedgeLab.practice.state()).progress['flip-edge'])).toBe(true);

    await typeAndRun(page, solution('wrong/flip-forgets-vertex'));
    await expect(page.locator('.practice-summary')).toHaveText('13 of 16 checks pass.', { timeout: 15_000 });
    const broken = page.locator('.practice-broken');
    await expect(broken).toContainText(/First broken: v\d+'s halfedge h\d+ does not start at v\d+\. It broke at write \d+, origin\(h\d+\) = v\d+, line 2[34]/);
    // the culprit vertex is selected in the view, on the mesh the code left
    const state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.selection).toMatch(/^v\d+$/);
    expect(await page.evaluate(async () => (await window.halfedgeLab.practice.state()).shown)).toMatchObject({ fixture: 0, write: 18, drawn: 18 });
    await page.screenshot({ path: testInfo.outputPath('practice-wrong-flip.png') });

    // step back through the writes: the last ones are drawable, the half-way ones are said to be not
    await page.getByRole('button', { name: 'Show the previous write' }).click();
    await expect(page.locator('.practice-writes .note')).toContainText('after write 17 of 18');
    await page.getByRole('button', { name: 'Show the fixture before any write' }).click();
    await expect(page.locator('.practice-writes .note')).toHaveText('The view shows the fixture before any write.');
    await page.locator('.practice-write-list li').nth(0).getByRole('button').click();
    await expect(page.locator('.practice-writes .note')).toContainText('After write 1 the pointers are half-way rewired');
    // a state that cannot be drawn: the last one that can, with the writes since marked on it
    await expect(page.locator('#status')).toHaveText(/, write 1 marked\.$/);
    const firstWrite = await page.locator('.practice-write-list li').nth(0).getByRole('button').textContent();
    expect(firstWrite).toMatch(/^next\(h\d+\) = h\d+$/);
    await expect(page.locator('#viewport .label', { hasText: firstWrite! })).toBeVisible();
    // stepping keeps the keyboard on the button pressed
    await page.getByRole('button', { name: 'Show the next write' }).focus();
    await page.keyboard.press('Enter');
    await expect(page.locator('.practice-writes .note')).toContainText('After write 2 the pointers');
    await expect(page.locator('#status')).toHaveText(/, writes 1–2 marked\.$/);
    expect(await page.evaluate(() => document.activeElement?.getAttribute('aria-label'))).toBe('Show the next write');
    // in presentation mode the code is as large as every other text (the editor's shadow root too)
    await page.locator('#presentation').click();
    expect(await page.locator('.practice-editor .cm-content').evaluate((node) => parseFloat(getComputedStyle(node).fontSize))).toBeGreaterThanOrEqual(20);
    await page.locator('#presentation').click();
    expect(appErrors(page)).toEqual([]);
  });

  test('code that allocates without bound is stopped for its memory; a query\'s reads walk in the view; an error names its line', async ({ page }) => {
    await openAppAt(page, '/?exercise=vertex-degree');
    await expect(page.locator('.practice-editor .cm-editor')).toBeVisible();
    // code that allocates without bound is stopped for its memory, at its line, and the page lives on
    await page.evaluate((code) => window.halfedgeLab.practice.setCode(code), solution('wrong/allocates'));
    const allocated = await page.evaluate(() => window.halfedgeLab.practice.run());
    expect(allocated.checks.map((c) => c.passed)).toEqual([false, false, false, false]);
    expect(allocated.checks[0].message).toBe('stopped at line 3: your code used more than 256 MB of memory for arrays without returning: a list that keeps growing?');
    expect(await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => resolve(true))))).toBe(true);

    // a query's reads are walked in the view, one halfedge after another
    await typeAndRun(page, solution('vertex-degree'));
    await expect(page.locator('.practice-summary')).toHaveText('All 4 checks pass.', { timeout: 10_000 });
    const read = (await page.evaluate(async () => (await window.halfedgeLab.practice.state()).read))!;
    expect(read.total).toBeGreaterThan(2);
    expect(read.step).toBe(read.total - 1);
    await expect(page.locator('#viewport .label', { hasText: `read ${read.total}: h` })).toBeVisible();
    await page.evaluate(() => window.halfedgeLab.practice.showRead(0, 0));
    await expect(page.locator('#viewport .label', { hasText: /^read 1: h\d+$/ })).toBeVisible();
    await page.getByRole('button', { name: 'Play the reads' }).click();
    await expect.poll(async () => (await page.evaluate(async () => (await window.halfedgeLab.practice.state()).read))!.step, { timeout: 10_000 }).toBe(read.total - 1);
    await expect(page.getByRole('button', { name: 'Play the reads' })).toHaveAttribute('aria-pressed', 'false');

    await typeAndRun(page, 'export default function (mesh, v) {\n  const h = mesh.vertexHalfedge(v);\n  return h.length.value;\n}\n');
    await expect(page.locator('.practice-checks').first()).toContainText('your code threw TypeError at line 3', { timeout: 10_000 });
    await typeAndRun(page, 'export default function (mesh, v) {\n  return document.title;\n}\n');
    await expect(page.locator('.practice-checks')).toContainText('your code threw ReferenceError at line 2: document is not defined', { timeout: 10_000 });
    await typeAndRun(page, 'export default function (mesh, v) {\n  fetch("/models/index.json");\n  return 3;\n}\n');
    await expect(page.locator('.practice-checks')).toContainText('at line 2: fetch is not available to a solution', { timeout: 10_000 });
    await typeAndRun(page, 'export default function (mesh, v) {\n  return mesh.next(v;\n}\n');
    await expect(page.locator('.practice-summary')).toHaveText('The code cannot run: line 2: syntax error: Unexpected token (column 21)', { timeout: 10_000 });
    expect(appErrors(page)).toEqual([]);
  });

  test('a hidden fixture is listed by its rule and never shown; a hard case refused cleanly earns part of its point', async ({ page }) => {
    await openAppAt(page, '/?exercise=poke-face');
    await expect(page.locator('.practice-task h3')).toHaveText('Inset a vertex (poke a face)');
    await page.evaluate(() => window.halfedgeLab.practice.load('bevel-vertex'));
    await expect(page.locator('#status')).toHaveText('Practice: Bevel a vertex, a corner of a cube, amount 0.25, input { vertex: 0, amount: 0.25 }.');
    await typeAndRun(page, solution('wrong/bevel-refuses-boundary'));
    await expect(page.locator('.practice-summary')).toHaveText('10 of 14 checks pass (13.2 of 14 points: a hard case refused earns 80 % of its points).', { timeout: 15_000 });
    const partial = page.locator('.practice-checks li.partial');
    await expect(partial).toHaveCount(4);
    await expect(partial.first()).toContainText('(hidden: its mesh is not shown)');
    await expect(partial.first()).toContainText('A hidden case: A vertex on the boundary is bevelled too');
    // the writes of the fixtures shown only; the view shows a fixture that is not hidden
    const picked = await page.locator('.practice-writes select option').allTextContents();
    expect(picked).toHaveLength(3);
    expect(picked.some((name) => name.startsWith('hidden'))).toBe(false);
    const result = await page.evaluate(() => window.halfedgeLab.practice.run());
    expect(result).toMatchObject({ score: 13.2, maxScore: 14 });
    expect(result.fixtures.filter((f) => f.hidden).every((f) => f.writes.length === 0 && f.firstBroken === null)).toBe(true);
    expect(appErrors(page)).toEqual([]);
  });

  test('the automation object runs a solution and reports the checks, the writes and the first broken write', async ({ page }) => {
    await openAppAt(page, '/');
    expect(await page.evaluate(() => window.halfedgeLab.practice.list())).toContain('loop-subdivision');
    await page.evaluate(() => window.halfedgeLab.practice.load('split-edge'));
    await page.evaluate((code) => window.halfedgeLab.practice.setCode(code), solution('wrong/split-forgets-face'));
    const result = await page.evaluate(() => window.halfedgeLab.practice.run());
    expect(result.passed).toBe(false);
    expect(result.firstBroken).toMatchObject({ line: 30 });
    expect(result.writes[result.firstBroken!.write]).toMatchObject({ field: 'newFace', line: 30 });
    expect(result.checks.find((c) => !c.passed)!.message).toMatch(/halfedge h-1 is not a live halfedge/);
    // the code is kept per exercise, across a reload
    await page.reload();
    await page.waitForFunction(() => window.halfedgeLab !== undefined);
    await page.evaluate(() => window.halfedgeLab.practice.load('split-edge'));
    expect(await page.evaluate(async () => (await window.halfedgeLab.practice.state()).code)).toContain('never gives them a halfedge');
  });

  test("Use my code: Operate's flip runs the student's flip on the mesh in the view; a broken result is not kept and names its line", async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openApp(page, 'sphere.ply');
    await page.evaluate(() => window.halfedgeLab.practice.load('flip-edge'));
    // the exercise shows its first fixture; the student goes back to the model they were looking at
    expect(await page.evaluate(() => window.halfedgeLab.openSample('sphere.ply'))).toBe(true);
    const opened = await page.evaluate(() => window.halfedgeLab.state());

    // a flip that forgets a vertex halfedge: the view keeps its mesh, the panel says where it broke
    await page.evaluate((code) => window.halfedgeLab.practice.setCode(code), solution('wrong/flip-forgets-vertex'));
    await page.getByRole('button', { name: 'Use my code' }).click();
    await expect(page.getByRole('button', { name: 'Use my code' })).toHaveAttribute('aria-pressed', 'true');
    expect(await page.evaluate(() => window.halfedgeLab.edit({ kind: 'flip-edge', edge: 10 }))).toBeNull();
    await expect(page.locator('#status')).toHaveText(/^Your code broke the mesh, so it stays as it was: v\d+'s halfedge h\d+ does not start at v\d+, since write \d+, origin\(h\d+\) = v\d+ at line 2[34]\. To fix: the reference sets v\d+'s halfedge to h\d+ .*\.$/);
    await expect(page.locator('.practice-broken')).toContainText(/First broken: v\d+'s halfedge/);
    let state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.lastEdit).toMatchObject({ kind: 'flip-edge', by: 'solution' });
    expect(state.lastEdit!.writes).toBeGreaterThan(10);
    expect(state.version).toBe(opened.version);
    expect(state.history!.items.length).toBe(opened.history!.items.length);

    // the right flip, from Operate's own button on the selected edge: kept, as an entry undo takes back
    await page.evaluate((code) => window.halfedgeLab.practice.setCode(code), solution('flip-edge'));
    await page.evaluate(() => window.halfedgeLab.select('e10'));
    await page.getByRole('tab', { name: 'Operate' }).click();
    await page.getByRole('button', { name: 'Flip edge' }).click();
    await expect(page.locator('#status')).toHaveText(/^Flip e10 \(your code\): \d+ writes\. Ctrl\+Z undoes it\.$/);
    state = await page.evaluate(() => window.halfedgeLab.state());
    expect(state.lastEdit).toMatchObject({ kind: 'flip-edge', by: 'solution' });
    expect(state.history!.items[state.history!.index]!.label).toBe('flip e10 (your code)');
    expect(state.problems).toEqual([]);
    expect(state.stats).toMatchObject({ vertices: opened.stats!.vertices, edges: opened.stats!.edges, faces: opened.stats!.faces });
    expect(state.phase!.diff!.total).toBeGreaterThan(5);
    await page.screenshot({ path: testInfo.outputPath('use-my-code-1280.png') });
    await page.keyboard.press('Control+z');
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().history!.index)).toBe(opened.history!.index);

    // switched off, the same button is the library's again
    await page.evaluate(() => window.halfedgeLab.practice.setUseMine(false));
    await page.getByRole('button', { name: 'Flip edge' }).click();
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().lastEdit?.by)).toBe('library');
    expect(appErrors(page)).toEqual([]);
  });
});
