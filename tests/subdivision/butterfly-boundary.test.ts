/**
 * Modified Butterfly next to the boundary: the published stencils (Zorin and Schröder's course
 * notes as open implementations transcribe them; rules 1–5 of butterfly.ts's header). Every
 * expected point here is worked out from the reference's tables in the test itself, its named
 * vertices found by lattice arithmetic on a grid or from the triangle list, never by the library.
 */
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import {
  buildMesh,
  butterflySubdivision,
  cube,
  disk,
  fan,
  type HalfedgeMesh,
  type PolygonSoup,
  runOperation,
  seededRandom,
  singleTriangle,
  soupFromArrays,
  strip,
  tetrahedron,
  uvSphere,
  validate,
} from '../../src/index.js';
import { creaseWeight, creaseWeights } from '../../src/core/subdivision/butterfly.js';
import { faceLists, triangulate } from './helpers.js';

type Terms = Array<[vertex: number, weight: number]>;
interface Stencil {
  rule: string;
  terms: Terms;
}

// ---------------------------------------------------------------------------------------------
// The reference's weights, transcribed

/** The interior extraordinary weights s_0 … s_(K−1), K ≥ 3. */
function interiorWeights(K: number): number[] {
  if (K === 3) return [5 / 12, -1 / 12, -1 / 12];
  if (K === 4) return [3 / 8, 0, -1 / 8, 0];
  return Array.from({ length: K }, (_, j) => (1 / 4 + Math.cos((2 * Math.PI * j) / K) + Math.cos((4 * Math.PI * j) / K) / 2) / K);
}

/** Rule 4 for the edge to neighbour i of a boundary vertex of k sectors: its own weight, then neighbours 0 … k. */
function creaseReference(k: number, i: number): { self: number; ring: number[] } {
  const t = Math.PI / k;
  const c0 = Math.cos(i * t) / 4 - (Math.sin(2 * t) * Math.sin(2 * i * t)) / (4 * k * (Math.cos(t) - Math.cos(2 * t)));
  const ring = Array.from({ length: k + 1 }, (_, j) =>
    j === 0 ? c0 : j === k ? -c0 : (Math.sin(i * t) * Math.sin(j * t) + Math.sin(2 * i * t) * Math.sin(2 * j * t) / 2) / k,
  );
  return { self: 1 - (Math.sin(t) * Math.sin(i * t)) / (k * (1 - Math.cos(t))), ring };
}

const half = (terms: Terms): Terms => terms.map(([v, w]) => [v, w / 2]);

// ---------------------------------------------------------------------------------------------
// Meshes and their adjacency, from the triangle list alone

const edgeKey = (u: number, v: number) => (u < v ? `${u},${v}` : `${v},${u}`);

class Adjacency {
  readonly neighbours: Array<Set<number>>;
  private readonly thirds = new Map<string, number[]>();

  constructor(readonly triangles: number[][], vertices: number) {
    this.neighbours = Array.from({ length: vertices }, () => new Set<number>());
    for (const [a, b, c] of triangles) {
      for (const [u, v, w] of [[a, b, c], [b, c, a], [c, a, b]]) {
        this.neighbours[u].add(v);
        this.neighbours[v].add(u);
        const key = edgeKey(u, v);
        if (!this.thirds.has(key)) this.thirds.set(key, []);
        this.thirds.get(key)!.push(w);
      }
    }
  }
  static of(soup: PolygonSoup): Adjacency {
    return new Adjacency(faceLists(soup), soup.positions.length / 3);
  }
  edges(): Array<[number, number]> {
    return [...this.thirds.keys()].map((key) => key.split(',').map(Number) as [number, number]);
  }
  /** The third corners of the triangles on edge u–v. */
  corners(u: number, v: number): number[] {
    return this.thirds.get(edgeKey(u, v)) ?? [];
  }
  boundaryEdge(u: number, v: number): boolean {
    return this.corners(u, v).length === 1;
  }
  valence(v: number): number {
    return this.neighbours[v].size;
  }
  onBoundary(v: number): boolean {
    return [...this.neighbours[v]].some((w) => this.boundaryEdge(v, w));
  }
  regular(v: number): boolean {
    return this.valence(v) === (this.onBoundary(v) ? 4 : 6);
  }
  kind(v: number): string {
    return `${this.regular(v) ? 'regular' : 'extraordinary'} ${this.onBoundary(v) ? 'boundary' : 'interior'}`;
  }
  /** The boundary neighbour of boundary vertex v other than w. */
  beyond(v: number, w: number): number {
    return [...this.neighbours[v]].find((u) => u !== w && this.boundaryEdge(v, u))!;
  }
  /** The vertex across side u–v from the triangle u, v, w. */
  across(u: number, v: number, w: number): number {
    return this.corners(u, v).find((c) => c !== w)!;
  }
  /** v's neighbours in order around it from `first` (on the boundary, `first` is a boundary neighbour). */
  fan(v: number, first: number): number[] {
    const order = [first];
    for (let prev = -1, cur = first; order.length < this.valence(v); ) {
      const next = this.corners(v, cur).find((c) => c !== prev)!;
      [prev, cur] = [cur, next];
      order.push(next);
    }
    return order;
  }
}

