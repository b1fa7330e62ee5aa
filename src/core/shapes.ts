/**
 * Small named shapes, as polygon soups: the fixtures of the tests, the sample models of the app
 * and the inputs of the benchmarks. Faces run counter-clockwise seen from outside.
 */
import { soupFromArrays, soupFromUniformFaces, type PolygonSoup } from './soup.js';

/** Regular tetrahedron: 4 vertices, 6 edges, 4 triangles, closed, genus 0. */
export function tetrahedron(): PolygonSoup {
  return soupFromArrays(
    [1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1],
    [
      [0, 1, 2],
      [0, 3, 1],
      [0, 2, 3],
      [1, 3, 2],
    ],
  );
}

/** Unit cube of 6 quads: 8 vertices, 12 edges, closed, genus 0. */
export function cube(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1],
    [
      [0, 3, 2, 1],
      [4, 5, 6, 7],
      [0, 1, 5, 4],
      [1, 2, 6, 5],
      [2, 3, 7, 6],
      [3, 0, 4, 7],
    ],
  );
}

/** One triangle in the plane z = 0. */
export function singleTriangle(): PolygonSoup {
  return soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [[0, 1, 2]]);
}

/** `n` triangles around a centre vertex, spanning `angle` radians (an open fan for angle < 2π). */
export function fan(n: number, angle = Math.PI): PolygonSoup {
  const positions = [0, 0, 0];
  for (let i = 0; i <= n; i++) positions.push(Math.cos((angle * i) / n), Math.sin((angle * i) / n), 0);
  const faces: number[][] = [];
  for (let i = 0; i < n; i++) faces.push([0, i + 1, i + 2]);
  return soupFromArrays(positions, faces);
}

/** A strip of `n` squares, each split into two triangles, along x in the plane z = 0. */
export function strip(n: number): PolygonSoup {
  const positions: number[] = [];
  for (let i = 0; i <= n; i++) positions.push(i, 0, 0, i, 1, 0);
  const faces: number[][] = [];
  for (let i = 0; i < n; i++) {
    const a = 2 * i;
    faces.push([a, a + 2, a + 3], [a, a + 3, a + 1]);
  }
  return soupFromArrays(positions, faces);
}

/** A flat ring of `segments` quads between radii `inner` and `outer`: two boundary loops. */
export function annulus(segments: number, inner = 0.5, outer = 1): PolygonSoup {
  const positions: number[] = [];
  for (let i = 0; i < segments; i++) {
    const t = (2 * Math.PI * i) / segments;
    positions.push(inner * Math.cos(t), inner * Math.sin(t), 0, outer * Math.cos(t), outer * Math.sin(t), 0);
  }
  const faces: number[][] = [];
  for (let i = 0; i < segments; i++) {
    const j = (i + 1) % segments;
    faces.push([2 * i, 2 * i + 1, 2 * j + 1, 2 * j]);
  }
  return soupFromArrays(positions, faces);
}

/** A disk of triangles in z = 0: `rings` rings of 6·k triangles around the centre; one boundary loop. */
export function disk(rings: number, radius = 1): PolygonSoup {
  const positions = [0, 0, 0];
  const ringStart = [0];
  for (let r = 1; r <= rings; r++) {
    ringStart.push(positions.length / 3);
    for (let i = 0; i < 6 * r; i++) {
      const t = (2 * Math.PI * i) / (6 * r);
      positions.push(((radius * r) / rings) * Math.cos(t), ((radius * r) / rings) * Math.sin(t), 0);
    }
  }
  const faces: number[][] = [];
  for (let r = 1; r <= rings; r++) {
    // walk the outer ring (6r vertices) and the inner ring (6(r-1), or the centre) together
    const outer = (i: number) => ringStart[r] + (i % (6 * r));
    const inner = (i: number) => (r === 1 ? 0 : ringStart[r - 1] + (i % (6 * (r - 1))));
    const innerCount = 6 * (r - 1);
    let i = 0;
    let j = 0;
    while (i < 6 * r || j < innerCount) {
      // advance on whichever ring lags behind in angle
      const outerNext = (i + 1) / (6 * r);
      const innerNext = j < innerCount ? (j + 1) / innerCount : Infinity;
      if (i < 6 * r && outerNext <= innerNext) {
        faces.push([inner(j), outer(i), outer(i + 1)]);
        i++;
      } else {
        faces.push([inner(j), outer(i), inner(j + 1)]);
        j++;
      }
    }
  }
  return soupFromArrays(positions, faces);
}

