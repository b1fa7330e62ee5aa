import { readFileSync } from 'node:fs';
import type { Page } from '@playwright/test';

/**
 * The counts of the mesh on show, once they are complete: after a change that reached the page as
 * a patch, the full pass (components, genus, closed) arrives a moment after the change is drawn.
 */
export async function stats(page: Page) {
  await page.waitForFunction(() => !window.halfedgeLab.state().pending);
  return page.evaluate(() => window.halfedgeLab.state().stats!);
}

/** Opens the app (optionally on a sample model, optionally from another server) and waits for the first mesh. */
export async function openApp(page: Page, model?: string, origin = ''): Promise<void> {
  await openAppAt(page, `${origin}/${model ? `?model=${encodeURIComponent(model)}` : ''}`);
}

/** Opens the app at a path and query of its own (`/?exercise=flip-edge`) and waits for the first mesh. */
export async function openAppAt(page: Page, url: string): Promise<void> {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  page.on('console', (message) => {
    // a Content-Security-Policy violation or an uncaught error fails the test that caused it
    if (message.type() === 'error' && !message.text().includes('favicon')) errors.push(message.text());
  });
  (page as Page & { appErrors?: string[] }).appErrors = errors;
  await page.goto(url);
  await page.waitForFunction(() => window.halfedgeLab !== undefined);
  await page.evaluate(() => window.halfedgeLab.ready);
}

export function appErrors(page: Page): string[] {
  return (page as Page & { appErrors?: string[] }).appErrors ?? [];
}

/** Whether a point (relative to the canvas) shows the canvas itself, with no panel over it. */
export async function onCanvas(page: Page, x: number, y: number): Promise<boolean> {
  return page.evaluate(([x, y]) => {
    const canvas = document.querySelector('#viewport canvas')!;
    const box = canvas.getBoundingClientRect();
    return document.elementFromPoint(box.left + x!, box.top + y!) === canvas;
  }, [x, y]);
}

/** Clicks the canvas at a point given relative to it; a panel over that point fails the test plainly. */
export async function clickCanvas(page: Page, x: number, y: number): Promise<void> {
  const box = await page.locator('#viewport canvas').boundingBox();
  if (!box) throw new Error('no canvas');
  if (!(await onCanvas(page, x, y))) throw new Error(`something covers the canvas at ${x}, ${y}`);
  await page.mouse.click(box.x + x, box.y + y);
}

/** Red, green, blue of a canvas pixel (CSS pixels relative to the canvas). */
export async function canvasPixel(page: Page, x: number, y: number): Promise<[number, number, number]> {
  return page.evaluate(
    ([px, py]) => {
      const canvas = document.querySelector('#viewport canvas') as HTMLCanvasElement;
      const ratio = canvas.width / canvas.clientWidth;
      const probe = document.createElement('canvas');
      probe.width = probe.height = 1;
      const context = probe.getContext('2d')!;
      context.drawImage(canvas, Math.round(px * ratio), Math.round(py * ratio), 1, 1, 0, 0, 1, 1);
      const [r, g, b] = context.getImageData(0, 0, 1, 1).data;
      return [r, g, b] as [number, number, number];
    },
    [x, y],
  );
}

/** The smallest colour distance to `colour` among the canvas pixels within `radius` of (x, y). */
export async function nearestColourDistance(page: Page, x: number, y: number, colour: [number, number, number], radius = 6): Promise<number> {
  return page.evaluate(
    ([px, py, r, [cr, cg, cb]]) => {
      const canvas = document.querySelector('#viewport canvas') as HTMLCanvasElement;
      const ratio = canvas.width / canvas.clientWidth;
      const size = Math.round(2 * r * ratio) + 1;
      const probe = document.createElement('canvas');
      probe.width = probe.height = size;
      const context = probe.getContext('2d')!;
      context.drawImage(canvas, Math.round((px - r) * ratio), Math.round((py - r) * ratio), size, size, 0, 0, size, size);
      const data = context.getImageData(0, 0, size, size).data;
      let best = Infinity;
      for (let i = 0; i < data.length; i += 4) best = Math.min(best, Math.hypot(data[i]! - cr, data[i + 1]! - cg, data[i + 2]! - cb));
      return best;
    },
    [x, y, radius, colour] as const,
  );
}

