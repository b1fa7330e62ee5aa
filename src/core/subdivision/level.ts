/**
 * One level of a subdivision scheme, run from the scheme's description. A scheme file says what a
 * textbook says, as data and plain functions: how many elements a level makes, where the new
 * points go (its stencils, read from the old mesh), and its phases, each either a topology step
 * or the storing of points it shows moving. This module does the rest, the same for every scheme:
 *
 * 1. ready the mesh (`startLevel`) and reserve the memory of the level from its counts;
 * 2. hand the topology steps to a helper thread, run straight through when there is one
 *    (`helper-thread.ts`): it rewires the new arrays while this thread works out the stencils;
 * 3. work out every stencil from the old mesh, while its one-rings are intact;
 * 4. run the phases in order: a topology step (here, unless the helper did them all), or the
 *    storing of the points a phase moves. Stepped, each phase records what it changed: a
 *    topology step rewires the whole mesh (`ChangeRecorder.wholeMesh`), a move writes a range of
 *    positions (`valueRange`).
 *
 * Where the new points wait until their phase: face points, and edge points that no phase of their
 * own moves (Catmull-Clark's), are written where they end before any topology, so the phase that
 * creates them shows them in place. Edge points that a phase moves (Loop's, Butterfly's) are first
 * shown where the topology puts them: stepping, they wait in scratch arrays; straight through, no
 * one looks in between, so they are written where they end at once, which saves a level of a
 * million faces tens of megabytes of fresh memory. The old vertices' new places always wait in
 * scratch: the other stencils read the old ones.
 *
 * √3 is not described this way: its phases depend on the level's parity and the boundary, and its
 * steps pass what they found on to the next (`sqrt3.ts`).
 */
import type { HalfedgeMesh, MeshCapacity } from '../mesh.js';
import type { Memory } from '../memory.js';
import type { Operation } from '../change/operation.js';
import { growForLevel, handOver } from './helper-thread.js';
import { compactAtOnce, requireApplicable, startLevel, type SubdivisionScheme } from './preconditions.js';
import { blendedAttributes, storeValues } from './stencil.js';
import { ChangeRecorder } from '../change/recorder.js';

/**
 * One of a level's topology steps, as its phase runs it: `recording` when the level is stepped
 * (its phases shown one by one), `oldVertices` the vertex count when the level began. A step that two threads can share says how (`share`), and is given their shared
 * state (`work`) on the helper.
 */
export interface TopologyStep {
  (mesh: HalfedgeMesh, recording: boolean, oldVertices: number, work?: Int32Array): void;
  share?: SharedStep;
}

/** How the calling thread joins the helper in a step (see `shared-fan.ts`). */
export interface SharedStep {
  /** The state both threads share, in the helper's memory, made here before the helper begins. */
  work(mesh: HalfedgeMesh, memory: Memory): Int32Array;
  /** This thread's part, once its stencils are done. */
  join(mesh: HalfedgeMesh, oldVertices: number, work: Int32Array): void;
}

/**
 * A stencil for new points: reads the old mesh and the values `x` (three per vertex; face points
 * already placed, for edge points) and writes the point of the i-th face or edge to `out` as the
 * values of vertex `first + i`. `out` is `x` itself or a scratch array.
 */
export type PointStencil = (old: HalfedgeMesh, x: ArrayLike<number>, out: Float64Array | Float32Array, first: number) => void;

/** A stencil for the old vertices: their new values, three per vertex, from the old mesh. */
export type VertexStencil = (old: HalfedgeMesh, x: ArrayLike<number>) => Float64Array;

/** A phase: its name and explanation for a student, and what it does. */
export type LevelPhase = { name: string; explanation: string } & (
  | { topology: TopologyStep }
  | { moves: 'edge points' | 'old vertices' }
);

/**
 * A scheme's level. The stencils read the mesh as it was when the level began: its counts are the
 * old V, E and F. New vertices are numbered face points first (V + f), then edge points (V + F + e,
 * or V + e without face points), as the topology steps create them.
 */
export interface SchemeLevel {
  scheme: SubdivisionScheme;
  /** The element counts after the level (at most), to reserve memory for once. */
  counts(V: number, E: number, F: number): MeshCapacity;
  facePoints?: PointStencil;
  edgePoints: PointStencil;
  vertexPoints?: VertexStencil;
  phases: readonly LevelPhase[];
}

/**
 * One level as a steppable operation that edits `mesh` in place (each phase with its record).
 * @throws TopologyError when the scheme does not apply (nothing is changed).
 */
export function levelOperation(mesh: HalfedgeMesh, level: SchemeLevel): Operation {
  requireApplicable(mesh, level.scheme);
  compactAtOnce(mesh);
  return levelPhases(mesh, level, true);
}

/** The phases of one level; `recording` false leaves the phases' records out (a run straight through). */
export function* levelPhases(mesh: HalfedgeMesh, level: SchemeLevel, recording: boolean): Operation {
  startLevel(mesh);
  const V = mesh.vertexSlots;
  const E = mesh.edgeSlots;
  const F = mesh.faceSlots;
  const firstEdgePoint = level.facePoints ? V + F : V;

  // reserve memory; straight through, a helper thread (when there is one) does the topology steps
  // in the new arrays while this one works out the new positions from the old ones
  const { helper, old } = growForLevel(mesh, recording, level.counts(V, E, F));
  const steps = level.phases.flatMap((phase) => ('topology' in phase ? [phase.topology] : []));
  const handed = handOver(helper, mesh, level.scheme, V, steps);

  // compute the new positions while the old one-rings are intact: face points, edge points (where
  // they end, unless they wait for a phase of their own while stepping), old vertices
  const attributes = blendedAttributes(mesh);
  if (level.facePoints) for (const a of attributes) level.facePoints(old, a.data, a.data, V);
  const edgePointsWait = recording && level.phases.some((phase) => 'moves' in phase && phase.moves === 'edge points');
  const edgePoints = edgePointsWait ? attributes.map(() => new Float64Array(3 * E)) : null;
  attributes.forEach((a, i) => level.edgePoints(old, a.data, edgePoints?.[i] ?? a.data, edgePoints ? 0 : firstEdgePoint));
  const vertexPoints = level.vertexPoints ? attributes.map((a) => level.vertexPoints!(old, a.data)) : [];
  const step = handed.take(recording);

  // the phases, in order: change the topology, or store the points a phase moves
  let topologySteps = 0;
  for (const phase of level.phases) {
    const { name, explanation } = phase;
    const recorder = recording ? new ChangeRecorder(mesh) : null;
    if ('topology' in phase) {
      recorder?.wholeMesh();
      step(topologySteps++);
    } else if (phase.moves === 'edge points') {
      recorder?.valueRange('vertex', firstEdgePoint, firstEdgePoint + E);
      if (edgePoints) storeValues(attributes, edgePoints, firstEdgePoint);
    } else {
      recorder?.valueRange('vertex', 0, V);
      storeValues(attributes, vertexPoints, 0);
    }
    yield { name, explanation, ...(recorder ? { change: recorder.record() } : {}) };
  }
}