/** A regular grid of `nx × ny` squares in z = 0, each split into two triangles (or kept as quads). */
export function grid(nx: number, ny: number, quads = false): PolygonSoup {
  const positions = new Float64Array(3 * (nx + 1) * (ny + 1));
  for (let j = 0; j <= ny; j++) {
    for (let i = 0; i <= nx; i++) positions.set([i / nx, j / ny, 0], 3 * (j * (nx + 1) + i));
  }
  const degree = quads ? 4 : 3;
  const perCell = quads ? 1 : 2;
  const faceIndices = new Uint32Array(nx * ny * perCell * degree);
  let k = 0;
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const a = j * (nx + 1) + i;
      const b = a + 1;
      const c = a + nx + 2;
      const d = a + nx + 1;
      if (quads) faceIndices.set([a, b, c, d], k);
      else faceIndices.set([a, b, c, a, c, d], k);
      k += perCell * degree;
    }
  }
  return soupFromUniformFaces(positions, faceIndices, degree);
}

/**
 * A torus of `nu × nv` quads (major radius R around z, minor radius r): closed, genus 1.
 * @example buildMesh(torus(1000, 1000)) // a million quads
 */
export function torus(nu: number, nv: number, R = 1, r = 0.35): PolygonSoup {
  const positions = new Float64Array(3 * nu * nv);
  for (let i = 0; i < nu; i++) {
    const u = (2 * Math.PI * i) / nu;
    for (let j = 0; j < nv; j++) {
      const v = (2 * Math.PI * j) / nv;
      const k = 3 * (i * nv + j);
      positions[k] = (R + r * Math.cos(v)) * Math.cos(u);
      positions[k + 1] = (R + r * Math.cos(v)) * Math.sin(u);
      positions[k + 2] = r * Math.sin(v);
    }
  }
  const faceIndices = new Uint32Array(4 * nu * nv);
  for (let i = 0; i < nu; i++) {
    const i1 = (i + 1) % nu;
    for (let j = 0; j < nv; j++) {
      const j1 = (j + 1) % nv;
      faceIndices.set([i * nv + j, i1 * nv + j, i1 * nv + j1, i * nv + j1], 4 * (i * nv + j));
    }
  }
  return soupFromUniformFaces(positions, faceIndices, 4);
}

/**
 * A latitude–longitude sphere of triangles: `stacks` bands from pole to pole, `slices` around;
 * `2 · slices · (stacks − 1)` triangles, closed, genus 0.
 * @example buildMesh(uvSphere(501, 1000)) // a million triangles
 */
export function uvSphere(stacks: number, slices: number): PolygonSoup {
  const ringCount = stacks - 1;
  const positions = new Float64Array(3 * (ringCount * slices + 2));
  const south = ringCount * slices;
  const north = south + 1;
  for (let i = 0; i < ringCount; i++) {
    const phi = (Math.PI * (i + 1)) / stacks - Math.PI / 2;
    for (let j = 0; j < slices; j++) {
      const theta = (2 * Math.PI * j) / slices;
      positions.set([Math.cos(phi) * Math.cos(theta), Math.cos(phi) * Math.sin(theta), Math.sin(phi)], 3 * (i * slices + j));
    }
  }
  positions.set([0, 0, -1, 0, 0, 1], 3 * south);
  const faceIndices = new Uint32Array(3 * 2 * slices * (stacks - 1));
  let k = 0;
  for (let j = 0; j < slices; j++) {
    const j1 = (j + 1) % slices;
    faceIndices.set([south, j1, j], k);
    k += 3;
    for (let i = 0; i + 1 < ringCount; i++) {
      const a = i * slices + j;
      const b = i * slices + j1;
      faceIndices.set([a, b, b + slices, a, b + slices, a + slices], k);
      k += 6;
    }
    faceIndices.set([(ringCount - 1) * slices + j, (ringCount - 1) * slices + j1, north], k);
    k += 3;
  }
  return soupFromUniformFaces(positions, faceIndices, 3);
}

