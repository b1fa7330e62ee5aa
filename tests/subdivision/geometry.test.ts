import { describe, expect, it } from 'vitest';
import { annulus, cube, disk, grid, type HalfedgeMesh, meshStats, type PolygonSoup, seededRandom, strip, tetrahedron, torus, uvSphere } from '../../src/index.js';
import { subdivide, type SubdivisionScheme } from '../../src/core/subdivision/index.js';
import { at, flower, meshOf, pyramid, stepLevel, triangulate } from './helpers.js';

const schemes: SubdivisionScheme[] = ['loop', 'catmull-clark', 'butterfly', 'sqrt3', 'linear'];
/** The schemes that take any polygons (the others need triangles). */
const anyPolygons = (scheme: SubdivisionScheme) => scheme === 'catmull-clark' || scheme === 'linear';

/** The halfedge from v to w (throws when they are not neighbours). */
function halfedgeBetween(mesh: HalfedgeMesh, v: number, w: number): number {
  let h = mesh.vHalfedge[v];
  for (let i = 0; i < 100; i++, h = mesh.hePrev[h] ^ 1) if (mesh.target(h) === w) return h;
  throw new Error(`v${v} and v${w} are not neighbours`);
}

/** Grid vertex (i, j) of `grid(n, n)`. */
const gridVertex = (n: number) => (i: number, j: number) => j * (n + 1) + i;

/** A weighted sum of vertex positions. */
function combination(mesh: HalfedgeMesh, terms: Array<[number, number]>): number[] {
  const sum = [0, 0, 0];
  for (const [v, w] of terms) at(mesh, v).forEach((x, k) => (sum[k] += w * x));
  return sum;
}

/** A bumpy grid: heights make the stencils' results depend on every weight. */
function bumpyGrid(n: number): HalfedgeMesh {
  const mesh = meshOf(grid(n, n));
  const next = seededRandom(7);
  for (let v = 0; v < mesh.vertexSlots; v++) mesh.positions[3 * v + 2] = next();
  return mesh;
}

function expectClose(actual: number[], expected: number[], digits = 12): void {
  expect(actual.length).toBe(expected.length);
  actual.forEach((x, k) => expect(x).toBeCloseTo(expected[k], digits));
}

describe('Loop subdivision places points by the box-spline stencils', () => {
  const n = 4;
  const g = gridVertex(n);

  it('moves a regular interior vertex to 10/16 of itself and 1/16 of each of its six neighbours', () => {
    const mesh = bumpyGrid(n);
    const v = g(2, 2);
    const ring = [g(3, 2), g(1, 2), g(2, 3), g(2, 1), g(3, 3), g(1, 1)];
    const expected = combination(mesh, [[v, 10 / 16], ...ring.map((w): [number, number] => [w, 1 / 16])]);
    subdivide(mesh, 'loop');
    expectClose(at(mesh, v), expected);
  });

  it('puts an interior edge point at 3/8 of its ends and 1/8 of the two corners facing it', () => {
    const mesh = bumpyGrid(n);
    const [a, b] = [g(2, 2), g(3, 2)];
    const expected = combination(mesh, [[a, 3 / 8], [b, 3 / 8], [g(3, 3), 1 / 8], [g(2, 1), 1 / 8]]);
    const edgePoint = mesh.vertexSlots + (halfedgeBetween(mesh, a, b) >> 1); // vertex V + e sits on edge e
    subdivide(mesh, 'loop');
    expectClose(at(mesh, edgePoint), expected);
  });

  it('treats the boundary as a cubic B-spline: midpoints, and 3/4 + 1/8 + 1/8 at vertices', () => {
    const mesh = bumpyGrid(n);
    const [v, left, right] = [g(2, 0), g(1, 0), g(3, 0)];
    const vertex = combination(mesh, [[v, 3 / 4], [left, 1 / 8], [right, 1 / 8]]);
    const midpoint = combination(mesh, [[v, 1 / 2], [right, 1 / 2]]);
    const edgePoint = mesh.vertexSlots + (halfedgeBetween(mesh, v, right) >> 1);
    const corner = at(mesh, g(n, 0)); // valence 2: stays
    subdivide(mesh, 'loop');
    expectClose(at(mesh, v), vertex);
    expectClose(at(mesh, edgePoint), midpoint);
    expect(at(mesh, g(n, 0))).toEqual(corner);
  });

  it('uses Loop’s β for other valences: a tetrahedron vertex (n = 3) moves to 7/16 of itself', () => {
    // β(3) = 3/16, and the three neighbours of a vertex of a centred regular tetrahedron sum to −v
    const mesh = meshOf(tetrahedron());
    const v = at(mesh, 0);
    subdivide(mesh, 'loop');
    expectClose(at(mesh, 0), v.map((x) => (1 - 3 * (3 / 16)) * x - (3 / 16) * x));
  });
});

