/** Fixtures and checks shared by the decimation tests. */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect } from 'vitest';
import { buildMesh } from '../../src/core/build.js';
import { type DecimationOptions, decimation } from '../../src/core/decimation/index.js';
import { boundingBox } from '../../src/core/geometry.js';
import { readMesh } from '../../src/core/io/index.js';
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { type Phase, type PhaseElements, phaseElements } from '../../src/core/change/operation.js';
import type { PolygonSoup } from '../../src/core/soup.js';
import { validate } from '../../src/core/validate.js';

export function meshOf(soup: PolygonSoup): HalfedgeMesh {
  const { mesh, report } = buildMesh(soup);
  expect(report.repairs).toEqual([]);
  return mesh;
}

/** The Stanford bunny of the sample models (1839 vertices, 3674 triangles, closed). */
export function bunny(): HalfedgeMesh {
  const bytes = readFileSync(join(import.meta.dirname, '../../public/models/bunny.ply'));
  return meshOf(readMesh(bytes, { fileName: 'bunny.ply' }).soup);
}

/** Steps through the decimation, checking the mesh after every phase; returns the phases. */
export function stepDecimation(mesh: HalfedgeMesh, options: DecimationOptions): Array<Phase & PhaseElements> {
  const phases: Array<Phase & PhaseElements> = [];
  for (const phase of decimation(mesh, options)) {
    expect(validate(mesh), `after "${phase.name}"`).toEqual([]);
    phases.push({ ...phase, ...phaseElements(phase.change!) });
  }
  return phases;
}

/** Length of the bounding-box diagonal. */
export function diagonal(mesh: HalfedgeMesh): number {
  const { min, max } = boundingBox(mesh)!;
  return Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
}

/** The corners of every live triangle, 9 numbers each. */
export function triangles(mesh: HalfedgeMesh): Float64Array {
  const corners: number[] = [];
  for (const f of mesh.faces()) {
    let h = mesh.fHalfedge[f];
    for (let k = 0; k < 3; k++, h = mesh.heNext[h]) corners.push(...mesh.position(mesh.heVertex[h]));
  }
  return Float64Array.from(corners);
}

/**
 * Largest distance from a live vertex of `from` to the surface of `to` (brute force over the
 * triangles): the one-sided Hausdorff distance measured at the vertices.
 */
export function vertexToSurfaceDistance(from: HalfedgeMesh, to: HalfedgeMesh): number {
  const t = triangles(to);
  let worst = 0;
  for (const v of from.vertices()) {
    const p = from.position(v);
    let nearest = Infinity;
    for (let i = 0; i < t.length; i += 9) nearest = Math.min(nearest, pointTriangleDistance(p, t, i));
    worst = Math.max(worst, nearest);
  }
  return worst;
}

/** Distance from `p` to the triangle of corners t[i…i+2], t[i+3…i+5], t[i+6…i+8] (Ericson, §5.1.5). */
export function pointTriangleDistance(p: number[], t: ArrayLike<number>, i: number): number {
  const a = [t[i], t[i + 1], t[i + 2]];
  const b = [t[i + 3], t[i + 4], t[i + 5]];
  const c = [t[i + 6], t[i + 7], t[i + 8]];
  const sub = (u: number[], w: number[]) => [u[0] - w[0], u[1] - w[1], u[2] - w[2]];
  const dot = (u: number[], w: number[]) => u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
  const at = (s: number, u: number[], w: number[]) => [u[0] + s * w[0], u[1] + s * w[1], u[2] + s * w[2]];
  const distance = (q: number[]) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  const ab = sub(b, a);
  const ac = sub(c, a);
  const ap = sub(p, a);
  const d1 = dot(ab, ap);
  const d2 = dot(ac, ap);
  // in the region of corner a, b or c, or of edge ab, ac or bc? else inside the face
  if (d1 <= 0 && d2 <= 0) return distance(a);
  const bp = sub(p, b);
  const d3 = dot(ab, bp);
  const d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return distance(b);
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return distance(at(d1 / (d1 - d3), a, ab));
  const cp = sub(p, c);
  const d5 = dot(ab, cp);
  const d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return distance(c);
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return distance(at(d2 / (d2 - d6), a, ac));
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return distance(at((d4 - d3) / (d4 - d3 + (d5 - d6)), b, sub(c, b)));
  const denominator = 1 / (va + vb + vc);
  const v = vb * denominator;
  const w = vc * denominator;
  return distance([a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w]);
}
