import { describe, expect, it } from 'vitest';
import { adjustable, DragAdjust } from '../../src/ui/drag-adjust.js';
import type { EditRequest } from '../../src/workers/operations.js';

describe('dragging an extrusion or a bevel', () => {
  it('offers an extrusion by its offset and a bevel by its amount, with the numbers the edit used', () => {
    expect(adjustable({ kind: 'extrude-face', face: 3 }, { face: 3, offset: 0.4, inset: 0.1 })).toMatchObject({
      request: { kind: 'extrude-face', face: 3, offset: 0.4, inset: 0.1 },
      field: 'offset',
      value: 0.4,
      perPixel: 0.004,
    });
    expect(adjustable({ kind: 'bevel-edge', edge: 2 }, { edge: 2, amount: 0.25 })).toMatchObject({ request: { kind: 'bevel-edge', edge: 2, amount: 0.25 }, field: 'amount', min: 0.02, max: 0.95 });
    expect(adjustable({ kind: 'flip-edge', edge: 2 }, null)).toBeNull();
    expect(adjustable({ kind: 'poke-face', face: 2 }, { face: 2 })).toBeNull();
  });

  it('makes the edit again for each move, the latest of those made while one is under way, within its range', async () => {
    const made: EditRequest[] = [];
    let finish: (() => void) | null = null;
    const drag = new DragAdjust(
      (request) =>
        new Promise((resolve) => {
          made.push(request);
          finish = () => resolve(true);
        }),
      () => {},
    );
    drag.offer(adjustable({ kind: 'bevel-vertex', vertex: 1 }, { vertex: 1, amount: 0.25 }));
    expect(drag.down(300)).toBe(true);
    drag.move(270); // 30 px up: 0.25 + 0.1
    drag.move(240); // while the first is under way
    drag.move(0); // the latest: 0.25 + 1, held at 0.95
    expect(made).toHaveLength(1);
    expect(made[0]).toMatchObject({ amount: 0.35 });
    finish!();
    await new Promise((resolve) => setTimeout(resolve));
    expect(made).toHaveLength(2);
    expect(made[1]).toMatchObject({ kind: 'bevel-vertex', vertex: 1, amount: 0.95 });
    finish!();
    await new Promise((resolve) => setTimeout(resolve));
    expect(drag.target!.value).toBe(0.95);
    drag.up();
    drag.end();
    expect(drag.down(10)).toBe(false);
  });

  it('keeps the number it had when the edit made again does not apply', async () => {
    const drag = new DragAdjust(async () => false, () => {});
    drag.offer(adjustable({ kind: 'extrude-face', face: 0 }, { face: 0, offset: 1, inset: 0 }));
    drag.down(100);
    drag.move(0);
    await new Promise((resolve) => setTimeout(resolve));
    expect(drag.target).toMatchObject({ value: 1, request: { offset: 1 } });
  });
});