/** The reference's stencil for the new vertex on edge a–b, from the adjacency alone. */
function referenceStencil(mesh: Adjacency, a: number, b: number): Stencil {
  if (mesh.boundaryEdge(a, b)) {
    return { rule: 'four-point', terms: [[a, 9 / 16], [b, 9 / 16], [mesh.beyond(a, b), -1 / 16], [mesh.beyond(b, a), -1 / 16]] };
  }
  const [y, z] = mesh.corners(a, b);
  if (mesh.regular(a) && mesh.regular(b)) {
    const aBoundary = mesh.onBoundary(a);
    const bBoundary = mesh.onBoundary(b);
    if (!aBoundary && !bBoundary) {
      const wings = [mesh.across(a, y, b), mesh.across(b, y, a), mesh.across(a, z, b), mesh.across(b, z, a)];
      return { rule: 'ten-point', terms: [[a, 1 / 2], [b, 1 / 2], [y, 1 / 8], [z, 1 / 8], ...wings.map((w): [number, number] => [w, -1 / 16])] };
    }
    if (aBoundary !== bBoundary) {
      const [B, I] = aBoundary ? [a, b] : [b, a];
      const [ba, x] = mesh.boundaryEdge(B, y) ? [y, z] : [z, y];
      const [p, q] = [mesh.across(I, ba, B), mesh.across(I, x, B)];
      const terms: Terms = [[B, 3 / 8], [I, 5 / 8], [ba, 1 / 16], [x, 3 / 16], [mesh.beyond(B, ba), -1 / 16], [p, -1 / 16], [q, -1 / 8]];
      return { rule: 'interior–crease', terms };
    }
    const corner = (v: number) => mesh.valence(v) === 2 && mesh.boundaryEdge(a, v) && mesh.boundaryEdge(b, v);
    if (!corner(y) && !corner(z)) return { rule: 'midpoint', terms: [[a, 1 / 2], [b, 1 / 2]] };
    const [e, d] = corner(y) ? [y, z] : [z, y];
    return { rule: 'crease–crease', terms: [[a, 1 / 2], [b, 1 / 2], [d, 1 / 4], [mesh.beyond(a, e), -1 / 8], [mesh.beyond(b, e), -1 / 8]] };
  }
  if (mesh.regular(a) || mesh.regular(b)) {
    const [v, w] = mesh.regular(b) ? [a, b] : [b, a];
    return { rule: `${mesh.kind(v)} alone beside ${mesh.kind(w)}`, terms: endStencil(mesh, v, w) };
  }
  const kinds = [mesh.kind(a), mesh.kind(b)].sort().join(' and ');
  return { rule: `mean of ${kinds}`, terms: [...half(endStencil(mesh, a, b)), ...half(endStencil(mesh, b, a))] };
}