/**
 * The surface of a set of unit cubes (voxels), as quads on the lattice. Voxels are `[x, y, z]`
 * cells; the result is closed, and manifold when no two voxels touch along only an edge or a corner.
 * @example voxelSurface(doubleTorusVoxels) // genus 2
 */
export function voxelSurface(voxels: ReadonlyArray<readonly [number, number, number]>): PolygonSoup {
  const filled = new Set(voxels.map((v) => v.join(',')));
  const vertexIds = new Map<string, number>();
  const positions: number[] = [];
  const vertex = (x: number, y: number, z: number) => {
    const key = `${x},${y},${z}`;
    let id = vertexIds.get(key);
    if (id === undefined) {
      id = positions.length / 3;
      vertexIds.set(key, id);
      positions.push(x, y, z);
    }
    return id;
  };
  // corners of each cube side, counter-clockwise seen from outside (along the outward normal)
  const sides: Array<[number[], number[][]]> = [
    [[1, 0, 0], [[1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1]]],
    [[-1, 0, 0], [[0, 0, 0], [0, 0, 1], [0, 1, 1], [0, 1, 0]]],
    [[0, 1, 0], [[0, 1, 0], [0, 1, 1], [1, 1, 1], [1, 1, 0]]],
    [[0, -1, 0], [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]],
    [[0, 0, 1], [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]],
    [[0, 0, -1], [[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0]]],
  ];
  const faces: number[][] = [];
  for (const [x, y, z] of voxels) {
    for (const [n, quad] of sides) {
      if (filled.has(`${x + n[0]},${y + n[1]},${z + n[2]}`)) continue;
      faces.push(quad.map(([dx, dy, dz]) => vertex(x + dx, y + dy, z + dz)));
    }
  }
  return soupFromArrays(positions, faces);
}

/** A 5 × 3 × 1 slab of voxels with two holes through it: a closed surface of genus 2. */
export function doubleTorus(): PolygonSoup {
  const voxels: Array<[number, number, number]> = [];
  for (let x = 0; x < 5; x++) {
    for (let y = 0; y < 3; y++) if (!(y === 1 && (x === 1 || x === 3))) voxels.push([x, y, 0]);
  }
  return voxelSurface(voxels);
}

/** A Möbius strip of `segments` quads: one boundary loop, non-orientable. */
export function moebiusStrip(segments: number, width = 0.4): PolygonSoup {
  const positions: number[] = [];
  for (let i = 0; i < segments; i++) {
    const t = (2 * Math.PI * i) / segments;
    for (const s of [-width, width]) {
      // the band's direction turns by half a turn on the way round
      const radial = 1 + s * Math.cos(t / 2);
      positions.push(radial * Math.cos(t), radial * Math.sin(t), s * Math.sin(t / 2));
    }
  }
  const faces: number[][] = [];
  for (let i = 0; i < segments; i++) {
    const a = 2 * i;
    const b = 2 * i + 1;
    // the last quad joins back with the two sides swapped: that is the twist
    const [c, d] = i + 1 < segments ? [2 * i + 2, 2 * i + 3] : [1, 0];
    faces.push([a, c, d, b]);
  }
  return soupFromArrays(positions, faces);
}

/** Two triangles that touch at one vertex only (a "bow tie"): a non-manifold vertex. */
export function bowTie(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, -0.5, 0, 1, 0.5, 0, -1, 0.5, 0, -1, -0.5, 0],
    [
      [0, 1, 2],
      [0, 3, 4],
    ],
  );
}

/** Three triangles on one edge (like pages of a book): a non-manifold edge. */
export function threeFacesOnAnEdge(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 0, 0, 1, 1, 0, 0, -0.5, 0.86, 0, -0.5, -0.86, 0],
    [
      [0, 2, 1],
      [0, 1, 3],
      [1, 0, 4],
    ],
  );
}

/** Two triangles sharing an edge, the second listed clockwise: their orientations disagree. */
export function inconsistentPair(): PolygonSoup {
  return soupFromArrays(
    [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0],
    [
      [0, 1, 2],
      [1, 2, 3],
    ],
  );
}
