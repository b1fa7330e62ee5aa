/**
 * The pointer colours seen as a room sees them: on a washed-out projector (the colours mixed with
 * 40% white, as a bright room and a weak lamp do) and by colour-blind students (deuteranopia and
 * protanopia, Machado, Oliveira and Fernandes 2009, severity 1). Any two arrow roles drawn at once
 * whose colours then come close (CIE76 ΔE below 25) must also differ in shape: one hollow.
 */
import { describe, expect, it } from 'vitest';
import { colors, hollowRoles, type PointerRole } from '../../src/ui/colors.js';

const toLinear = (c: number) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);
const toSrgb = (c: number) => (c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055);
const linearRgb = (hex: string) => [1, 3, 5].map((i) => toLinear(parseInt(hex.slice(i, i + 2), 16) / 255));

function lab([r, g, b]: number[]): number[] {
  const x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const f = (t: number) => (t > 216 / 24389 ? Math.cbrt(t) : ((24389 / 27) * t + 16) / 116);
  return [116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))];
}

const matrix = (m: number[][]) => (c: number[]) => m.map((row) => Math.min(1, Math.max(0, row[0]! * c[0]! + row[1]! * c[1]! + row[2]! * c[2]!)));
const views: Record<string, (linear: number[]) => number[]> = {
  'a washed-out projector': (c) => c.map((x) => toLinear(0.6 * toSrgb(x) + 0.4)),
  deuteranopia: matrix([
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.01182, 0.04294, 0.968881],
  ]),
  protanopia: matrix([
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
  ]),
};

const arrowRoles: PointerRole[] = ['selected', 'next', 'prev', 'twin'];

function difference(a: PointerRole, b: PointerRole, view: (c: number[]) => number[]): number {
  const [p, q] = [lab(view(linearRgb(colors[a]))), lab(view(linearRgb(colors[b])))];
  return Math.hypot(p[0]! - q[0]!, p[1]! - q[1]!, p[2]! - q[2]!);
}

describe('the pointer colours in the room', () => {
  it('tell every two arrow roles apart by colour, or else one of them is hollow', () => {
    const close: string[] = [];
    for (const [name, view] of Object.entries(views)) {
      for (let i = 0; i < arrowRoles.length; i++) {
        for (let j = i + 1; j < arrowRoles.length; j++) {
          const [a, b] = [arrowRoles[i]!, arrowRoles[j]!];
          if (difference(a, b, view) >= 25) continue;
          close.push(`${a}–${b} on ${name}`);
          expect(hollowRoles.has(a) !== hollowRoles.has(b), `${a} and ${b} on ${name}`).toBe(true);
        }
      }
    }
    // the pairs the issue names do come close: the check above is not empty
    expect(close).toEqual(expect.arrayContaining(['selected–twin on a washed-out projector', 'next–prev on a washed-out projector']));
  });
});