/** The stencil of the end v of edge v–w that is not regular. */
function endStencil(mesh: Adjacency, v: number, w: number): Terms {
  const midpoint: Terms = [[v, 1 / 2], [w, 1 / 2]];
  if (mesh.onBoundary(v)) {
    const k = mesh.valence(v) - 1;
    if (k < 2) return midpoint;
    const order = mesh.fan(v, mesh.beyond(v, -1));
    const { self, ring } = creaseReference(k, order.indexOf(w));
    return [[v, self], ...order.map((u, j): [number, number] => [u, ring[j]])];
  }
  const K = mesh.valence(v);
  if (K < 3) return midpoint;
  const s = interiorWeights(K);
  return [[v, 3 / 4], ...mesh.fan(v, w).map((u, j): [number, number] => [u, s[j]])];
}

// ---------------------------------------------------------------------------------------------
// Running the scheme and reading the result

/** The halfedge from v to w in the library's mesh (throws when they are not neighbours). */
function halfedgeBetween(mesh: HalfedgeMesh, v: number, w: number): number {
  let h = mesh.vHalfedge[v];
  for (let i = 0; i < 100; i++, h = mesh.hePrev[h] ^ 1) if (mesh.target(h) === w) return h;
  throw new Error(`v${v} and v${w} are not neighbours`);
}

/** One level of Butterfly on the soup; the old positions, and the new vertex of each old edge. */
function subdivideOnce(soup: PolygonSoup) {
  const mesh = buildMesh(soup).mesh;
  const old = mesh.positions.slice(0, 3 * mesh.vertexSlots);
  const V = mesh.vertexSlots;
  const edgePoint = new Map<string, number>();
  for (const [a, b] of Adjacency.of(soup).edges()) edgePoint.set(edgeKey(a, b), V + (halfedgeBetween(mesh, a, b) >> 1));
  runOperation(butterflySubdivision(mesh));
  expect(validate(mesh)).toEqual([]);
  const pointOn = (a: number, b: number) => {
    const v = edgePoint.get(edgeKey(a, b))!;
    return Array.from(mesh.positions.subarray(3 * v, 3 * v + 3));
  };
  return { mesh, old, pointOn };
}

/** A weighted sum of the positions `x`. */
function combine(x: ArrayLike<number>, terms: Terms): number[] {
  const sum = [0, 0, 0];
  for (const [v, w] of terms) for (let k = 0; k < 3; k++) sum[k] += w * x[3 * v + k];
  return sum;
}

function expectClose(actual: number[], expected: number[], message = '', digits = 12): void {
  actual.forEach((x, k) => expect(x, `${message} [${k}]`).toBeCloseTo(expected[k], digits));
}

/** Subdivides the soup once and checks every new vertex against the reference; returns the rules met. */
function expectReference(soup: PolygonSoup): Set<string> {
  const adjacency = Adjacency.of(soup);
  const { old, pointOn } = subdivideOnce(soup);
  const rules = new Set<string>();
  for (const [a, b] of adjacency.edges()) {
    const { rule, terms } = referenceStencil(adjacency, a, b);
    rules.add(rule);
    expectClose(pointOn(a, b), combine(old, terms), `edge v${a}–v${b} (${rule})`);
  }
  return rules;
}

/** The soup with heights (z) from `height(x, y)`, or seeded random ones. */
function withHeights(soup: PolygonSoup, height?: (x: number, y: number) => number): PolygonSoup {
  const p = Float64Array.from(soup.positions);
  const next = seededRandom(23);
  for (let v = 0; v < p.length / 3; v++) p[3 * v + 2] = height ? height(p[3 * v], p[3 * v + 1]) : next();
  return soupFromArrays(p, faceLists(soup));
}

// ---------------------------------------------------------------------------------------------
// A regular grid with a boundary

/** The six lattice directions of the grid's triangulation, counter-clockwise. */
const D: Array<[number, number]> = [[1, 0], [1, 1], [0, 1], [-1, 0], [-1, -1], [0, -1]];

