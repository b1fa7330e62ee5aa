/**
 * Our side of one native comparison (see `native.ts`), in plain Node on the built library's Node
 * entry (what `import 'halfedge-lab'` gives a program in Node, a helper thread included):
 * `node --expose-gc native-child.mjs OP FILE ours|ours-one-thread|meshoptimizer` prints one JSON line,
 * `{ lib, ms, peakMB, inFaces, outFaces }`, and for decimation `distance`: how far the result
 * strays from the input (see `surface-distance.mjs`), measured after the peak memory is taken.
 * The timing policy is the native harnesses' (`bench_common.h`): the input prepared outside the
 * timed region, one warm-up, then the median of 5 runs (3 when the warm-up took over 3 s, 1 over
 * 30 s).
 */
import { readFileSync } from 'node:fs';
import { MeshoptSimplifier } from 'meshoptimizer';
import { buildMesh, cutMesh, decimate, readMesh, subdivide, useHelperThread } from '../dist/node/index.js';
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
};

const soupOf = () => readMesh(readFileSync(file)).soup;
let ms;
let inFaces;
let outFaces;
/** For decimation: the input's vertices, and the result's positions and triangles. */
let strayFrom;
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
  let copy = input;
  ms = timeLikeNatives(
    () => {
      // the natives' `m = in` lets the last run's result go before it copies: so does ours
      copy = input;
      globalThis.gc?.();
      copy = input.clone();
    },
    () => {
      operations[op](copy, inFaces);
      outFaces = copy.nFaces;
    },
  );
  if (op === 'decimate') strayFrom = { points: input.positions.subarray(0, 3 * input.vertexSlots), positions: copy.positions, indices: triangleIndices(copy) };
}
const peakMB = Math.round(process.resourceUsage().maxRSS / 1024);
const distance = strayFrom && distanceToSurface(strayFrom.points, strayFrom.positions, strayFrom.indices);
console.log(JSON.stringify({ lib, ms: Math.round(ms * 10) / 10, peakMB, inFaces, outFaces, ...(distance ? { distance } : {}) }));