export function hexToRgb(hex: string): [number, number, number] {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

export function colourDistance(a: [number, number, number], b: [number, number, number]): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/** The vertices of the mesh drawn under one of the overlays named (ids of the panels over the view). */
export async function verticesUnderOverlays(page: Page, overlayIds: string[]): Promise<string[]> {
  return page.evaluate((ids) => {
    const canvas = document.querySelector('#viewport canvas')!.getBoundingClientRect();
    const boxes = ids
      .map((id) => document.getElementById(id)!)
      .filter((overlay) => overlay.checkVisibility())
      .map((overlay) => overlay.getBoundingClientRect());
    const { vertices } = window.halfedgeLab.state().stats!;
    const under: string[] = [];
    for (let v = 0; v < vertices; v++) {
      const at = window.halfedgeLab.screenPosition(`v${v}`);
      const x = canvas.left + at.x;
      const y = canvas.top + at.y;
      if (boxes.some((box) => x >= box.left && x <= box.right && y >= box.top && y <= box.bottom)) under.push(`v${v}`);
    }
    return under;
  }, overlayIds);
}

/**
 * Text of the side panel that a room cannot read in presentation mode: cut by the window's edge,
 * or below it. A box that scrolls its own long content (`.scroll-box`: the operations, the history,
 * a pointer diff, the practice panel…) must itself be in the window, with its first lines in
 * sight; what it scrolls away is not counted.
 */
export async function textOutside(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const inside = (box: DOMRect, frame: { top: number; bottom: number; left: number; right: number }) =>
      box.top >= frame.top - 0.5 && box.bottom <= frame.bottom + 0.5 && box.left >= frame.left - 0.5 && box.right <= frame.right + 0.5;
    const window_ = { top: 0, left: 0, bottom: window.innerHeight, right: window.innerWidth };
    const problems: string[] = [];
    const side = document.querySelector('.side')!;
    for (const element of side.querySelectorAll<HTMLElement>('*')) {
      const text = [...element.childNodes].filter((node) => node.nodeType === Node.TEXT_NODE).map((node) => node.textContent!.trim()).filter(Boolean).join(' ');
      if (!text || !element.checkVisibility({ visibilityProperty: true }) || element.getClientRects().length === 0) continue;
      const box = element.getBoundingClientRect();
      if (box.width === 0 || box.height === 0) continue;
      const scroller = element.closest<HTMLElement>('.scroll-box');
      if (scroller) {
        const frame = scroller.getBoundingClientRect();
        if (!inside(frame, window_)) problems.push(`the box of “${text.slice(0, 40)}” reaches outside the window`);
        continue;
      }
      if (!inside(box, window_)) problems.push(`“${text.slice(0, 60)}” at ${Math.round(box.left)},${Math.round(box.top)}–${Math.round(box.right)},${Math.round(box.bottom)}`);
    }
    return problems;
  });
}

/** Asks until the answer lies where a click picks it (a random answer may sit under the counts panel). */
export async function askClickable(page: Page): Promise<{ answer: string; path: string[]; text: string; x: number; y: number }> {
  for (let tries = 0; tries < 20; tries++) {
    const question = (await page.evaluate(() => window.halfedgeLab.quiz.question()))!;
    const kind = question.answer[0] === 'h' ? 'halfedge' : question.answer[0] === 'v' ? 'vertex' : 'face';
    const at = await page.evaluate((name) => window.halfedgeLab.screenPosition(name), question.answer);
    const picked = await page.evaluate(([x, y, k]) => window.halfedgeLab.pickAt(x as number, y as number, k as 'face'), [at.x, at.y, kind]);
    if (at.visible && picked === question.answer && (await onCanvas(page, at.x, at.y))) return { ...question, x: at.x, y: at.y };
    await page.evaluate(() => window.halfedgeLab.quiz.ask());
  }
  throw new Error('no question with an answer that can be clicked');
}

/** A test solution's source (tests/practice/solutions/NAME.js). */
export function solution(name: string): string {
  return readFileSync(new URL(`../tests/practice/solutions/${name}.js`, import.meta.url), 'utf8');
}

/** Replaces the editor's text as a student would paste it, and runs it with the Run button. */
export async function typeAndRun(page: Page, code: string): Promise<void> {
  await page.locator('.practice-editor .cm-content').click();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.press('Delete');
  await page.keyboard.insertText(code);
  await page.getByRole('button', { name: 'Run the solution' }).click();
}