/**
 * An m × m grid of vertices (i, j), vertex j·m + i, each square cut along its (1, 1) diagonal, laid
 * out by a shear so that no stencil is symmetric by accident: (x, y) = (i + 0.35 j, 0.9 j − 0.2 i) / (m − 1).
 */
function shearedGrid(m: number, height?: (x: number, y: number) => number): PolygonSoup {
  const positions: number[] = [];
  for (let j = 0; j < m; j++) for (let i = 0; i < m; i++) positions.push((i + 0.35 * j) / (m - 1), (0.9 * j - 0.2 * i) / (m - 1), 0);
  const faces: number[][] = [];
  for (let j = 0; j + 1 < m; j++) {
    for (let i = 0; i + 1 < m; i++) {
      const v = j * m + i;
      faces.push([v, v + 1, v + m + 1], [v, v + m + 1, v + m]);
    }
  }
  return withHeights(soupFromArrays(positions, faces), height);
}

/** A grid stencil with its named vertices found by lattice arithmetic; `swapped`: rule 2 with p and q exchanged. */
interface GridStencil extends Stencil {
  swapped?: Terms;
}

/**
 * The reference's stencil of edge a–b of `shearedGrid(m)`, by index: the vertex across side P–Q of
 * a triangle P, Q, R is P + Q − R, and a boundary runs straight between corners. Null for the edges
 * whose stencils reach round a corner (the four-point rule there, rule 4 at the corners of 3
 * neighbours), which the other tests cover.
 */
function gridStencil(m: number, a: number, b: number): GridStencil | null {
  const ij = (v: number): [number, number] => [v % m, Math.floor(v / m)];
  const inside = ([i, j]: number[]) => i >= 0 && j >= 0 && i < m && j < m;
  const id = ([i, j]: number[]) => j * m + i;
  const onBoundary = ([i, j]: number[]) => i === 0 || j === 0 || i === m - 1 || j === m - 1;
  const valence = (p: number[]) => D.filter(([di, dj]) => inside([p[0] + di, p[1] + dj])).length;
  const regular = (p: number[]) => valence(p) === (onBoundary(p) ? 4 : 6);
  /** p + q − r: with r a neighbour of p and q, the vertex across side p–q from r. */
  const plus = (p: number[], q: number[], r: number[] = [0, 0]) => [p[0] + q[0] - r[0], p[1] + q[1] - r[1]];
  const reflect = plus;
  /** The third corners of the triangles on edge p → q: p + D[k ± 1] for q − p = D[k]. */
  const corners = (p: number[], q: number[]) => {
    const k = D.findIndex(([di, dj]) => p[0] + di === q[0] && p[1] + dj === q[1]);
    return [plus(p, D[(k + 1) % 6]), plus(p, D[(k + 5) % 6])].filter(inside);
  };
  const named = (terms: Array<[number[], number]>): Terms => terms.map(([p, w]) => [id(p), w]);
  /** Whether p and q lie on one side of the square: whether p–q is a boundary edge, for neighbours. */
  const sameSide = (p: number[], q: number[]) => [0, 1].some((c) => p[c] === q[c] && (p[c] === 0 || p[c] === m - 1));
  const A = ij(a);
  const B = ij(b);
  if (sameSide(A, B)) {
    const [a2, b2] = [plus(A, A, B), plus(B, B, A)]; // 2a − b, 2b − a
    if (!inside(a2) || !inside(b2)) return null;
    return { rule: 'four-point', terms: named([[A, 9 / 16], [B, 9 / 16], [a2, -1 / 16], [b2, -1 / 16]]) };
  }
  if (!regular(A) || !regular(B)) return null;
  const [y, z] = corners(A, B);
  if (!onBoundary(A) && !onBoundary(B)) {
    const wings = [reflect(A, y, B), reflect(B, y, A), reflect(A, z, B), reflect(B, z, A)];
    const terms = named([[A, 1 / 2], [B, 1 / 2], [y, 1 / 8], [z, 1 / 8], ...wings.map((w): [number[], number] => [w, -1 / 16])]);
    return { rule: 'ten-point', terms };
  }
  if (onBoundary(A) !== onBoundary(B)) {
    const [Bd, I] = onBoundary(A) ? [A, B] : [B, A];
    const [y2, z2] = corners(Bd, I);
    const [ba, x] = sameSide(Bd, y2) ? [y2, z2] : [z2, y2]; // b_a: B's boundary neighbour
    const bc = plus(Bd, Bd, ba);
    const p = reflect(I, ba, Bd);
    const q = reflect(I, x, Bd);
    const common: Array<[number[], number]> = [[Bd, 3 / 8], [I, 5 / 8], [ba, 1 / 16], [x, 3 / 16], [bc, -1 / 16]];
    return {
      rule: 'interior–crease',
      terms: named([...common, [p, -1 / 16], [q, -1 / 8]]),
      swapped: named([...common, [p, -1 / 8], [q, -1 / 16]]),
    };
  }
  const e = [y, z].find((c) => valence(c) === 2);
  if (!e) return { rule: 'midpoint', terms: named([[A, 1 / 2], [B, 1 / 2]]) };
  const d = e === y ? z : y;
  return { rule: 'crease–crease', terms: named([[A, 1 / 2], [B, 1 / 2], [d, 1 / 4], [plus(A, A, e), -1 / 8], [plus(B, B, e), -1 / 8]]) };
}

