import { expect, type Page, test } from '@playwright/test';
import { preview } from 'vite';
import { cube, writeSoup } from '../src/index.js';
import { colors } from '../src/ui/colors.js';
import { askClickable, canvasPixel, clickCanvas, colourDistance, hexToRgb, onCanvas, openApp, verticesUnderOverlays } from './helpers.js';

/** Starts a stepped Loop subdivision and shows its first phase. */
async function firstLoopPhase(page: Page): Promise<void> {
  await page.evaluate(async () => {
    await window.halfedgeLab.start({ kind: 'subdivide', scheme: 'loop' });
    await window.halfedgeLab.step();
  });
}

/** Whether halfedge `name` is drawn in the selection colour where it lies on screen. */
async function drawnSelected(page: Page, name: string): Promise<boolean> {
  await page.evaluate(() => new Promise(requestAnimationFrame));
  const at = await page.evaluate((h) => window.halfedgeLab.screenPosition(h), name);
  return colourDistance(await canvasPixel(page, at.x, at.y), hexToRgb(colors.selected)) < 70;
}

/** Finds an element of the given kind whose spot on screen picks it, to click it like a student. */
async function clickable(page: Page, kind: 'halfedge' | 'vertex' | 'face', avoid: string | null): Promise<{ name: string; x: number; y: number }> {
  const found = await page.evaluate(
    async ({ kind, avoid }) => {
      const prefix = { halfedge: 'h', vertex: 'v', face: 'f' }[kind];
      for (let id = 0; id < 400; id++) {
        const name = `${prefix}${id}`;
        if (name === avoid) continue;
        try {
          const at = window.halfedgeLab.screenPosition(name);
          const canvas = document.querySelector('#viewport canvas')!.getBoundingClientRect();
          const uncovered = document.elementFromPoint(canvas.left + at.x, canvas.top + at.y)?.tagName === 'CANVAS';
          if (at.visible && uncovered && (await window.halfedgeLab.pickAt(at.x, at.y, kind)) === name) return { name, ...at };
        } catch {
          return null;
        }
      }
      return null;
    },
    { kind, avoid },
  );
  if (!found) throw new Error(`no ${kind} can be clicked`);
  return found;
}

