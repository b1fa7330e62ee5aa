/** The cutting plane a·x + b·y + c·z + d = 0, as the user gives it and as the cut uses it. */
import { InvalidInputError } from '../errors.js';

/** A plane a·x + b·y + c·z + d = 0; "above" is where a·x + b·y + c·z + d > 0. */
export type Plane = { a: number; b: number; c: number; d: number } | readonly [number, number, number, number];

/** The plane scaled so (a, b, c) has length 1: then a·x + b·y + c·z + d is the signed distance. */
export interface UnitPlane {
  nx: number;
  ny: number;
  nz: number;
  d: number;
}

/**
 * @throws InvalidInputError when a coefficient is not a finite number or (a, b, c) is zero.
 */
export function unitPlane(plane: Plane): UnitPlane {
  const [a, b, c, d] = 'a' in plane ? [plane.a, plane.b, plane.c, plane.d] : plane;
  if (![a, b, c, d].every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new InvalidInputError(`the plane needs four finite numbers a, b, c, d, not ${[a, b, c, d].join(', ')}`);
  }
  const length = Math.hypot(a, b, c);
  if (length === 0) throw new InvalidInputError('the plane has normal (a, b, c) = (0, 0, 0): it has no direction');
  return { nx: a / length, ny: b / length, nz: c / length, d: d / length };
}
