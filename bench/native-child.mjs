/**
 * Our side of one native comparison (see `native.ts`), in plain Node on the built library's Node
 * entry (what `import 'halfedge-lab'` gives a program in Node, a helper thread included):
 * `node --expose-gc native-child.mjs OP FILE ours|ours-one-thread|meshoptimizer` prints one JSON line,
 * `{ lib, ms, peakMB, inFaces, outFaces }`, and for decimation `distance`: how far the result
 * strays from the input (see `surface-distance.mjs`), measured after the peak memory is taken.
 * Remeshing reads its target as CGAL's harness does, the input's mean edge length times
 * `REMESH_TARGET_FACTOR` (default 1), after quads are triangulated as CGAL's `triangulate_faces`
 * does (untimed), and reports `spread`: the output's edge lengths as CGAL's note gives them.
 * The timing policy is the native harnesses' (`bench_common.h`): the input prepared outside the
 * timed region, one warm-up, then the median of 5 runs (3 when the warm-up took over 3 s, 1 over
 * 30 s).
 */
import { readFileSync } from 'node:fs';
import { MeshoptSimplifier } from 'meshoptimizer';
import { buildMesh, cutMesh, decimate, meanEdgeLength, readMesh, remesh, soupFromArrays, subdivide, useHelperThread } from '../dist/node/index.js';
import { distanceToSurface, triangleIndices } from './surface-distance.mjs';

const [op, file, lib] = process.argv.slice(2);
if (lib === 'ours-one-thread') useHelperThread(null);

function timeLikeNatives(prepare, run) {
  const once = () => {
    prepare();
    globalThis.gc?.(); // the previous run's garbage is not this run's cost (the natives free theirs as they go)
    const start = performance.now();
    run();
    return performance.now() - start;
  };
  const warmup = once();
  const reps = warmup < 3000 ? 5 : warmup < 30000 ? 3 : 0;
  if (reps === 0) return warmup;
  const times = Array.from({ length: reps }, once).sort((a, b) => a - b);
  return times[reps >> 1];
}

/** Our call for each operation that changes a mesh, as the natives call theirs. */
const operations = {
  loop: (mesh) => subdivide(mesh, 'loop'),
  cc: (mesh) => subdivide(mesh, 'catmull-clark'),
  // plane z = 0, keep z < 0, capped: the natives' `clip_cap`
  clip_cap: (mesh) => cutMesh(mesh, [0, 0, 1, 0], { keep: 'below' }),
  decimate: (mesh, inFaces) => decimate(mesh, { targetFaces: Math.round(inFaces / 10) }),
  // CGAL's: the input's mean edge length times the factor, 3 iterations
  remesh: (mesh, _, target) => remesh(mesh, { targetEdgeLength: target, iterations: 3 }),
};

const remeshFactor = Number(process.env.REMESH_TARGET_FACTOR ?? 1);

/**
 * Each quad cut into two triangles as CGAL's `triangulate_faces` cuts it: along the diagonal whose
 * two triangles' (area-weighted) normals have the larger dot product; other faces are kept.
 */