describe('Catmull-Clark subdivision of the cube with corners (±1, ±1, ±1)', () => {
  const mesh = meshOf(cube());
  mesh.positions.forEach((x, i) => (mesh.positions[i] = 2 * x - 1));
  const V = mesh.nVertices;
  const F = mesh.nFaces;
  subdivide(mesh, 'catmull-clark');
  const sorted = (p: number[]) => p.map(Math.abs).sort();

  it('moves the corners to (±5/9, ±5/9, ±5/9)', () => {
    for (let v = 0; v < V; v++) expectClose(at(mesh, v).map(Math.abs), [5 / 9, 5 / 9, 5 / 9], 14);
  });

  it('puts the face points at the face centres (±1, 0, 0) …', () => {
    for (let f = 0; f < F; f++) expectClose(sorted(at(mesh, V + f)), [0, 0, 1], 14);
  });

  it('puts the edge points at (±3/4, ±3/4, 0) and the like', () => {
    for (let v = V + F; v < mesh.nVertices; v++) expectClose(sorted(at(mesh, v)), [0, 3 / 4, 3 / 4], 14);
  });
});

describe('Modified Butterfly subdivision', () => {
  it('keeps every old vertex where it was, level after level (it interpolates)', () => {
    for (const soup of [uvSphere(6, 8), disk(3), triangulate(torus(6, 5))]) {
      const mesh = meshOf(soup);
      const old = mesh.positions.slice(0, 3 * mesh.nVertices);
      subdivide(mesh, 'butterfly', 3);
      expect(mesh.positions.subarray(0, old.length)).toEqual(old);
    }
  });

  it('uses the ten-point stencil between two vertices of valence 6', () => {
    const n = 5;
    const g = gridVertex(n);
    const mesh = bumpyGrid(n);
    const [a, b] = [g(2, 2), g(3, 2)];
    const expected = combination(mesh, [
      [a, 1 / 2],
      [b, 1 / 2],
      [g(3, 3), 1 / 8], // the corners facing the edge
      [g(2, 1), 1 / 8],
      [g(4, 3), -1 / 16], // the wings, across the triangles' other sides
      [g(2, 3), -1 / 16],
      [g(1, 1), -1 / 16],
      [g(3, 1), -1 / 16],
    ]);
    const edgePoint = mesh.vertexSlots + (halfedgeBetween(mesh, a, b) >> 1);
    subdivide(mesh, 'butterfly');
    expectClose(at(mesh, edgePoint), expected);
  });

  it('averages the valence-3 stencils (5/12, −1/12, −1/12) at both ends of a tetrahedron edge', () => {
    // (7/12)(a + b) − (1/12)(c + d), and c + d = −(a + b) on a centred regular tetrahedron
    const mesh = meshOf(tetrahedron());
    const expected = combination(mesh, [[0, 2 / 3], [1, 2 / 3]]);
    const edgePoint = mesh.vertexSlots + (halfedgeBetween(mesh, 0, 1) >> 1);
    subdivide(mesh, 'butterfly');
    expectClose(at(mesh, edgePoint), expected);
  });

  it('refines the boundary by the four-point rule (−1, 9, 9, −1)/16', () => {
    const n = 4;
    const g = gridVertex(n);
    const mesh = bumpyGrid(n);
    const expected = combination(mesh, [[g(0, 0), -1 / 16], [g(1, 0), 9 / 16], [g(2, 0), 9 / 16], [g(3, 0), -1 / 16]]);
    const edgePoint = mesh.vertexSlots + (halfedgeBetween(mesh, g(1, 0), g(2, 0)) >> 1);
    subdivide(mesh, 'butterfly');
    expectClose(at(mesh, edgePoint), expected);
  });
});

describe('√3 subdivision', () => {
  it('relaxes a tetrahedron vertex by α₃ = 5/9 and puts face points at the centroids', () => {
    // (1 − α)v + α·(mean of the neighbours) = (4/9)v − (5/27)v = (7/27)v
    const mesh = meshOf(tetrahedron());
    const v = at(mesh, 0);
    const centroid = combination(mesh, [[0, 1 / 3], [1, 1 / 3], [2, 1 / 3]]); // face 0
    subdivide(mesh, 'sqrt3');
    expectClose(at(mesh, 0), v.map((x) => (7 / 27) * x));
    expectClose(at(mesh, 4), centroid);
  });

  it('keeps the boundary on even levels and smooths it by (4, 19, 4)/27 on odd ones', () => {
    const mesh = meshOf(strip(4));
    mesh.positions.forEach((_, i) => i % 3 === 2 && (mesh.positions[i] = Math.sin(i))); // bumps
    const boundary = [...mesh.vertices()].filter((v) => mesh.isBoundaryVertex(v));
    const kept = boundary.map((v) => at(mesh, v));
    stepLevel(mesh, 'sqrt3', 0);
    expect(boundary.map((v) => at(mesh, v))).toEqual(kept);
    const v = 4; // (2, 0), between 2 and 6 along the boundary
    const expected = combination(mesh, [[2, 4 / 27], [v, 19 / 27], [6, 4 / 27]]);
    stepLevel(mesh, 'sqrt3', 1);
    expectClose(at(mesh, v), expected);
  });
});

