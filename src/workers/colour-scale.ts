/**
 * Colours for per-vertex values a phase reports (a quadric's error, a distance to the cutting
 * plane, how far smoothing moved a vertex), computed in the worker with the snapshot so that the
 * page only uploads them. Values of one sign run from light to dark; values of both signs from
 * blue through white to vermillion (Okabe–Ito ends, readable by colour-blind students). A few
 * outliers do not wash out the rest: the scale stops at the 98th percentile of the magnitudes.
 *
 * The colours are linear RGB, as three.js reads vertex colours; the stops are the sRGB colours
 * named here, blended in linear RGB as three.js's `Color.lerp` would blend them.
 */

export interface ColourScale {
  /** Three numbers per value, 0 … 1, linear RGB. */
  colours: Float32Array;
  low: number;
  high: number;
  diverging: boolean;
}

type Rgb = readonly [number, number, number];

/** `#rrggbb` as linear RGB (the sRGB transfer undone). */
function linear(hex: string): Rgb {
  const channel = (at: number) => {
    const c = parseInt(hex.slice(at, at + 2), 16) / 255;
    return c < 0.04045 ? c * 0.0773993808 : Math.pow(c * 0.9478672986 + 0.0521327014, 2.4);
  };
  return [channel(1), channel(3), channel(5)];
}

const light = linear('#F0E442');
const middle = linear('#009E73');
const dark = linear('#0072B2');
const negative = linear('#0072B2');
const positive = linear('#D55E00');
const white = linear('#ffffff');
const missing = linear('#9a9a9a');

export function colourScale(values: ArrayLike<number>): ColourScale {
  let below = false;
  let above = false;
  let lowest = Infinity;
  const magnitudes = new Float64Array(values.length);
  let finite = 0;
  for (let i = 0; i < values.length; i++) {
    const x = values[i]!;
    if (!Number.isFinite(x)) continue;
    below ||= x < 0;
    above ||= x > 0;
    lowest = Math.min(lowest, x);
    magnitudes[finite++] = Math.abs(x);
  }
  const diverging = below && above;
  const top = (finite > 0 ? select(magnitudes.subarray(0, finite), Math.floor(0.98 * (finite - 1))) : 0) || 1;
  const low = diverging ? -top : Math.min(lowest, top);
  const colours = new Float32Array(3 * values.length);
  const put = (i: number, from: Rgb, to: Rgb, t: number) => {
    colours[3 * i] = from[0] + (to[0] - from[0]) * t;
    colours[3 * i + 1] = from[1] + (to[1] - from[1]) * t;
    colours[3 * i + 2] = from[2] + (to[2] - from[2]) * t;
  };
  for (let i = 0; i < values.length; i++) {
    const x = values[i]!;
    if (!Number.isFinite(x)) put(i, missing, missing, 0);
    else if (diverging) {
      const t = Math.max(-1, Math.min(1, x / top));
      put(i, white, t < 0 ? negative : positive, Math.abs(t));
    } else {
      const t = top === low ? 0 : Math.max(0, Math.min(1, (x - low) / (top - low)));
      if (t < 0.5) put(i, light, middle, 2 * t);
      else put(i, middle, dark, 2 * t - 1);
    }
  }
  return { colours, low, high: top, diverging };
}

/**
 * The k-th smallest of `values` (reordering them): quickselect, a pass a round over a shrinking
 * range, so a percentile of a million values costs a few passes rather than a sort.
 */
export function select(values: Float64Array, k: number): number {
  let left = 0;
  let right = values.length - 1;
  // each round leaves out at least the pivot: at most `length` rounds
  for (let round = 0; round < values.length && left < right; round++) {
    const pivot = medianOfThree(values[left], values[(left + right) >> 1], values[right]);
    let i = left;
    let j = right;
    while (i <= j) {
      while (values[i] < pivot) i++;
      while (values[j] > pivot) j--;
      if (i <= j) {
        const swap = values[i];
        values[i++] = values[j];
        values[j--] = swap;
      }
    }
    if (k <= j) right = j;
    else if (k >= i) left = i;
    else break; // between j and i every value equals the pivot
  }
  return values[k];
}

function medianOfThree(a: number, b: number, c: number): number {
  return Math.max(Math.min(a, b), Math.min(Math.max(a, b), c));
}
