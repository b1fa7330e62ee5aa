/**
 * `npm run bench:browser [-- --json]`: the app in headless Chromium, on the production build.
 *
 *   - first load: from navigation to the sample mesh drawn;
 *   - open a 1M-triangle binary PLY: from choosing the file to the first frame that shows it;
 *   - one Loop step on 250k triangles: from the click to the first frame that shows the result;
 *   - for both, the longest main-thread task while the worker works, and overall;
 *   - the size of the app's JavaScript, gzipped: what the first load needs, and the Practice tab's, loaded when it opens;
 *   - the same for a page with one <halfedge-view> element (its own bundle, dist/element);
 *   - the longest gap between animation frames while a 121k-triangle file opens (from choosing it
 *     until a second after it is drawn), beside the median frame while the view turns around it;
 *   - on the 1.31M-triangle icosphere: opening it, then flip, split, collapse, undo, redo and one
 *     smoothing step, each from the call to the drawn result and as a share of the open; then one
 *     Loop and one Catmull-Clark level stepped phase by phase (each phase with its pointer diff)
 *     beside the same level run in one go, in the same run: the stepped level and each phase as a
 *     ratio of the one-run level, and the longest main-thread task of each.
 *
 * Prints one JSON object per line with --json (`case`, `size`, `ms`, plus the case's own fields).
 * `--only levels` opens the icosphere and measures the levels alone.
 */
import { execFileSync, spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { chromium } from '@playwright/test';
import { writeSoup } from '../src/index.js';
import { sphereWithFaces } from './cases/sphere.js';
import { icosphere } from './cases/icosphere.js';

const json = process.argv.includes('--json');
const onlyLevels = process.argv.includes('levels') && process.argv.includes('--only');
const root = join(import.meta.dirname, '..');
const port = 5199;
const results: Array<Record<string, unknown>> = [];
const report = (result: Record<string, unknown>) => {
  results.push(result);
  console.log(json ? JSON.stringify(result) : `${String(result.case).padEnd(28)} ${JSON.stringify(result)}`);
};

execFileSync(join(root, 'node_modules/.bin/vite'), ['build', '--logLevel', 'error'], { cwd: root, stdio: 'inherit' });
execFileSync(join(root, 'node_modules/.bin/vite'), ['build', '-c', 'vite.element.config.ts', '--logLevel', 'error'], { cwd: root, stdio: 'inherit' });
const server = spawn(join(root, 'node_modules/.bin/vite'), ['preview', '--port', String(port), '--strictPort'], { cwd: root, stdio: 'ignore' });
const folder = mkdtempSync(join(tmpdir(), 'halfedge-bench-'));
const executablePath = ['/usr/bin/chromium', '/usr/bin/chromium-browser'].find((p) => existsSync(p));
const browser = await chromium.launch({
  executablePath,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking'],
});

try {
  await waitForServer(`http://localhost:${port}/`);

  // first load, and the scripts it fetched (the page's and its workers'; code loaded on demand —
  // the Practice tab, glTF and its decoders — is not among them)
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const fetched = new Set<string>();
  page.context().on('response', (response) => {
    // the offline service worker fetches every script to keep: those are not the first load's
    if (response.request().serviceWorker()) return;
    const name = new URL(response.url()).pathname.split('/').pop()!;
    if (name.endsWith('.js')) fetched.add(name);
  });
  await page.goto(`http://localhost:${port}/`);
  await page.waitForFunction(() => window.halfedgeLab !== undefined);
  await page.evaluate(() => window.halfedgeLab.ready);
  const firstLoad = await page.evaluate(() => window.halfedgeLab.state().drawnAt);

  const assets = join(root, 'site/assets');
  const scripts = readdirSync(assets).filter((name) => name.endsWith('.js'));
  const gzipped = (names: string[]) => gzippedKB(assets, names);
  const loadedFirst = scripts.filter((name) => fetched.has(name));
  const practice = scripts.filter((name) => name.startsWith('practice'));
  const gltf = scripts.filter((name) => /^(gltf|decoder|meshopt|draco)/.test(name));
  report({ case: 'bundle-js-gzip', size: loadedFirst.length, ms: null, kB: gzipped(loadedFirst), limitKB: 300 });
  report({ case: 'practice-js-gzip', size: practice.length, ms: null, kB: gzipped(practice) });
  report({ case: 'gltf-js-gzip', size: gltf.length, ms: null, kB: gzipped(gltf) });
  if (!onlyLevels) {
    report({ case: 'first-load-to-sample-drawn', size: 0, ms: Math.round(firstLoad), limitMs: 1500 });
    await measureElement();
    await measureFrameGaps(page, 121_000);
  }

  await page.evaluate(() => {
    const w = window as unknown as { longTasks: Array<{ start: number; duration: number }> };
    w.longTasks = [];
    new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) w.longTasks.push({ start: entry.startTime, duration: entry.duration });
    }).observe({ type: 'longtask', buffered: false });
  });

  if (!onlyLevels) await measureOpenAndLoop(page);
  await measureIcosphere(page);
} finally {
  await browser.close();
  server.kill();
  rmSync(folder, { recursive: true, force: true });
}

