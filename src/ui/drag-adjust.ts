/**
 * Dragging an extrusion's offset or a bevel's amount in the view, as a modelling tool does. Once
 * an extrusion or a bevel has landed, a drag on the view sets how far it goes instead of turning
 * the camera: up for more, down for less.
 * ```
 *   pointer   down ─────── move ──── move ────────── up          a click, a key or another
 *   edit                 undo+edit  (busy: the    undo+edit      edit ends the dragging
 *                        offset .3  latest waits) offset .45
 * ```
 * Each step takes the edit back and makes it again with the new number (through the app, so
 * "Use my code" runs the student's own extrusion each time), one at a time: a move made while a
 * step is under way waits, and only the latest one runs. The history keeps one entry.
 */
import type { EditRequest } from '../workers/operations.js';

/** An edit a drag can set: its request with the number written out, and that number's name and range. */
export interface Adjustable {
  request: EditRequest;
  /** The number the drag sets: `offset` of an extrusion, `amount` of a bevel. */
  field: 'offset' | 'amount';
  value: number;
  /** Change per pixel dragged up. */
  perPixel: number;
  min: number;
  max: number;
}

/** How a drag redoes the edit: take the last edit back and make `request` instead; false when it did not land. */
export type Redo = (request: EditRequest) => Promise<boolean>;

/**
 * The adjustable form of an edit that landed, with the numbers it used (`used`: what the library
 * or the solution was called with), or null for an edit there is nothing to drag in.
 */
export function adjustable(request: EditRequest, used: { readonly [name: string]: number } | null): Adjustable | null {
  if (!used) return null;
  if (request.kind === 'extrude-face') {
    const offset = used.offset ?? 0;
    // a pixel moves the face a hundredth of its first offset, or of a unit when it had none
    const step = Math.abs(offset) > 0 ? Math.abs(offset) / 100 : 0.01;
    return { request: { ...request, offset, inset: used.inset ?? 0 }, field: 'offset', value: offset, perPixel: step, min: -Infinity, max: Infinity };
  }
  if (request.kind === 'bevel-vertex' || request.kind === 'bevel-edge') {
    // the whole range in about 300 pixels; never 0 or 1, where the new corners would meet
    return { request: { ...request, amount: used.amount ?? 0.25 }, field: 'amount', value: used.amount ?? 0.25, perPixel: 1 / 300, min: 0.02, max: 0.95 };
  }
  return null;
}

export class DragAdjust {
  /** The edit the next drag sets, or null. */
  target: Adjustable | null = null;
  private dragging: { startY: number; startValue: number } | null = null;
  private busy = false;
  /** The value a move asked for while a step was under way: the next step's. */
  private waiting: number | null = null;

  constructor(
    private readonly redo: Redo,
    private readonly say: (message: string) => void,
  ) {}

  /** After an extrusion or a bevel: the next drag on the view sets its number. */
  offer(target: Adjustable | null): void {
    this.target = target;
    this.dragging = null;
  }

  /** A click, a key or another edit: the edit stays as it is. */
  end(): void {
    this.offer(null);
  }

  /** A pointer pressed on the view: true when the drag is this one's (the camera then stays). */
  down(y: number): boolean {
    if (!this.target) return false;
    this.dragging = { startY: y, startValue: this.target.value };
    return true;
  }

  move(y: number): void {
    if (!this.dragging || !this.target) return;
    const { min, max, perPixel } = this.target;
    const value = Math.min(max, Math.max(min, this.dragging.startValue + (this.dragging.startY - y) * perPixel));
    this.waiting = +value.toPrecision(3);
    void this.flush();
  }

  /** The pointer let go: the drag is over, and the next one starts from where this one left the number. */
  up(): void {
    this.dragging = null;
  }

  private async flush(): Promise<void> {
    while (!this.busy && this.waiting !== null && this.target) {
      const value = this.waiting;
      this.waiting = null;
      if (value === this.target.value) continue;
      this.busy = true;
      const request = { ...this.target.request, [this.target.field]: value } as EditRequest;
      try {
        if (await this.redo(request)) {
          this.target = { ...this.target, request, value };
          this.say(`${this.target.field === 'offset' ? 'Offset' : 'Amount'} ${value}: drag up or down in the view to change it; a click keeps it.`);
        }
      } finally {
        this.busy = false;
      }
    }
  }
}
