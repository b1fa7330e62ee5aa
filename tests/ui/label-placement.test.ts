/**
 * Where labels go, worked out on boxes alone: beside their anchors, inside the view, off the
 * overlays, and apart from one another.
 */
import { describe, expect, it } from 'vitest';
import type { Rect } from '../../src/ui/scene/clear-spot.js';
import { labelOffsets } from '../../src/ui/scene/label-placement.js';

const view: Rect = { left: 0, top: 0, right: 640, bottom: 400 };
const box = (x: number, y: number, width: number, height: number): Rect => ({ left: x - width / 2, top: y - height / 2, right: x + width / 2, bottom: y + height / 2 });
const area = (r: Rect) => Math.max(0, r.right - r.left) * Math.max(0, r.bottom - r.top);
const overlap = (a: Rect, b: Rect) =>
  area({ left: Math.max(a.left, b.left), top: Math.max(a.top, b.top), right: Math.min(a.right, b.right), bottom: Math.min(a.bottom, b.bottom) });
const centre = (r: Rect) => ({ x: (r.left + r.right) / 2, y: (r.top + r.bottom) / 2 });

/** The label boxes where the offsets put them. */
function placed(labels: Rect[], obstacles: Rect[] = []): Rect[] {
  const offsets = labelOffsets(labels, labels.map(centre), obstacles, view);
  return labels.map((r, i) => ({ left: r.left + offsets[i]!.dx, top: r.top + offsets[i]!.dy, right: r.right + offsets[i]!.dx, bottom: r.bottom + offsets[i]!.dy }));
}

function expectApartAndInside(boxes: Rect[]): void {
  for (const r of boxes) expect(r.left >= view.left && r.right <= view.right && r.top >= view.top && r.bottom <= view.bottom, JSON.stringify(r)).toBe(true);
  // at most a sliver: 4 % of the smaller box
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      expect(overlap(boxes[i]!, boxes[j]!), `labels ${i} and ${j}`).toBeLessThanOrEqual(0.04 * Math.min(area(boxes[i]!), area(boxes[j]!)));
    }
  }
}

describe('label placement', () => {
  it('spreads six labels anchored on one small spot so that none covers another', () => {
    // the pile a three-faced edge used to make: six labels within a few pixels
    const labels = [0, 1, 2, 3, 4, 5].map((i) => box(320 + 3 * i, 200 + 2 * i, 180, 26));
    expectApartAndInside(placed(labels));
  });

  it('keeps a label anchored at the top edge of the view inside it, not clipped', () => {
    const [top] = placed([box(300, 4, 260, 48)]);
    expect(top!.top).toBeGreaterThanOrEqual(0);
    // an anchor above the view altogether: the label still comes in
    const [above] = placed([box(300, -300, 260, 48)]);
    expect(above!.top).toBeGreaterThanOrEqual(0);
    expect(above!.bottom).toBeLessThanOrEqual(view.bottom);
  });

  it('keeps labels off the overlays and off their own anchors', () => {
    const legend: Rect = { left: 0, top: 0, right: 200, bottom: 160 };
    const labels = [box(210, 120, 240, 46), box(230, 140, 240, 46)];
    const boxes = placed(labels, [legend]);
    expectApartAndInside(boxes);
    for (const [i, r] of boxes.entries()) {
      expect(overlap(r, legend), `label ${i} on the legend`).toBe(0);
      const anchor = centre(labels[i]!);
      expect(anchor.x > r.left && anchor.x < r.right && anchor.y > r.top && anchor.y < r.bottom, `label ${i} on its anchor`).toBe(false);
    }
  });

  it('places a free label at the first place of the ring: just right of its anchor, clear of it', () => {
    const [offset] = labelOffsets([box(320, 200, 100, 20)], [{ x: 320, y: 200 }], [], view);
    expect(offset!.dy).toBe(0);
    expect(offset!.dx).toBeGreaterThan(50 + 10);
    expect(offset!.dx).toBeLessThanOrEqual(50 + 24);
  });
});
