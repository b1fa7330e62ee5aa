/**
 * Connecting the face points of every face (`fanFaces` on all faces) on two threads at once: the
 * faces go in chunks, and each thread takes the next chunk until none is left. Chunks write
 * disjoint slots, and each chunk's first spoke is counted before any is taken, so the mesh is the
 * one `fanFaces` makes on one thread, whichever thread takes which chunk.
 *
 * The calling thread counts each chunk's spokes from the faces as they are before their sides are
 * split (`sharedFanWork`); the helper thread (see `helper-thread.ts`) appends the slots once it
 * has split the edges (`prepareSharedFan`), and the calling thread joins in when its stencils are
 * done (`joinSharedFan`). Their shared state is one `Int32Array` in shared memory.
 */
import type { HalfedgeMesh } from '../mesh.js';
import type { Memory } from '../memory.js';
import { appendSlots, fanFaces, fanRange } from './topology.js';

/** Faces per chunk: a chunk takes a millisecond or two, so the threads finish close together. */
const CHUNK_BITS = 14;
const CHUNK = 1 << CHUNK_BITS;

// the shared state: [state, next chunk, chunks done, faces, first edge, first face, then each
// chunk's first spoke, and the spokes of all]
const STATE = 0;
const NEXT = 1;
const DONE = 2;
const FACES = 3;
const FIRST_EDGE = 4;
const FIRST_FACE = 5;
const SPOKES = 6;

const PREPARING = 0;
const READY = 1;
const FAILED = -1;

const chunksOf = (faces: number) => (faces + CHUNK - 1) >> CHUNK_BITS;

/** Faces whose sides were split in two: every other corner is joined to the face's point. */
const STRIDE = 2;

/**
 * Catmull-Clark's step that connects every face point (vertex `firstCentre + f`) to the edge
 * points around its face, after the split: `fanFaces` on one thread, or, given the state shared
 * with the calling thread, the helper's part.
 */
export function connectFacePoints(mesh: HalfedgeMesh, _recording: boolean, firstCentre: number, work?: Int32Array): void {
  if (work === undefined) fanFaces(mesh, 'all', firstCentre, STRIDE);
  else prepareSharedFan(mesh, firstCentre, work);
}
connectFacePoints.share = { work: sharedFanWork, join: joinSharedFan };

/**
 * The shared state for fanning the faces of `mesh`, in `memory`, with each chunk's first spoke
 * counted now, before the sides are split: a face of n corners is split into 2n sides and joined
 * to its point by n spokes. One pass over the halfedges, on this thread, whose code is warm, where
 * the helper, started afresh for each level, would run it cold.
 */
function sharedFanWork(mesh: HalfedgeMesh, memory: Memory): Int32Array {
  const faces = mesh.faceSlots;
  const chunks = chunksOf(faces);
  const work = new Int32Array(memory(4 * (SPOKES + chunks + 1)));
  work[FACES] = faces;
  const { heFace } = mesh;
  const halfedges = mesh.halfedgeSlots;
  for (let h = 0; h < halfedges; h++) {
    const f = heFace[h];
    if (f !== -1) work[SPOKES + (f >> CHUNK_BITS) + 1]++;
  }
  for (let c = 1; c <= chunks; c++) work[SPOKES + c] += work[SPOKES + c - 1];
  return work;
}

/**
 * The helper's part, once it has split the edges: appends the slots, lets the other thread in,
 * fans chunks, and waits until every chunk is done. Says FAILED if it throws, so the other thread
 * does not wait for it.
 */
function prepareSharedFan(mesh: HalfedgeMesh, firstCentre: number, work: Int32Array): void {
  try {
    const faces = work[FACES];
    const spokes = work[SPOKES + chunksOf(faces)];
    const first = appendSlots(mesh, 0, spokes, spokes - faces);
    work[FIRST_EDGE] = first.edge;
    work[FIRST_FACE] = first.face;
  } catch (error) {
    Atomics.store(work, STATE, FAILED);
    Atomics.notify(work, STATE);
    throw error;
  }
  Atomics.store(work, STATE, READY);
  Atomics.notify(work, STATE);
  fanChunks(mesh, firstCentre, work);
  const chunks = chunksOf(work[FACES]);
  for (let done = Atomics.load(work, DONE); done < chunks; done = Atomics.load(work, DONE)) Atomics.wait(work, DONE, done);
}

/**
 * The calling thread's part, once the helper has begun: waits until the slots are appended, then
 * fans chunks until none is left. False when the helper failed first (its error comes with `join`).
 */
function joinSharedFan(mesh: HalfedgeMesh, firstCentre: number, work: Int32Array): boolean {
  while (Atomics.load(work, STATE) === PREPARING) Atomics.wait(work, STATE, PREPARING);
  if (Atomics.load(work, STATE) === FAILED) return false;
  fanChunks(mesh, firstCentre, work);
  return true;
}

/** Fans the next chunk not yet taken, until none is left; counts each one done. */
function fanChunks(mesh: HalfedgeMesh, firstCentre: number, work: Int32Array): void {
  const faces = work[FACES];
  const chunks = chunksOf(faces);
  const first = { vertex: -1, edge: work[FIRST_EDGE], face: work[FIRST_FACE] };
  const faceAt = (i: number) => i;
  for (let c = Atomics.add(work, NEXT, 1); c < chunks; c = Atomics.add(work, NEXT, 1)) {
    const range = { faceAt, begin: c << CHUNK_BITS, end: Math.min(faces, (c + 1) << CHUNK_BITS), spoke: work[SPOKES + c] };
    fanRange(mesh, range, first, firstCentre, STRIDE);
    Atomics.add(work, DONE, 1);
    Atomics.notify(work, DONE);
  }
}