/** Opening a 1M-triangle file, and one Loop step on 250k triangles. */
async function measureOpenAndLoop(page: import('@playwright/test').Page): Promise<void> {
  // opening a 1M-triangle binary PLY
  const big = join(folder, 'sphere-1m.ply');
  writeFileSync(big, writeSoup(sphereWithFaces(1_000_000), 'ply-binary'));
  await measure(page, 'open-1m-binary-ply', 1_000_000, async () => {
    await page.locator('#file-input').setInputFiles(big);
  });

  // one Loop step on 250k triangles
  const medium = join(folder, 'sphere-250k.ply');
  writeFileSync(medium, writeSoup(sphereWithFaces(250_000), 'ply-binary'));
  await page.locator('#file-input').setInputFiles(medium);
  await page.waitForFunction(() => window.halfedgeLab.state().file?.name === 'sphere-250k.ply' && window.halfedgeLab.state().drawnAt > window.halfedgeLab.state().shownAt);
  // let the load's follow-up work (arrows, the picking worker's copy) finish: it is not the step's
  await page.waitForTimeout(1500);
  await page.evaluate(() => window.halfedgeLab.start({ kind: 'subdivide', scheme: 'loop' }));
  await measure(page, 'loop-step-250k-to-drawn', 250_000, async () => {
    await page.evaluate(() => void window.halfedgeLab.runToEnd());
  });
}