describe('Butterfly on a regular grid with a boundary', () => {
  const m = 7;
  /** The grid's parameter point (i, j) as (x, y), the shear of `shearedGrid`. */
  const xy = (i: number, j: number) => [(i + 0.35 * j) / (m - 1), (0.9 * j - 0.2 * i) / (m - 1)];

  it('has 6 neighbours at interior vertices, 4 at boundary ones away from the corners', () => {
    const adjacency = Adjacency.of(shearedGrid(m));
    const corners = new Map([[0, 3], [m - 1, 2], [m * (m - 1), 2], [m * m - 1, 3]]);
    for (let v = 0; v < m * m; v++) {
      const [i, j] = [v % m, Math.floor(v / m)];
      const boundary = i === 0 || j === 0 || i === m - 1 || j === m - 1;
      expect(adjacency.onBoundary(v), `v${v}`).toBe(boundary);
      expect(adjacency.valence(v), `v${v}`).toBe(corners.get(v) ?? (boundary ? 4 : 6));
    }
  });

  it('puts each new vertex at its stencil (random heights), the named neighbours found on the lattice', () => {
    const soup = shearedGrid(m);
    const { old, pointOn } = subdivideOnce(soup);
    const counts = new Map<string, number>();
    for (const [a, b] of Adjacency.of(soup).edges()) {
      const stencil = gridStencil(m, a, b);
      if (!stencil) continue;
      counts.set(stencil.rule, (counts.get(stencil.rule) ?? 0) + 1);
      expectClose(pointOn(a, b), combine(old, stencil.terms), `edge v${a}–v${b} (${stencil.rule})`);
    }
    // every boundary side, both diagonal directions of rule 2, and the two corners of 2 neighbours
    // (n = m − 2 interior vertices a side; 2 of the 120 edges, at the corners of 3 neighbours, take rule 4)
    const n = m - 2;
    expect(Object.fromEntries(counts)).toEqual({
      'four-point': 4 * (m - 3), // each side's edges but the two at its ends
      'ten-point': 2 * n * (n - 1) + (n - 1) * (n - 1),
      'interior–crease': 2 * 4 * n - 4, // two per boundary vertex but the crease–crease edges' ends
      'crease–crease': 2,
    });
  });

  it('agrees with the stencils read off the triangle list, corners included', () => {
    const rules = expectReference(shearedGrid(m));
    expect(rules).toContain('extraordinary boundary alone beside regular interior'); // the corners of 3 neighbours
  });

  it('lands every point of rules 1–3 (and of the ten-point rule) on a quadratic height field', () => {
    const f = (x: number, y: number) => 0.7 * x * x - 1.1 * x * y + 0.45 * y * y - 0.3 * x + 0.8 * y + 0.25;
    const soup = shearedGrid(m, f);
    const { pointOn } = subdivideOnce(soup);
    const checked = new Set<string>();
    for (const [a, b] of Adjacency.of(soup).edges()) {
      const stencil = gridStencil(m, a, b);
      if (!stencil) continue;
      checked.add(stencil.rule);
      const [x, y, z] = pointOn(a, b);
      // at the middle of the edge in the parameter plane, on the surface
      const [i, j] = [(a % m + (b % m)) / 2, (Math.floor(a / m) + Math.floor(b / m)) / 2];
      expectClose([x, y], xy(i, j), `edge v${a}–v${b} (${stencil.rule})`);
      expect(z, `edge v${a}–v${b} (${stencil.rule})`).toBeCloseTo(f(x, y), 12);
    }
    expect([...checked].sort()).toEqual(['crease–crease', 'four-point', 'interior–crease', 'ten-point']);
  });

  it('needs p and q where the reference puts them: swapped, rule 2 would miss even a linear field', () => {
    const f = (x: number, y: number) => 0.6 * x - 1.3 * y + 0.2;
    const soup = shearedGrid(m, f);
    const { old, pointOn } = subdivideOnce(soup);
    let edges = 0;
    for (const [a, b] of Adjacency.of(soup).edges()) {
      const stencil = gridStencil(m, a, b);
      if (stencil?.rule !== 'interior–crease') continue;
      edges++;
      const middle = xy((a % m + (b % m)) / 2, (Math.floor(a / m) + Math.floor(b / m)) / 2);
      const expected = [...middle, f(middle[0], middle[1])];
      expectClose(pointOn(a, b), expected, `edge v${a}–v${b}`);
      // the mirrored stencil puts the point elsewhere in the parameter plane, and off the field's value there
      const mirrored = combine(old, stencil.swapped!);
      expect(Math.hypot(mirrored[0] - middle[0], mirrored[1] - middle[1]), `edge v${a}–v${b}`).toBeGreaterThan(0.005);
      expect(Math.abs(mirrored[2] - expected[2]), `edge v${a}–v${b}`).toBeGreaterThan(0.005);
    }
    expect(edges).toBe(2 * 4 * (m - 2) - 4);
  });
});

