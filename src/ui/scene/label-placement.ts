/**
 * Placing the labels of a highlight so that each can be read and none hides what it labels.
 *
 * A label is anchored at its element (the middle of an arrow, a vertex, a face's centre), and
 * left there it covers the very arrow it names. So each label is moved beside its anchor: the
 * first of a ring of places around it (right, left, above, below, then the diagonals, then further
 * out) where it covers no anchor of any label and no point a highlight marks (`.label-avoid`:
 * along an arrow from its tail to its tip, on a dot, across a tinted face), no label placed
 * before it, and no overlay of the view (the legend, the counts, the status line), and stays
 * inside the view. A thin line in the label's colour leads back to the anchor. When no place is
 * free, the label takes the place that covers least.
 */

import type { Rect } from './clear-spot.js';

type Point = { x: number; y: number };

/** Above this many labels (every id shown), they stay where they are: too many to place. */
const MAX_PLACED_LABELS = 40;
/** Gaps (CSS pixels) tried between a label and its anchor, nearest first. */
const GAPS = [8, 24, 44, 70, 110, 160];
/** Directions tried around the anchor, as unit steps in x and y (screen y down). */
const DIRECTIONS: Array<[number, number]> = [
  [1, 0],
  [-1, 0],
  [0, -1],
  [0, 1],
  [1, -1],
  [-1, -1],
  [1, 1],
  [-1, 1],
];
/** Space kept around an anchor point (half a thick arrow, or a vertex dot), in CSS pixels. */
const ANCHOR_MARGIN = 10;

/**
 * Places the `.label` elements under `root` (see above). `obstacles` are the screen rectangles
 * labels must keep off. Each label's parent is its anchor element, centred on the anchor point.
 */
export function placeLabels(root: HTMLElement, obstacles: DOMRect[]): void {
  const tags = [...root.querySelectorAll<HTMLElement>('.label')];
  for (const tag of tags) {
    tag.style.transform = '';
    leaderOf(tag).hidden = true;
  }
  if (tags.length > MAX_PLACED_LABELS) return;
  const rects = tags.map((tag) => tag.getBoundingClientRect());
  // the points to keep clear: each label's own anchor, and the points marked along the arrows
  const anchors = rects.map((r) => ({ x: r.left + r.width / 2, y: r.top + r.height / 2 }));
  for (const marker of root.querySelectorAll<HTMLElement>('.label-avoid')) {
    const r = marker.getBoundingClientRect();
    anchors.push({ x: r.left + r.width / 2, y: r.top + r.height / 2 });
  }
  const offsets = labelOffsets(rects, anchors, obstacles, root.getBoundingClientRect());
  tags.forEach((tag, i) => {
    const { dx, dy } = offsets[i];
    tag.style.transform = `translate(${dx}px, ${dy}px)`;
    drawLeader(tag, dx, dy, rects[i]);
  });
}

export interface Offset {
  dx: number;
  dy: number;
}

/**
 * Where each label goes, in order: the offset of its box from where it is drawn (centred on its
 * anchor). Pure, in screen rectangles, so that a test can give it boxes. Each box keeps inside
 * `bounds` and off the `obstacles`, the points of `keepClear` and the boxes placed before it.
 */
export function labelOffsets(labels: Rect[], keepClear: Point[], obstacles: Rect[], bounds: Rect): Offset[] {
  const placed = [...obstacles];
  return labels.map((rect) => {
    const { dx, dy } = freeSpot(rect, keepClear, placed, bounds);
    placed.push(shifted(rect, dx, dy));
    return { dx, dy };
  });
}

/**
 * The first offset of the ring around a label's anchor where it covers nothing; when every place
 * covers something, the one that covers least (another label or an overlay counts more than an
 * arrow's point). A place that crosses the edge of the view is pushed back inside it: a label
 * clipped at the top of the view cannot be read.
 */
function freeSpot(rect: Rect, anchors: Point[], placed: Rect[], bounds: Rect): Offset & { cost: number } {
  let best: (Offset & { cost: number }) | null = null;
  for (const gap of GAPS) {
    for (const [ux, uy] of DIRECTIONS) {
      const width = rect.right - rect.left;
      const height = rect.bottom - rect.top;
      const dx = inside(rect.left + ux * (width / 2 + gap), width, bounds.left, bounds.right) - rect.left;
      const dy = inside(rect.top + uy * (height / 2 + gap), height, bounds.top, bounds.bottom) - rect.top;
      const moved = shifted(rect, dx, dy);
      const cost = 10 * placed.filter((r) => overlaps(moved, r)).length + anchors.filter((a) => covers(moved, a.x, a.y, ANCHOR_MARGIN)).length;
      if (cost === 0) return { dx, dy, cost };
      if (!best || cost < best.cost) best = { dx, dy, cost };
    }
  }
  return best!;
}

/** The start of a span of `size` from `start`, moved to lie between `low` and `high` (its start shown when it is longer). */
function inside(start: number, size: number, low: number, high: number): number {
  return Math.max(low, Math.min(start, high - size));
}

function shifted(r: Rect, dx: number, dy: number): Rect {
  return { left: r.left + dx, top: r.top + dy, right: r.right + dx, bottom: r.bottom + dy };
}

function covers(r: Rect, x: number, y: number, margin: number): boolean {
  return x > r.left - margin && x < r.right + margin && y > r.top - margin && y < r.bottom + margin;
}

function overlaps(a: Rect, b: Rect): boolean {
  return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}

/** The label's leader line (made on first use), a sibling inside its anchor element. */
function leaderOf(tag: HTMLElement): HTMLElement {
  const anchor = tag.parentElement!;
  let leader = anchor.querySelector<HTMLElement>(':scope > .leader');
  if (!leader) {
    leader = document.createElement('span');
    leader.className = 'leader';
    leader.setAttribute('aria-hidden', 'true');
    anchor.prepend(leader);
  }
  return leader;
}

/** A line from the anchor point (the anchor element's centre) to the nearest point of the moved label. */
function drawLeader(tag: HTMLElement, dx: number, dy: number, rect: DOMRect): void {
  if (dx === 0 && dy === 0) return; // left on its anchor: nothing to lead back to
  const leader = leaderOf(tag);
  // the label's centre is (dx, dy) from the anchor: the line stops where that ray enters the label
  const length = Math.hypot(dx, dy);
  const inside = length * Math.min(dx ? rect.width / 2 / Math.abs(dx) : Infinity, dy ? rect.height / 2 / Math.abs(dy) : Infinity);
  const reach = Math.max(0, length - inside);
  leader.hidden = false;
  leader.style.width = `${reach}px`;
  leader.style.transform = `rotate(${Math.atan2(dy, dx)}rad)`;
  leader.style.background = tag.style.borderColor;
}
