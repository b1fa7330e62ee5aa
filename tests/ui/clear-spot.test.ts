import { describe, expect, it } from 'vitest';
import { clearSpot, covered } from '../../src/ui/scene/clear-spot.js';

describe('the clear spot of a view', () => {
  it('is the middle of a view with no overlays, as large as the view allows', () => {
    expect(clearSpot(800, 600, [])).toEqual({ x: 400, y: 300, radius: 300 });
  });

  it('moves away from a large overlay in a corner, meeting none of it', () => {
    const legend = { left: 0, top: 0, right: 390, bottom: 300 };
    const spot = clearSpot(820, 560, [legend]);
    expect(spot.x).toBeGreaterThan(410);
    expect(spot.radius).toBeGreaterThan(0.5 * 280);
    // the circle keeps off the legend and inside the view
    const dx = Math.max(legend.left - spot.x, 0, spot.x - legend.right);
    const dy = Math.max(legend.top - spot.y, 0, spot.y - legend.bottom);
    expect(Math.hypot(dx, dy)).toBeGreaterThanOrEqual(spot.radius);
    expect(spot.x + spot.radius).toBeLessThanOrEqual(820);
    expect(spot.y + spot.radius).toBeLessThanOrEqual(560);
  });

  it('stays in the middle when the overlays leave no room for a circle of a useful size', () => {
    const band = { left: 0, top: 200, right: 800, bottom: 400 };
    expect(clearSpot(800, 600, [band])).toEqual({ x: 400, y: 300, radius: 300 });
    // a small embed with its legend and counts: a clear circle there would show the mesh too small to read
    const legend = { left: 10, top: 10, right: 215, bottom: 190 };
    const counts = { left: 245, top: 10, right: 490, bottom: 160 };
    expect(clearSpot(500, 360, [legend, counts])).toEqual({ x: 250, y: 180, radius: 180 });
  });

  it('knows when an overlay covers part of a circle, and when it only touches or misses it', () => {
    const circle = { x: 400, y: 300, radius: 100 };
    expect(covered(circle, [{ left: 450, top: 250, right: 600, bottom: 280 }])).toBe(true);
    // beside the circle's edge, and off its bounding square's corner
    expect(covered(circle, [{ left: 500, top: 0, right: 600, bottom: 600 }])).toBe(false);
    expect(covered(circle, [{ left: 480, top: 0, right: 600, bottom: 220 }])).toBe(false);
    // the spot found for an overlay meets none of it
    const card = { left: 0, top: 0, right: 390, bottom: 350 };
    expect(covered(clearSpot(820, 560, [card]), [card])).toBe(false);
  });
});