// ---------------------------------------------------------------------------------------------
// Rule 4, the extraordinary crease

/**
 * A fan of k triangles around vertex 0, its rim 1 … k + 1 on the unit half circle at angles jθ,
 * θ = π/k (rule 4's own parameter picture), and a triangle outside every other rim edge, so that
 * each rim vertex between the ends has 4 neighbours: a regular boundary vertex, beside which the
 * centre's edges take rule 4 alone.
 */
function fanWithRegularRim(k: number, height?: (x: number, y: number) => number): PolygonSoup {
  const t = Math.PI / k;
  const positions = [0, 0, 0];
  for (let j = 0; j <= k; j++) positions.push(Math.cos(j * t), Math.sin(j * t), 0);
  const faces: number[][] = [];
  for (let j = 0; j < k; j++) faces.push([0, 1 + j, 2 + j]);
  for (let j = 0; j < k; j += 2) {
    faces.push([2 + j, 1 + j, positions.length / 3]);
    positions.push(1.6 * Math.cos((j + 0.5) * t), 1.6 * Math.sin((j + 0.5) * t), 0);
  }
  return withHeights(soupFromArrays(positions, faces), height);
}

describe('Butterfly at a boundary vertex that is not regular (rule 4)', () => {
  it('has weights that sum to 1 and reproduce linear functions, for k = 2 … 7', () => {
    for (let k = 2; k <= 7; k++) {
      const t = Math.PI / k;
      const weights = creaseWeights(k);
      for (let i = 1; i < k; i++) {
        const self = creaseWeight(weights, i, -1);
        const ring = Array.from({ length: k + 1 }, (_, j) => creaseWeight(weights, i, j));
        const reference = creaseReference(k, i);
        expect(self, `k = ${k}, i = ${i}`).toBeCloseTo(reference.self, 14);
        ring.forEach((w, j) => expect(w, `k = ${k}, i = ${i}, j = ${j}`).toBeCloseTo(reference.ring[j], 14));
        expect(self + ring.reduce((s, w) => s + w, 0), `k = ${k}, i = ${i}`).toBeCloseTo(1, 14);
        // on the neighbours at angles jθ (v at the origin), the point at the edge's middle: ½(cos iθ, sin iθ)
        const x = ring.reduce((s, w, j) => s + w * Math.cos(j * t), 0);
        const y = ring.reduce((s, w, j) => s + w * Math.sin(j * t), 0);
        expectClose([x, y], [Math.cos(i * t) / 2, Math.sin(i * t) / 2], `k = ${k}, i = ${i}`, 13);
      }
    }
  });

  it.each([2, 4, 5, 6, 7])('k = %i beside regular boundary vertices: rule 4 alone, linear heights reproduced', (k) => {
    const f = (x: number, y: number) => 0.4 * x - 0.9 * y + 1.5;
    const soup = fanWithRegularRim(k, f);
    const adjacency = Adjacency.of(soup);
    expect(adjacency.valence(0)).toBe(k + 1);
    for (let i = 1; i < k; i++) expect([adjacency.onBoundary(1 + i), adjacency.valence(1 + i)]).toEqual([true, 4]);
    const { mesh, old, pointOn } = subdivideOnce(soup);
    // every new point on the plane …
    for (let v = old.length / 3; v < mesh.nVertices; v++) {
      const [x, y, z] = Array.from(mesh.positions.subarray(3 * v, 3 * v + 3));
      expect(z, `v${v}`).toBeCloseTo(f(x, y), 12);
    }
    // … and the centre's at the middle of its edge in the parameter picture
    const t = Math.PI / k;
    for (let i = 1; i < k; i++) {
      const middle = [Math.cos(i * t) / 2, Math.sin(i * t) / 2];
      expectClose(pointOn(0, 1 + i), [...middle, f(middle[0], middle[1])], `k = ${k}, edge to neighbour ${i}`);
    }
  });

  it.each([2, 4, 5, 6, 7])('k = %i, random heights: each new vertex at the reference stencil', (k) => {
    expect(expectReference(fanWithRegularRim(k))).toContain('extraordinary boundary alone beside regular boundary');
  });

  it('averages two extraordinary boundary ends: a fan whose rim vertices have 3 neighbours', () => {
    for (const k of [2, 5, 8]) expect(expectReference(withHeights(fan(k)))).toContain('mean of extraordinary boundary and extraordinary boundary');
  });
});