describe('every scheme', () => {
  const inputs = (scheme: SubdivisionScheme): PolygonSoup[] =>
    anyPolygons(scheme) ? [flower(), pyramid(), torus(5, 4), annulus(6)] : [uvSphere(5, 6), disk(2), triangulate(torus(5, 4))];

  it.each(schemes)('%s: commutes with an affine map', (scheme) => {
    const next = seededRandom(11);
    const matrix = Array.from({ length: 9 }, () => 2 * next() - 1);
    const shift = [next(), next(), next()].map((x) => 10 * x);
    const transform = (mesh: HalfedgeMesh) => {
      const p = mesh.positions;
      for (let v = 0; v < mesh.nVertices; v++) {
        const [x, y, z] = at(mesh, v);
        for (let k = 0; k < 3; k++) p[3 * v + k] = matrix[3 * k] * x + matrix[3 * k + 1] * y + matrix[3 * k + 2] * z + shift[k];
      }
    };
    for (const soup of inputs(scheme)) {
      const first = meshOf(soup);
      const second = first.clone();
      transform(first);
      subdivide(first, scheme, 2);
      subdivide(second, scheme, 2);
      transform(second);
      for (let i = 0; i < first.positions.length; i++) expect(first.positions[i]).toBeCloseTo(second.positions[i], 9);
    }
  });

  it.each(schemes)('%s: keeps a planar mesh in its plane', (scheme) => {
    const plane = (x: number, y: number) => 0.3 * x - 0.2 * y + 0.1;
    const soup = anyPolygons(scheme) ? grid(3, 3, true) : disk(3);
    const mesh = meshOf(soup);
    for (let v = 0; v < mesh.nVertices; v++) mesh.positions[3 * v + 2] = plane(...(at(mesh, v) as [number, number]));
    subdivide(mesh, scheme, 3);
    for (let v = 0; v < mesh.nVertices; v++) {
      const [x, y, z] = at(mesh, v);
      expect(z).toBeCloseTo(plane(x, y), 12);
    }
  });

  it.each(schemes)('%s: keeps an open disk a disk, its rim one loop near the circle', (scheme) => {
    const mesh = meshOf(disk(4)); // a 24-gon inscribed in the unit circle
    subdivide(mesh, scheme, 3);
    const stats = meshStats(mesh);
    expect([stats.boundaryLoops, stats.components, stats.genus]).toEqual([1, 1, 0]);
    const radii = [...mesh.vertices()].filter((v) => mesh.isBoundaryVertex(v)).map((v) => Math.hypot(...at(mesh, v)));
    expect(Math.min(...radii)).toBeGreaterThan(0.98);
    expect(Math.max(...radii)).toBeLessThan(1.001);
    // and it still covers about the disk's area, π: no hole, no shrinking
    expect(stats.surfaceArea).toBeGreaterThan(0.97 * Math.PI);
  });

  it.each(schemes)('%s: blends a colour of three floats with the same weights as positions', (scheme) => {
    const mesh = meshOf(anyPolygons(scheme) ? flower() : disk(2));
    const color = mesh.vertexAttributes.add('color', 'float32', 3);
    color.data.set(mesh.positions.subarray(0, 3 * mesh.nVertices));
    subdivide(mesh, scheme, 2);
    const data = mesh.vertexAttributes.get('color')!.data;
    for (let i = 0; i < 3 * mesh.nVertices; i++) expect(data[i]).toBeCloseTo(mesh.positions[i], 5);
  });

  it.each(schemes)('%s: copies labels to new vertices and face attributes to the faces cut from a face', (scheme) => {
    const mesh = meshOf(anyPolygons(scheme) ? flower() : disk(2));
    const V = mesh.nVertices;
    const F = mesh.nFaces;
    const label = mesh.vertexAttributes.add('label', 'int32', 1);
    for (let v = 0; v < V; v++) label.data[v] = 100 + v;
    const group = mesh.faceAttributes.add('group', 'int32', 1);
    for (let f = 0; f < F; f++) group.data[f] = f;
    mesh.halfedgeAttributes.add('uv', 'float32', 2);
    mesh.edgeAttributes.add('crease', 'float32', 1);
    subdivide(mesh, scheme);

    const labels = mesh.vertexAttributes.get('label')!.data;
    for (let v = 0; v < V; v++) expect(labels[v]).toBe(100 + v);
    for (let v = V; v < mesh.nVertices; v++) expect(labels[v]).toBeGreaterThanOrEqual(100);
    // every old face's value lives on in as many faces as the scheme cuts it into
    const groups = Array.from(mesh.faceAttributes.get('group')!.data.subarray(0, mesh.nFaces));
    const pieces = (f: number) => (scheme === 'loop' || scheme === 'butterfly' ? 4 : scheme === 'sqrt3' ? 3 : meshOf(flower()).faceDegree(f));
    for (let f = 0; f < F; f++) expect(groups.filter((g) => g === f)).toHaveLength(pieces(f));
    // the schemes define no values on new corners and edges
    expect([mesh.halfedgeAttributes.size, mesh.edgeAttributes.size]).toEqual([0, 0]);
  });
});