/** On the 1.31M-triangle icosphere: opening it, the local edits (unless only the levels are asked for), the levels. */
async function measureIcosphere(page: import('@playwright/test').Page): Promise<void> {
  // local edits on the 1.31M-triangle icosphere, beside the time to open and draw it (the
  // machine's speed drifts: the ratios are the figures to read)
  const ico = join(folder, 'icosphere-1310k.ply');
  writeFileSync(ico, writeSoup(icosphere(8), 'ply-binary'));
  const open = await measure(page, 'open-icosphere-1310k', 1_310_720, async () => {
    await page.locator('#file-input').setInputFiles(ico);
  });
  await page.waitForTimeout(1500);
  const versus = (name: string, ms: number, share: number) =>
    report({ case: `${name}-vs-open`, size: 1_310_720, ms, peer: 'open and draw the same mesh', peerMs: open.ms, ratio: +(ms / open.ms).toFixed(3), limitRatio: share });
  // each edit from a view at rest (the frame of the last change done), then the same kinds back to
  // back, each called as soon as the last is drawn: a software renderer takes most of a second to
  // draw 2.6M triangles, and a change that arrives meanwhile waits for that frame
  const edits = (first: number): Array<[string, () => Promise<unknown>, number]> => [
    ['flip', () => page.evaluate((e) => window.halfedgeLab.edit({ kind: 'flip-edge', edge: e }), 1000 + first), 0.05],
    ['split', () => page.evaluate((e) => window.halfedgeLab.edit({ kind: 'split-edge', edge: e, triangulate: true }), 2000 + first), 0.05],
    ['collapse', () => page.evaluate((e) => window.halfedgeLab.edit({ kind: 'collapse-edge', edge: e }), 3000 + first), 0.05],
    ['undo', () => page.evaluate(() => window.halfedgeLab.undo()), 0.05],
    ['redo', () => page.evaluate(() => window.halfedgeLab.redo()), 0.05],
  ];
  // an edit the session refuses never draws: say so rather than wait
  const refusedIsAnError = (name: string, act: () => Promise<unknown>) => async () => {
    if ((await act()) === null) throw new Error(`${name} was refused on the icosphere: ${await page.evaluate(() => window.halfedgeLab.state().message)}`);
  };
  if (!onlyLevels) await measureEdits();
  await measureLevels();

  async function measureEdits(): Promise<void> {
    for (const [name, act, share] of edits(0)) {
      await settle(page);
      const timed = await measure(page, `${name}-icosphere-1310k`, 1_310_720, refusedIsAnError(name, act), 50);
      versus(name, timed.ms, share);
    }
    // far from the first series' edges, which its collapse may have taken
    for (const [name, act] of edits(10_000)) await measure(page, `${name}-icosphere-1310k-back-to-back`, 1_310_720, refusedIsAnError(name, act), 50);
    // the step from a view at rest too: starting shows the phase card, a frame of its own
    await page.evaluate(() => window.halfedgeLab.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 3 } }));
    await settle(page);
    const smoothStep = await measure(page, 'smoothing-step-icosphere-1310k', 1_310_720, async () => void page.evaluate(() => window.halfedgeLab.step()), 50);
    versus('smoothing-step', smoothStep.ms, 0.15);
    await page.evaluate(() => window.halfedgeLab.cancel());
  }

  /**
   * One level of Loop and of Catmull-Clark, stepped phase by phase and then run in one go from
   * the same mesh, each from a view at rest (the full checks of the phase before done): the stepped level (the sum of its phases, each from
   * the press of Step to its drawing) as a ratio of the one-run level (from Run to end to the
   * drawn result; both started first), and each phase's too; every phase with its pointer diff.
   */
  async function measureLevels(): Promise<void> {
    // at rest: the full counts and checks of the last change done (they follow a phase, in the
    // worker, which a step asked for meanwhile would wait behind), and the frame after them
    const atRest = async () => {
      await page.waitForFunction(() => !window.halfedgeLab.state().pending, null, { timeout: 300_000 });
      await settle(page);
    };
    for (const scheme of ['loop', 'catmull-clark'] as const) {
      const start = () => page.evaluate((scheme) => window.halfedgeLab.start({ kind: 'subdivide', scheme }), scheme);
      await settle(page);
      await start();
      const phases: Array<{ ms: number; longestTaskOverallMs: number }> = [];
      for (let phase = 1; ; phase++) {
        await atRest();
        const timed = await measure(page, `${scheme}-phase-${phase}-icosphere-1310k`, 1_310_720, async () => void page.evaluate(() => window.halfedgeLab.step()));
        phases.push(timed);
        const state = await page.evaluate(() => window.halfedgeLab.state());
        report({ case: `${scheme}-phase-${phase}-diff`, size: 1_310_720, ms: timed.ms, phase: state.phase?.name ?? null, diffShown: state.phase?.diff !== null, diffTotal: state.phase?.diff?.total ?? null, patched: state.patched });
        if (!state.stepping) break;
      }
      await page.evaluate(() => window.halfedgeLab.undo());
      await start();
      await atRest();
      const oneRun = await measure(page, `${scheme}-level-one-run-icosphere-1310k`, 1_310_720, async () => void page.evaluate(() => window.halfedgeLab.runToEnd()));
      await page.evaluate(() => window.halfedgeLab.undo());
      const stepped = phases.reduce((sum, phase) => sum + phase.ms, 0);
      const longest = Math.max(...phases.map((phase) => phase.longestTaskOverallMs));
      report({ case: `${scheme}-level-stepped-vs-one-run`, size: 1_310_720, ms: stepped, peer: 'the same level in one run', peerMs: oneRun.ms, ratio: +(stepped / oneRun.ms).toFixed(3), limitRatio: 1.5, longestTaskMs: longest, limitLongestTaskMs: 100 });
      phases.forEach((phase, i) =>
        report({ case: `${scheme}-phase-${i + 1}-vs-one-run`, size: 1_310_720, ms: phase.ms, peer: 'the same level in one run', peerMs: oneRun.ms, ratio: +(phase.ms / oneRun.ms).toFixed(3), limitRatio: 1 }),
      );
    }
  }
}