// ---------------------------------------------------------------------------------------------
// Mixed ends, small boundaries, and closed meshes

/** `shearedGrid(m)` with the diagonal of the square at (i, j) turned the other way. */
function flippedGrid(m: number, i: number, j: number): PolygonSoup {
  const soup = shearedGrid(m);
  const v = j * m + i;
  const turned = new Map([
    [`${[v, v + 1, v + m + 1]}`, [v, v + 1, v + m]],
    [`${[v, v + m + 1, v + m]}`, [v + 1, v + m + 1, v + m]],
  ]);
  const faces = faceLists(soup).map((f) => turned.get(`${f}`) ?? f);
  return soupFromArrays(soup.positions, faces);
}

describe('Butterfly next to the boundary: mixed ends and small boundaries', () => {
  it('an extraordinary interior vertex beside a regular boundary one: its own stencil alone', () => {
    const soup = flippedGrid(6, 2, 1); // vertices (2, 1) and (3, 2) get 5 neighbours, (3, 1) and (2, 2) get 7
    const rules = expectReference(soup);
    expect(rules).toContain('extraordinary interior alone beside regular boundary');
  });

  it('an extraordinary boundary vertex beside an extraordinary interior one: the mean of their stencils', () => {
    const soup = flippedGrid(6, 2, 0); // (3, 0) gets 5 neighbours, (2, 0) 3, (3, 1) 5, (2, 1) 7
    const rules = expectReference(soup);
    expect(rules).toContain('mean of extraordinary boundary and extraordinary interior');
    expect(rules).toContain('extraordinary boundary alone beside regular interior');
  });

  it('a strip, every vertex on the boundary: the midpoint between regular ones without a corner', () => {
    const rules = expectReference(withHeights(strip(6)));
    expect([...rules].sort()).toEqual([
      'extraordinary boundary alone beside regular boundary', // at the ends, the vertices of 3 neighbours
      'four-point',
      'midpoint',
    ]);
  });

  it('a disk: every case its rim and centre make', () => {
    expectReference(withHeights(disk(3)));
  });

  it('a boundary of three vertices: a′ and b′ are the same vertex', () => {
    const { old, pointOn } = subdivideOnce(withHeights(singleTriangle()));
    for (const [a, b, c] of [[0, 1, 2], [1, 2, 0], [2, 0, 1]]) {
      expectClose(pointOn(a, b), combine(old, [[a, 9 / 16], [b, 9 / 16], [c, -1 / 8]]));
    }
    // a tetrahedron without its base: a rim of three vertices of 3 neighbours round a vertex of valence 3
    const open = soupFromArrays(tetrahedron().positions, faceLists(tetrahedron()).slice(1));
    expectReference(withHeights(open));
  });

  it('keeps weights that sum to 1 everywhere: a moved mesh subdivides to the moved result', () => {
    const soups = [shearedGrid(6), flippedGrid(6, 2, 0), flippedGrid(6, 2, 1), fanWithRegularRim(5)];
    soups.push(...[fan(4), strip(4), disk(2), singleTriangle()].map((soup) => withHeights(soup)));
    for (const soup of soups) {
      const shift = [3.5, -2, 7.25];
      const moved = soupFromArrays(Array.from(soup.positions, (x, i) => x + shift[i % 3]), faceLists(soup));
      const first = subdivideOnce(soup).mesh;
      const second = subdivideOnce(moved).mesh;
      for (let i = 0; i < 3 * first.nVertices; i++) expect(second.positions[i] - shift[i % 3]).toBeCloseTo(first.positions[i], 12);
    }
  });
});

