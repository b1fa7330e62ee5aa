/**
 * Where on the view a framed mesh goes so that the overlays (the legend, the colour scale, the
 * counts, the status line) cover none of it: the largest circle inside the view that meets no
 * overlay. The camera then shows the mesh's bounding sphere in that circle, which in presentation
 * mode, where the overlays are large, keeps them off the mesh.
 * ```
 *   ┌────────┬──────────────┬──────┐
 *   │ legend │     ╭──╮     │counts│
 *   ├────────┘    (  ● )    └──────┤
 *   │              ╰──╯            │
 *   └status──┘─────────────────────┘
 * ```
 */

export interface Rect {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

export interface Spot {
  /** The centre, in the view's pixels. */
  x: number;
  y: number;
  radius: number;
}

/** Candidate centres along each side of the view (a grid: the overlays are few and boxy). */
const STEPS = 24;
/**
 * A clear spot smaller than this share of the whole view's circle, or than this many pixels
 * across its radius, shows the mesh too small to read (in a small embed, say): the mesh keeps the
 * middle and the whole view, overlays or not. Beside a phase card at 1280 × 720 the clear spot is
 * about 130 px across its radius, and a mesh that size still reads.
 */
const SMALLEST = 0.5;
const SMALLEST_PIXELS = 120;

/**
 * The largest circle in a `width` × `height` view that meets none of `overlays` (in the view's
 * pixels); the view's own circle when the overlays leave no room for one large enough (see
 * `SMALLEST`). Of equal circles, the one nearest the middle.
 */
export function clearSpot(width: number, height: number, overlays: readonly Rect[]): Spot {
  const whole = { x: width / 2, y: height / 2, radius: Math.min(width, height) / 2 };
  let best: Spot | null = null;
  let bestDistance = Infinity;
  for (let i = 0; i <= STEPS; i++) {
    for (let j = 0; j <= STEPS; j++) {
      const x = (width * i) / STEPS;
      const y = (height * j) / STEPS;
      let radius = Math.min(x, width - x, y, height - y);
      for (const r of overlays) radius = Math.min(radius, distanceToRect(x, y, r));
      const distance = Math.hypot(x - whole.x, y - whole.y);
      if (!best || radius > best.radius + 0.5 || (radius > best.radius - 0.5 && distance < bestDistance)) {
        best = { x, y, radius };
        bestDistance = distance;
      }
    }
  }
  return best && best.radius >= Math.max(SMALLEST * whole.radius, SMALLEST_PIXELS) ? best : whole;
}

/** Whether one of the overlays covers part of the circle (more than touching its edge). */
export function covered(circle: Spot, overlays: readonly Rect[]): boolean {
  return overlays.some((r) => distanceToRect(circle.x, circle.y, r) < circle.radius - 0.5);
}

/** How far (x, y) is from the rectangle: 0 inside it. */
function distanceToRect(x: number, y: number, r: Rect): number {
  const dx = Math.max(r.left - x, 0, x - r.right);
  const dy = Math.max(r.top - y, 0, y - r.bottom);
  return Math.hypot(dx, dy);
}