/**
 * Waits until the view is at rest: three seconds, several times what the software renderer takes
 * over a frame of 2.6M triangles. (Neither animation frames nor reading a pixel back proved a
 * reliable sign that the last frame was done: the changes measured after them still waited.)
 */
async function settle(page: import('@playwright/test').Page): Promise<void> {
  await page.waitForTimeout(3000);
}

/**
 * Times `act` from its start to the first frame drawn after the next snapshot arrives, and the
 * longest main-thread tasks before that snapshot arrived (the worker working) and after.
 */
async function measure(page: import('@playwright/test').Page, name: string, size: number, act: () => Promise<void>, limitLongestTaskMs = 100) {
  const before = await page.evaluate(() => {
    (window as unknown as { longTasks: unknown[] }).longTasks = [];
    return { version: window.halfedgeLab.state().version, t: performance.now() };
  });
  await act();
  await page.waitForFunction(
    (version) => {
      const s = window.halfedgeLab.state();
      return s.version > version && s.drawnAt > s.shownAt;
    },
    before.version,
    { timeout: 300_000 },
  );
  const after = await page.evaluate(() => {
    const s = window.halfedgeLab.state();
    return { shownAt: s.shownAt, drawnAt: s.drawnAt, tasks: (window as unknown as { longTasks: Array<{ start: number; duration: number }> }).longTasks };
  });
  // a task that began before the action is an earlier one's (its entry can arrive late); the task
  // that handles the arriving snapshot ends after it is shown: it is the drawing's, not the wait's
  const tasks = after.tasks.filter((t) => t.start >= before.t);
  const during = tasks.filter((t) => t.start + t.duration < after.shownAt);
  const longest = (tasks: Array<{ duration: number }>) => Math.round(Math.max(0, ...tasks.map((t) => t.duration)));
  const result = {
    case: name,
    size,
    ms: Math.round(after.drawnAt - before.t),
    longestTaskWhileWorkerWorksMs: longest(during),
    longestTaskOverallMs: longest(tasks),
    limitLongestTaskMs,
  };
  report(result);
  return result;
}

/**
 * Whether the page keeps drawing frames while a file of `faces` triangles opens: the longest gap
 * between animation frames from choosing the file until a second after it is drawn (the arrows,
 * tables and counts that follow the first frame included). Beside it, the median frame while the
 * view turns around the mesh, which is what drawing it once costs the renderer: the open cannot
 * hold the page for less than one of those.
 */