/** A regular icosahedron: every vertex of valence 5. */
function icosahedron(): PolygonSoup {
  const t = (1 + Math.sqrt(5)) / 2;
  const positions = [-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1];
  const faces = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
  ];
  return soupFromArrays(positions, faces);
}

/** A regular octahedron: every vertex of valence 4. */
function octahedron(): PolygonSoup {
  const positions = [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1];
  const faces = [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]];
  return soupFromArrays(positions, faces);
}

describe('Butterfly on closed meshes: the interior rules, unchanged', () => {
  it.each([
    ['an icosahedron (valence 5)', icosahedron()],
    ['an octahedron (valence 4)', octahedron()],
    ['a tetrahedron (valence 3)', tetrahedron()],
    ['a triangulated cube (valences 3 to 6)', triangulate(cube())],
    ['a sphere with poles of valence 7', uvSphere(5, 7)],
  ])('%s: every new vertex at the interior stencil', (_, soup) => {
    const rules = expectReference(soup);
    for (const rule of rules) expect(rule).not.toMatch(/boundary|crease|four-point/);
  });

  it('gives the positions it gave before the boundary rules changed (hashes taken then)', () => {
    const positionsHash = (soup: PolygonSoup, levels: number) => {
      const mesh = buildMesh(soup).mesh;
      for (let level = 0; level < levels; level++) runOperation(butterflySubdivision(mesh));
      const p = mesh.positions.subarray(0, 3 * mesh.vertexSlots);
      return createHash('sha256').update(new Uint8Array(p.buffer, p.byteOffset, p.byteLength)).digest('hex').slice(0, 16);
    };
    expect(positionsHash(icosahedron(), 3)).toBe('af406ff43cff9956');
    expect(positionsHash(triangulate(cube()), 2)).toBe('5942487d8be11967');
    expect(positionsHash(uvSphere(6, 8), 2)).toBe('1bd51ea71d39a133');
  });
});