function triangulateLikeCgal(soup) {
  const { positions: p, faceIndices, faceStarts } = soup;
  const faces = [];
  const sub = (a, b) => [p[3 * a] - p[3 * b], p[3 * a + 1] - p[3 * b + 1], p[3 * a + 2] - p[3 * b + 2]];
  const cross = (u, v) => [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const dot = (u, v) => u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  for (let f = 0; f + 1 < faceStarts.length; f++) {
    const corners = Array.from(faceIndices.subarray(faceStarts[f], faceStarts[f + 1]));
    if (corners.length !== 4) {
      faces.push(corners);
      continue;
    }
    const [p0, p1, p2, p3] = corners;
    const along13 = dot(cross(sub(p2, p1), sub(p3, p2)), cross(sub(p0, p3), sub(p1, p0)));
    const along02 = dot(cross(sub(p1, p0), sub(p1, p2)), cross(sub(p3, p2), sub(p3, p0)));
    if (along02 > along13) faces.push([p0, p1, p2], [p0, p2, p3]);
    else faces.push([p1, p2, p3], [p1, p3, p0]);
  }
  return soupFromArrays(p, faces);
}

/** The edge lengths of `mesh` as CGAL's note gives them: min, mean, max, and the share within 4/5 … 4/3 of the target. */
function edgeSpread(mesh, target) {
  const { heVertex, eDeleted } = mesh;
  const p = mesh.positions;
  let min = Infinity;
  let max = 0;
  let sum = 0;
  let count = 0;
  let within = 0;
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (eDeleted[e]) continue;
    const a = 3 * heVertex[2 * e];
    const b = 3 * heVertex[2 * e + 1];
    const length = Math.hypot(p[a] - p[b], p[a + 1] - p[b + 1], p[a + 2] - p[b + 2]);
    min = Math.min(min, length);
    max = Math.max(max, length);
    sum += length;
    count++;
    if (length >= 0.8 * target && length <= (4 / 3) * target) within++;
  }
  const digits = (x) => +x.toPrecision(3);
  return { target: +target.toPrecision(6), edges: count, min: digits(min), mean: digits(sum / count), max: digits(max), within: +(within / count).toFixed(4) };
}

const soupOf = () => {
  const soup = readMesh(readFileSync(file)).soup;
  return op === 'remesh' ? triangulateLikeCgal(soup) : soup;
};
let ms;
let inFaces;
let outFaces;
/** For decimation: the input's vertices, and the result's positions and triangles. */
let strayFrom;
/** For remeshing: the result's edge lengths (`edgeSpread`). */
let spread;
if (op === 'read') {
  // reading the file is part of it, as for the natives
  ms = timeLikeNatives(() => {}, () => (outFaces = buildMesh(readMesh(readFileSync(file)).soup).mesh.nFaces));
  inFaces = outFaces;
} else if (op === 'build') {
  const soup = soupOf();
  ms = timeLikeNatives(() => {}, () => (outFaces = buildMesh(soup).mesh.nFaces));
  inFaces = outFaces;
} else if (lib === 'meshoptimizer') {
  await MeshoptSimplifier.ready;
  const soup = soupOf();
  const indices = Uint32Array.from(soup.faceIndices);
  const positions = new Float32Array(soup.positions);
  inFaces = indices.length / 3;
  const target = 3 * Math.round(inFaces / 10);
  let result;
  ms = timeLikeNatives(() => {}, () => (outFaces = (result = MeshoptSimplifier.simplify(indices, positions, 3, target, 1)[0]).length / 3));
  strayFrom = { points: soup.positions, positions, indices: result };
} else {
  const input = buildMesh(soupOf()).mesh;
  inFaces = input.nFaces;
  const target = op === 'remesh' ? remeshFactor * meanEdgeLength(input) : undefined;
  let copy = input;
  ms = timeLikeNatives(
    () => {
      // the natives' `m = in` lets the last run's result go before it copies: so does ours
      copy = input;
      globalThis.gc?.();
      copy = input.clone();
    },
    () => {
      operations[op](copy, inFaces, target);
      outFaces = copy.nFaces;
    },
  );
  if (op === 'remesh') spread = edgeSpread(copy, target);
  if (op === 'decimate') strayFrom = { points: input.positions.subarray(0, 3 * input.vertexSlots), positions: copy.positions, indices: triangleIndices(copy) };
}
const peakMB = Math.round(process.resourceUsage().maxRSS / 1024);
const distance = strayFrom && distanceToSurface(strayFrom.points, strayFrom.positions, strayFrom.indices);
console.log(JSON.stringify({ lib, ms: Math.round(ms * 10) / 10, peakMB, inFaces, outFaces, ...(distance ? { distance } : {}), ...(spread ? { spread } : {}) }));