async function measureFrameGaps(page: import('@playwright/test').Page, faces: number): Promise<void> {
  const file = join(folder, `sphere-${Math.round(faces / 1000)}k.ply`);
  writeFileSync(file, writeSoup(sphereWithFaces(faces), 'ply-binary'));
  // the frame loop is passed as text: the page must not see the names the TypeScript loader adds
  const startGaps = () => page.evaluate(`(() => {
    const w = window;
    w.frameGaps = { gaps: [], starts: [], stop: false };
    let last = performance.now();
    const tick = (t) => {
      w.frameGaps.gaps.push(t - last);
      w.frameGaps.starts.push(last);
      last = t;
      if (!w.frameGaps.stop) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  })()`);
  const stopGaps = async () => {
    const { gaps, starts } = (await page.evaluate(`(() => { window.frameGaps.stop = true; return window.frameGaps; })()`)) as { gaps: number[]; starts: number[] };
    const longest = gaps.indexOf(Math.max(...gaps));
    // frames that drew something: an idle page's frames come every 17 ms
    const drawn = gaps.filter((gap) => gap > 20).sort((a, b) => a - b);
    return { longest: gaps[longest]!, at: starts[longest]!, median: drawn[drawn.length >> 1] ?? 0 };
  };
  const version = await page.evaluate(() => window.halfedgeLab.state().version);
  await startGaps();
  const chosen = await page.evaluate(() => performance.now());
  await page.locator('#file-input').setInputFiles(file);
  await page.waitForFunction((version) => {
    const s = window.halfedgeLab.state();
    return s.version > version && s.drawnAt > s.shownAt;
  }, version, { timeout: 60_000 });
  const { shownAt, drawnAt } = await page.evaluate(() => window.halfedgeLab.state());
  await page.waitForTimeout(1000);
  const open = await stopGaps();
  // turning the view: a drag across the canvas, a frame drawn at each step
  await page.waitForTimeout(500);
  await startGaps();
  const box = (await page.locator('canvas').first().boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  for (let i = 1; i <= 20; i++) await page.mouse.move(box.x + box.width / 2 + 8 * i, box.y + box.height / 2);
  await page.mouse.up();
  await page.waitForTimeout(300);
  const turning = await stopGaps();
  report({
    case: `open-${Math.round(faces / 1000)}k-longest-frame-gap`,
    size: faces,
    ms: Math.round(open.longest),
    // where the gap began, from choosing the file; and when the mesh arrived and was first drawn
    gapBeganMs: Math.round(open.at - chosen),
    shownMs: Math.round(shownAt - chosen),
    drawnMs: Math.round(drawnAt - chosen),
    peer: 'the median frame while the view turns',
    peerMs: Math.round(turning.median),
    ratio: +(open.longest / turning.median).toFixed(2),
    longestWhileTurningMs: Math.round(turning.longest),
    limitMs: 200,
  });
}

/** A page of its own with one <halfedge-view>: the scripts it fetches until its mesh is drawn, gzipped, and the time. */
async function measureElement(): Promise<void> {
  const elementDir = join(root, 'dist/element');
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const fetched: string[] = [];
  await page.route('**/course/**', (route) => {
    const path = new URL(route.request().url()).pathname.replace(/^\/course\//, '');
    if (path === 'index.html') {
      const body = '<!doctype html><script type="module" src="/course/element.js"></script><halfedge-view src="/models/torus.off"></halfedge-view>';
      return route.fulfill({ body, contentType: 'text/html' });
    }
    fetched.push(path);
    return route.fulfill({ body: readFileSync(join(elementDir, path)), contentType: 'text/javascript' });
  });
  await page.goto(`http://localhost:${port}/course/index.html`);
  await page.waitForFunction(() => customElements.get('halfedge-view') !== undefined);
  const drawnAt = await page.evaluate(async () => {
    const lab = document.querySelector('halfedge-view')!.lab;
    await lab.ready;
    return lab.state().drawnAt;
  });
  const kB = gzippedKB(elementDir, fetched);
  report({ case: 'element-js-gzip', size: fetched.length, ms: null, kB });
  report({ case: 'element-first-load-to-drawn', size: 0, ms: Math.round(drawnAt) });
  await page.close();
}

/** The files' size together, gzipped as a server would (level 9), in kB. */
function gzippedKB(folder: string, names: string[]): number {
  return Math.round(names.reduce((sum, name) => sum + gzipSync(readFileSync(join(folder, name)), { level: 9 }).length, 0) / 1024);
}

async function waitForServer(url: string): Promise<void> {
  for (let i = 0; i < 100; i++) {
    try {
      if ((await fetch(url)).ok) return;
    } catch {
      // not up yet
    }
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
  throw new Error(`the preview server did not start at ${url}`);
}