test.describe('the classroom', () => {
  test('a quiz round answered right, then one answered wrong', async ({ page }, testInfo) => {
    await openApp(page, 'disk.off');
    await page.keyboard.press('q');
    await expect(page.locator('.quiz-question')).toContainText('Which');
    const first = await askClickable(page);
    await clickCanvas(page, first.x, first.y);
    await expect(page.locator('.quiz-verdict')).toHaveText(`Right: ${first.path[0]} → ${first.text.split(' is ')[1]!.split('.').slice(1).join('.').replace('?', '').split('.').map((move, i) => `${move} → ${first.path[i + 1]}`).join(' → ')}.`);
    await page.screenshot({ path: testInfo.outputPath('quiz-right.png') });

    await page.getByRole('button', { name: 'New question' }).click();
    const second = (await page.evaluate(() => window.halfedgeLab.quiz.question()))!;
    const secondKind = second.answer[0] === 'h' ? 'halfedge' : second.answer[0] === 'v' ? 'vertex' : 'face';
    const wrong = await clickable(page, secondKind, second.answer);
    await clickCanvas(page, wrong.x, wrong.y);
    await expect(page.locator('.quiz-verdict')).toContainText(`Not quite: you picked ${wrong.name}`);
    await expect(page.locator('.quiz-verdict')).toContainText(`→ ${second.answer}.`);
    expect(await page.evaluate(() => window.halfedgeLab.quiz.score())).toEqual({ right: 1, asked: 2 });
    await page.screenshot({ path: testInfo.outputPath('quiz-wrong.png') });
  });

  // the quiz's path used to stay drawn over everything: a new selection changed the inspector but
  // not the view, until the page was reloaded
  test('after an answer, a selection, a walk, Esc and another tab each take the view back', async ({ page }, testInfo) => {
    await openApp(page, 'disk.off');
    const answer = async () => {
      await page.keyboard.press('q');
      const question = await askClickable(page);
      await clickCanvas(page, question.x, question.y);
      await expect(page.locator('.quiz-verdict')).toContainText('Right');
    };
    await answer();
    await page.evaluate(() => window.halfedgeLab.select('h0'));
    await page.locator('#frame-selection').click();
    await page.waitForTimeout(300);
    expect(await drawnSelected(page, 'h0')).toBe(true);
    await page.keyboard.press('n');
    const next = (await page.evaluate(() => window.halfedgeLab.state().selection))!;
    expect(next).not.toBe('h0');
    expect(await drawnSelected(page, next)).toBe(true);
    await page.screenshot({ path: testInfo.outputPath('quiz-then-walk.png') });

    // Esc during a question stops it: the next click selects instead of answering
    await answer();
    await page.keyboard.press('q');
    await page.keyboard.press('Escape');
    expect(await page.evaluate(() => window.halfedgeLab.quiz.question()?.waiting)).toBe(false);
    await page.evaluate(() => window.halfedgeLab.select('h0'));
    expect(await drawnSelected(page, 'h0')).toBe(true);

    // leaving the Quiz tab, and opening another model, take its drawing (and labels) off the view
    const startLabels = page.locator('#viewport .label', { hasText: /^start / });
    await answer();
    await expect(startLabels).toHaveCount(1);
    await page.getByRole('tab', { name: 'Inspect' }).click();
    await expect(startLabels).toHaveCount(0);
    await answer();
    await expect(startLabels).toHaveCount(1);
    expect(await page.evaluate(() => window.halfedgeLab.openSample('torus.off'))).toBe(true);
    await expect(startLabels).toHaveCount(0);
  });

  test('presentation mode enlarges everything, and ? lists the keys', async ({ page }, testInfo) => {
    await openApp(page, 'disk.off');
    await page.evaluate(() => window.halfedgeLab.select('h7'));
    const before = await page.locator('.record').evaluate((node) => parseFloat(getComputedStyle(node).fontSize));
    await page.keyboard.press('m');
    await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
    const after = await page.locator('.record').evaluate((node) => parseFloat(getComputedStyle(node).fontSize));
    expect(after).toBeGreaterThan(1.3 * before);
    await page.screenshot({ path: testInfo.outputPath('presentation.png') });
    await page.keyboard.press('?');
    await expect(page.getByRole('dialog', { name: 'Keys' })).toBeVisible();
    await expect(page.getByRole('dialog', { name: 'Keys' })).toContainText('next: the following halfedge around the same face');
    await page.screenshot({ path: testInfo.outputPath('help.png') });
    await page.keyboard.press('Escape');
    await expect(page.getByRole('dialog', { name: 'Keys' })).toBeHidden();
  });

  test('on a 1024 × 768 projector, presentation mode fits the screen and leaves most of it to the mesh', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1024, height: 768 });
    await openApp(page, 'disk.off');
    await page.evaluate(() => window.halfedgeLab.select('h7'));
    await page.keyboard.press('m');
    await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
    const layout = await page.evaluate(() => {
      const box = (selector: string) => document.querySelector(selector)!.getBoundingClientRect();
      const side = box('.side');
      // what sticks out of its panel, sideways: walk buttons, tabs, table cells
      const outside = [...document.querySelectorAll('.side button, .side [role="tab"]')]
        .map((node) => [node.textContent, node.getBoundingClientRect()] as const)
        .filter(([, r]) => r.width > 0 && (r.left < side.left - 1 || r.right > side.right + 1))
        .map(([text]) => text);
      const tables = box('.tables');
      const wideCells = [...document.querySelectorAll('.tables .table-row > *')].filter((node) => node.getBoundingClientRect().right > tables.right + 1).length;
      return { page: document.documentElement.scrollHeight, stage: box('.stage'), outside, wideCells };
    });
    await page.screenshot({ path: testInfo.outputPath('projector.png') });
    expect(layout.page).toBeLessThanOrEqual(768); // no page scrolling: the panels scroll inside
    expect(layout.outside).toEqual([]);
    expect(layout.wideCells).toBe(0);
    expect(layout.stage.width).toBeGreaterThan(0.6 * 1024);
    expect(layout.stage.height).toBeGreaterThan(0.5 * 768);
    // the key help fits: its Close button used to sit below the bottom of the screen
    await page.keyboard.press('?');
    await expect(page.getByRole('button', { name: 'Close the key help' })).toBeInViewport({ ratio: 1 });
    await page.keyboard.press('Escape');
    await expect(page.locator('#help-overlay')).toBeHidden();
  });

  for (const [width, height] of [
    [1280, 720],
    [1024, 768],
  ] as const) {
    test(`at ${width} × ${height}, presentation mode has 20 px text, the demo's controls without scrolling, and overlays apart`, async ({ page }, testInfo) => {
      await page.setViewportSize({ width, height });
      await openApp(page, 'sphere.ply');
      await page.evaluate(() => window.halfedgeLab.select('h1'));
      await page.keyboard.press('m');
      await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');

      // every text on screen is at least 20 px (the 3D labels are larger still)
      const smallTexts = () =>
        page.evaluate(() =>
          [...document.querySelectorAll('body *')]
            .filter((node) => [...node.childNodes].some((child) => child.nodeType === Node.TEXT_NODE && child.textContent!.trim() !== ''))
            .filter((node) => node.tagName !== 'OPTION' && node.checkVisibility())
            .filter((node) => {
              const box = node.getBoundingClientRect();
              return box.width > 0 && box.bottom > 0 && box.top < innerHeight && box.right > 0 && box.left < innerWidth;
            })
            .filter((node) => parseFloat(getComputedStyle(node).fontSize) < 19.5)
            .map((node) => `${node.tagName.toLowerCase()}.${node.className} "${node.textContent!.trim().slice(0, 30)}" ${getComputedStyle(node).fontSize}`),
        );
      expect(await smallTexts()).toEqual([]);

      // the walk needs no scrolling: every walk button and Back are on screen
      for (const button of await page.locator('#walk-buttons button').all()) await expect(button).toBeInViewport({ ratio: 1 });
      await expect(page.getByRole('button', { name: 'Back one step' })).toBeInViewport({ ratio: 1 });
      // the naming menu shows its whole text
      const naming = await page.locator('#convention').evaluate((select: HTMLSelectElement) => {
        const style = getComputedStyle(select);
        const context = document.createElement('canvas').getContext('2d')!;
        context.font = `${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
        return { text: context.measureText(select.selectedOptions[0]!.text).width, room: select.clientWidth - parseFloat(style.paddingLeft) - 16 };
      });
      expect(naming.text).toBeLessThanOrEqual(naming.room);
      await page.screenshot({ path: testInfo.outputPath('presentation-walk.png') });

      // the record tables fold to their title, giving the view their height; D opens them
      const stageHeight = () => page.locator('.stage').evaluate((node) => node.getBoundingClientRect().height);
      const folded = await stageHeight();
      expect(folded).toBeGreaterThan(0.7 * height);
      await expect(page.locator('#tables-fold')).toHaveAttribute('aria-expanded', 'false');
      await page.keyboard.press('d');
      await expect(page.locator('#tables-fold')).toHaveAttribute('aria-expanded', 'true');
      await expect(page.locator('.tables .table-row').first()).toBeVisible();
      expect(await stageHeight()).toBeLessThan(folded - 100);
      await page.keyboard.press('d');
      await expect(page.locator('#tables-fold')).toHaveAttribute('aria-expanded', 'false');

      // stepping a smoothing: Step, Run and Cancel come first; the colour scale, the legend and
      // the status line stand apart
      await page.getByRole('tab', { name: 'Operate' }).click();
      await page.evaluate(async () => {
        await window.halfedgeLab.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 3 } });
        await window.halfedgeLab.step();
      });
      await expect(page.locator('#values-legend')).toBeVisible();
      for (const name of ['Step one phase (S)', 'Run to end (G)', 'Cancel the operation (X)']) {
        await expect(page.getByRole('button', { name })).toBeInViewport({ ratio: 1 });
      }
      const boxes = await page.evaluate(() => ['legend', 'values-legend', 'status', 'hud'].map((id) => document.getElementById(id)!.getBoundingClientRect().toJSON() as DOMRect));
      const overlap = (a: DOMRect, b: DOMRect) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
      for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) expect(overlap(boxes[i]!, boxes[j]!), `overlays ${i} and ${j} overlap`).toBe(false);
      expect(await smallTexts()).toEqual([]);
      // framed again, the mesh goes where the overlays leave room: none of its vertices is under one
      await page.keyboard.press('Home');
      expect(await verticesUnderOverlays(page, ['legend', 'values-legend', 'status', 'hud'])).toEqual([]);
      await page.screenshot({ path: testInfo.outputPath('presentation-smoothing.png') });
      await page.keyboard.press('x');
      await expect(page.locator('#values-legend')).toBeHidden();
      await expect(page.locator('#status')).toContainText('cancelled; the mesh is as it was');

      // the other tabs and the key help: large type too, and the help fits
      for (const tab of ['Quiz', 'File']) {
        await page.getByRole('tab', { name: tab }).click();
        expect(await smallTexts(), tab).toEqual([]);
      }
      await page.keyboard.press('?');
      await expect(page.getByRole('button', { name: 'Close the key help' })).toBeInViewport({ ratio: 1 });
      expect(await smallTexts()).toEqual([]);
      await page.keyboard.press('Escape');
    });
  }

  test('a phase card that comes over the mesh moves it aside, unless the lecturer has placed the view', async ({ page }, testInfo) => {
    await page.setViewportSize({ width: 1280, height: 720 });
    await openApp(page, 'bunny.ply');
    await page.keyboard.press('m');
    await expect(page.locator('#presentation')).toHaveAttribute('aria-pressed', 'true');
    await page.getByRole('tab', { name: 'Operate' }).click();
    // a click that picks is not a move of the view
    await clickCanvas(page, 400, 380);
    const overlays = ['legend', 'values-legend', 'status', 'hud', 'arrow-note'];
    await firstLoopPhase(page);
    await expect(page.locator('#legend')).toContainText('phase 1 of 4');
    expect(await verticesUnderOverlays(page, overlays)).toEqual([]);
    await page.screenshot({ path: testInfo.outputPath('phase-card-clear.png') });

    // turned by hand, the view stays where the lecturer put it, card or not
    await page.keyboard.press('x');
    const canvas = (await page.locator('#viewport canvas').boundingBox())!;
    await page.mouse.move(canvas.x + 500, canvas.y + 400);
    await page.mouse.down();
    await page.mouse.move(canvas.x + 560, canvas.y + 380, { steps: 5 });
    await page.mouse.up();
    const camera = async () => new URL(await page.evaluate(() => window.halfedgeLab.shareLink())).searchParams.get('camera');
    const placed = await camera();
    await firstLoopPhase(page);
    await expect(page.locator('#legend')).toContainText('phase 1 of 4');
    expect(await camera()).toBe(placed);
  });

  test('at 1024 × 768 in presentation mode, a refusal that runs over the mesh moves it aside', async ({ page }) => {
    await page.setViewportSize({ width: 1024, height: 768 });
    await openApp(page, 'annulus.off');
    await page.evaluate(() => window.halfedgeLab.setPresentation(true));
    await page.evaluate(() => window.halfedgeLab.select({ kind: 'halfedge', id: 10 }));
    // an inner edge cannot be welded: the sentence why takes three lines of presentation type
    expect(await page.evaluate(() => window.halfedgeLab.edit({ kind: 'weld-edges', edges: [0, 1] }))).toBeNull();
    await expect(page.locator('#status')).toContainText('only boundary edges can be welded');
    await page.evaluate(() => new Promise(requestAnimationFrame));
    const status = (await page.locator('#status').boundingBox())!;
    const canvas = (await page.locator('#viewport canvas').boundingBox())!;
    // no corner and no middle of a face under it
    const covered = await page.evaluate(
      ({ status, canvas }) => {
        const { vertices, faces } = window.halfedgeLab.state().stats!;
        const names = [...Array.from({ length: vertices }, (_, v) => `v${v}`), ...Array.from({ length: faces }, (_, f) => `f${f}`)];
        return names.filter((name) => {
          const at = window.halfedgeLab.screenPosition(name);
          const x = canvas.x + at.x;
          const y = canvas.y + at.y;
          return x >= status.x && x <= status.x + status.width && y >= status.y && y <= status.y + status.height;
        });
      },
      { status, canvas },
    );
    expect(covered).toEqual([]);
  });

  // the note that the arrows are too small comes up once the mesh has moved beside the card, and
  // used to cover its lowest part (the bunny's feet at 1024 × 768)
  for (const [width, height] of [[1280, 720], [1024, 768]] as const) {
    test(`at ${width} × ${height} without presentation mode too, the first phase card and the note about the arrows leave the whole mesh in sight`, async ({ page }) => {
      await page.setViewportSize({ width, height });
      await openApp(page, 'bunny.ply');
      await firstLoopPhase(page);
      await expect(page.locator('#legend')).toContainText('phase 1 of 4');
      await expect(page.locator('#arrow-note')).toBeVisible();
      await page.evaluate(() => new Promise(requestAnimationFrame));
      expect(await verticesUnderOverlays(page, ['legend', 'values-legend', 'status', 'hud', 'arrow-note'])).toEqual([]);
    });
  }

  test('at 1024 × 768 in presentation mode, the status line and the note about the arrows sit side by side', async ({ page }) => {
    await page.setViewportSize({ width: 1024, height: 768 });
    await openApp(page, 'bunny.ply');
    await page.keyboard.press('m');
    await firstLoopPhase(page);
    // four times the faces: at this zoom the edges are too short for arrows, and the note says so
    await expect(page.locator('#arrow-note')).toBeVisible();
    const status = (await page.locator('#status').boundingBox())!;
    const note = (await page.locator('#arrow-note').boundingBox())!;
    expect(status.x + status.width).toBeLessThan(note.x);
    // the colour key is the phase card's on the view (the stepper leaves it out in presentation), all in sight
    await page.getByRole('tab', { name: 'Operate' }).click();
    await expect(page.locator('#legend').getByText('rewired')).toBeInViewport({ ratio: 1 });
    await expect(page.locator('.phase-legend')).toBeHidden();
  });

  test('a shared link restores the model, the selection with its breadcrumb, and the view', async ({ page, context }) => {
    await openApp(page, 'torus.off');
    await page.evaluate(() => window.halfedgeLab.select('h42'));
    await page.keyboard.press('n');
    await page.keyboard.press('t');
    const { selection, breadcrumb } = await page.evaluate(() => window.halfedgeLab.state());
    expect(breadcrumb).toHaveLength(3);
    await page.getByRole('button', { name: 'Copy a link to this view' }).click();
    const link = await page.locator('#status').evaluate((node) => /http\S+/.exec(node.textContent ?? '')![0]);
    expect(link).toContain('model=torus.off');
    // the breadcrumb's start and the pointers walked from it, readable
    expect(link).toContain('select=h42&walk=next,twin&');
    const second = await context.newPage();
    await second.goto(link);
    await second.waitForFunction((selection) => window.halfedgeLab?.state().selection === selection, selection);
    expect(await second.evaluate(() => window.halfedgeLab.state().breadcrumb)).toEqual(breadcrumb);
    await expect(second.locator('#breadcrumb')).toHaveText(await page.locator('#breadcrumb').innerText());
    expect(await second.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('torus.off');
    const here = await page.evaluate(() => window.halfedgeLab.screenPosition('h42'));
    const there = await second.evaluate(() => window.halfedgeLab.screenPosition('h42'));
    expect(Math.abs(here.x - there.x) + Math.abs(here.y - there.y)).toBeLessThan(2);
  });

  // after a cut, the link used to say ?model=torus.off and open the uncut torus without a word
  test('a link reproduces what is on screen: the sample and the steps since; a file of the user\'s it cannot carry', async ({ page, context }) => {
    await openApp(page, 'torus.off');
    await page.evaluate(async () => {
      await window.halfedgeLab.start({ kind: 'cut', plane: [0, 0, 1, 0], keep: 'above' });
      await window.halfedgeLab.runToEnd();
      await window.halfedgeLab.edit({ kind: 'triangulate-mesh' });
    });
    const counts = (p: Page) => p.evaluate(() => window.halfedgeLab.state().stats).then((s) => [s!.vertices, s!.edges, s!.faces]);
    const here = await counts(page);
    const link = await page.evaluate(() => window.halfedgeLab.shareLink());
    expect(link).toContain('model=torus.off');
    // the steps as calls with their settings, nothing percent-encoded
    expect(link).toContain('&ops=cut(plane:0/0/1/0,keep:above);triangulate-mesh&');
    expect(link).not.toContain('%');
    await expect(page.locator('#status')).toContainText('replays 2 steps');
    const second = await context.newPage();
    await second.goto(link);
    await second.waitForFunction(() => window.halfedgeLab?.state().history?.items.length === 3);
    expect(await counts(second)).toEqual(here);

    // a file of the user's: the link cannot carry it, and says so; undoing back past it, the menu,
    // the status line and the link name the sample again
    const mine = writeSoup(cube(), 'off');
    expect(await page.evaluate((bytes) => window.halfedgeLab.open(bytes, 'mine.off'), Array.from(mine))).toBe(true);
    expect(await page.evaluate(() => window.halfedgeLab.shareLink())).not.toContain('model=');
    await expect(page.locator('#status')).toContainText('a file you opened yourself');
    await expect(page.locator('#sample-select')).toHaveValue('');
    await page.evaluate(() => window.halfedgeLab.undo());
    await expect(page.locator('#sample-select')).toHaveValue('torus.off');
    await expect(page.locator('#status')).toContainText('on torus.off');
    expect(await page.evaluate(() => window.halfedgeLab.shareLink())).toContain('model=torus.off');
  });

  test('a link naming a sample or an element that is not here opens what it can and says what is missing', async ({ page }) => {
    await openApp(page, 'no-such-model.ply'); // resolves only once a mesh is drawn
    const { samples, state } = await page.evaluate(async () => ({
      samples: (await (await fetch('models/index.json')).json()) as Array<{ file: string }>,
      state: window.halfedgeLab.state(),
    }));
    expect(state.file?.name).toBe(samples[0].file);
    expect(state.stats?.faces).toBeGreaterThan(0);
    expect(state.message).toContain('no-such-model.ply');
    await expect(page.getByRole('alert').filter({ hasText: 'no-such-model.ply' })).toBeVisible();

    // a selection the model does not have: the model opens, and the page says what is missing
    await page.goto('/?model=tetrahedron.off&select=h999');
    await page.waitForFunction(() => window.halfedgeLab !== undefined);
    await page.evaluate(() => window.halfedgeLab.ready);
    await expect(page.getByRole('alert').filter({ hasText: 'h999' })).toContainText('tetrahedron.off does not have');
    expect(await page.evaluate(() => window.halfedgeLab.state().selection)).toBeNull();
  });

  test('opens a file dropped anywhere on the page', async ({ page }) => {
    await openApp(page, 'tetrahedron.off');
    const text = new TextDecoder().decode(writeSoup(cube(), 'off'));
    await page.evaluate((content) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([content], 'dropped-cube.off', { type: 'text/plain' }));
      document.body.dispatchEvent(new DragEvent('dragover', { dataTransfer: transfer, bubbles: true }));
      document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true }));
    }, text);
    await expect.poll(() => page.evaluate(() => window.halfedgeLab.state().file?.name)).toBe('dropped-cube.off');
    expect(await page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(6);
    // no sample is open now: the menu shows none, and a link cannot name one
    await expect(page.getByLabel('Sample model')).toHaveValue('');
    await page.getByRole('button', { name: 'Copy a link to this view' }).click();
    await expect(page.locator('#status')).toContainText('without the model');
  });

  test('works offline once loaded', async ({ page }) => {
    // a server of its own, to take away: the browser's offline emulation does not reach service workers reliably
    const server = await preview({ logLevel: 'silent', preview: { port: 5191, strictPort: true } });
    try {
      const origin = server.resolvedUrls!.local[0]!.replace(/\/$/, '');
      await openApp(page, 'cube.off', origin);
      // the service worker took over once it had kept the whole site: the page and every sample, opened or not
      await page.waitForFunction(() => navigator.serviceWorker.controller !== null);
      expect(await page.evaluate(async () => (await caches.match('/models/torus.off')) !== undefined)).toBe(true);
      await server.close();
      expect(await page.request.get(`${origin}/`).then(() => 'reached', () => 'gone')).toBe('gone'); // the network is gone
      await page.reload();
      await page.waitForFunction(() => window.halfedgeLab !== undefined);
      await page.evaluate(() => window.halfedgeLab.ready);
      expect(await page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(6);
      expect(await page.evaluate(() => window.halfedgeLab.openSample('torus.off'))).toBe(true);
      expect(await page.evaluate(() => window.halfedgeLab.state().stats?.faces)).toBe(128);
    } finally {
      await server.close();
    }
  });
});

test('K hides the legend and the counts, leaving the view to the mesh, and shows them again', async ({ page }) => {
  await openApp(page, 'torus.off');
  await expect(page.locator('#legend')).toBeVisible();
  await page.keyboard.press('k');
  await expect(page.locator('#legend')).toBeHidden();
  await expect(page.locator('#hud')).toBeHidden();
  await expect(page.locator('#status')).toContainText('press K to show them');
  await page.keyboard.press('k');
  await expect(page.locator('#legend')).toBeVisible();
  await expect(page.locator('#hud')).toBeVisible();
});

test.describe('labels on a projector', () => {
  for (const [width, height, presentation] of [
    [1280, 720, false],
    [1024, 768, true],
  ] as const) {
    // the six labels of a selected halfedge used to stack on the arrows they name
    test(`at ${width} × ${height}${presentation ? ' in presentation mode' : ''}, labels clear their arrows, each other and the overlays`, async ({ page }, testInfo) => {
      await page.setViewportSize({ width, height });
      await openApp(page, 'torus.off');
      await page.evaluate(() => window.halfedgeLab.select('h42'));
      if (presentation) await page.keyboard.press('m');
      await page.waitForTimeout(300);
      await page.keyboard.press('z');
      await page.waitForTimeout(300);
      await page.screenshot({ path: testInfo.outputPath(`labels-${width}x${height}.png`) });
      type Box = { left: number; right: number; top: number; bottom: number };
      const labels = await page.locator('#viewport .label').evaluateAll((tags) => tags.map((t) => t.getBoundingClientRect().toJSON() as Box));
      expect(labels.length).toBeGreaterThanOrEqual(5);
      const overlaps = (a: Box, b: Box) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
      for (let i = 0; i < labels.length; i++) for (let j = i + 1; j < labels.length; j++) expect(overlaps(labels[i]!, labels[j]!), `labels ${i} and ${j}`).toBe(false);
      for (const id of ['hud', 'legend', 'status']) {
        const overlay = (await page.locator(`#${id}`).boundingBox())!;
        const box = { left: overlay.x, right: overlay.x + overlay.width, top: overlay.y, bottom: overlay.y + overlay.height };
        for (const label of labels) expect(overlaps(label, box), `a label on #${id}`).toBe(false);
      }
      // in presentation mode the overlays are compact, in type the back row reads
      if (presentation) {
        for (const id of ['legend', 'hud']) {
          expect(await page.locator(`#${id}`).evaluate((node) => parseFloat(getComputedStyle(node).fontSize))).toBeGreaterThanOrEqual(20);
        }
        await expect(page.locator('#hud')).toContainText('✓ valid');
      }
      // no label sits on the arrows it names (a point on each arrow, as screenPosition gives it)
      const record = await page.evaluate(() => window.halfedgeLab.record('h42'));
      const canvas = (await page.locator('#viewport canvas').boundingBox())!;
      for (const arrow of ['h42', record.next!, record.prev!, record.twin!]) {
        const at = await page.evaluate((h) => window.halfedgeLab.screenPosition(h), arrow);
        const [x, y] = [canvas.x + at.x, canvas.y + at.y];
        for (const label of labels) expect(x > label.left && x < label.right && y > label.top && y < label.bottom, `a label on ${arrow}`).toBe(false);
      }
    });
  }
});
