/**
 * A second thread for a level run straight through. A level's work is of two kinds that read the
 * old mesh and write different arrays: the topology steps rewire the pointers, the stencils work
 * out the new positions. Given a helper thread, a level grows the mesh into shared memory (it grows
 * every array anyway), hands the steps to the helper, and works out the stencils from the old
 * arrays meanwhile (`HalfedgeMesh.view`). While both threads run, neither reads memory fresh from
 * the system before writing it (arrays to add into come from `zeros`, see `memory.ts`): such reads
 * slow both threads, and the stencils ran at a quarter of their speed.
 *
 * The core runs anywhere and starts no thread itself: an environment that can installs a helper
 * with `useHelperThread` (the library's Node entry does, see `src/node/helper-thread.ts`). Without
 * one, for a level stepped phase by phase, or for a mesh too small to gain, everything runs on the
 * calling thread, as it also does when the helper has not begun by the time the stencils are done.
 */
import { attributeSetOf, elementKinds, meshArrays, type SlotCounts } from '../mesh-arrays.js';
import type { HalfedgeMesh, MeshCapacity } from '../mesh.js';
import { isShared, type Memory } from '../memory.js';
import { type SerializedMesh, shareMesh } from '../serialize.js';
import type { TopologyStep } from './level.js';
import type { SubdivisionScheme } from './preconditions.js';

/** A level's topology steps (those of its scheme's phases, see `topology-task.ts`), on the mesh's own arrays in shared memory. */
export interface TopologyTask {
  scheme: SubdivisionScheme;
  /** The vertex count when the level began. */
  oldVertices: number;
  mesh: SerializedMesh;
  /** The state of the step the calling thread joins in, when one is shared (`TopologyStep.share`). */
  work?: Int32Array;
}

export interface HelperThread {
  /** The fewest faces a level must start from to be worth a thread. */
  minFaces: number;
  /** Starts the helper for a task to come (a thread takes a while to begin). */
  start(): HelperRun;
}

export interface HelperRun {
  /** Memory the helper shares, for the arrays it rewires. */
  memory: Memory;
  /** Gives the helper its task. */
  post(task: TopologyTask): void;
  /**
   * Whether the helper has begun its task. If it has not (or has none), the task is called off
   * and the caller runs the steps.
   */
  begun(): boolean;
  /**
   * Waits for the task the helper began, and gives the slot counts it left.
   * @throws the helper's error when a step failed there.
   */
  join(): SlotCounts;
}

/** The steps a level handed over. */
export interface HandedSteps {
  /**
   * Once the stencils are done: when the helper has begun the steps, waits for them (joining it in
   * the step it shares, if any) and takes the slot counts they left, and each step then does
   * nothing; when it has not, they are called off, and each runs here.
   */
  take(recording: boolean): (i: number) => void;
}

let installed: HelperThread | null = null;

/** Installs the helper the levels use from now on, or none (null): every step on the calling thread. */
export function useHelperThread(helper: HelperThread | null): void {
  installed = helper;
}

/**
 * Grows the mesh for a level to `capacity`. Run straight through with a helper that takes a mesh
 * this size, the helper is started first (it takes a while to begin) and the mesh grows into its
 * memory. Returns the helper (or null) and the mesh the stencils read: with a helper, a view of the
 * old arrays, which the helper leaves alone; else the mesh itself (stepping, no view is kept, so
 * the old arrays can go while the phases wait).
 */
export function growForLevel(mesh: HalfedgeMesh, recording: boolean, capacity: MeshCapacity): { helper: HelperRun | null; old: HalfedgeMesh } {
  const helper = recording || installed === null || mesh.faceSlots < installed.minFaces ? null : installed.start();
  const old = helper === null ? mesh : mesh.view();
  mesh.reserve(capacity, helper?.memory);
  return { helper, old };
}

/**
 * Hands the level's topology steps to the helper, when every array they write is in its memory
 * (an array that already had room was not grown into it). A step the two threads share has its
 * state made now, in the helper's memory: only when the steps are handed over.
 */
export function handOver(
  run: HelperRun | null,
  mesh: HalfedgeMesh,
  scheme: SubdivisionScheme,
  oldVertices: number,
  steps: readonly TopologyStep[],
): HandedSteps {
  const shared = steps.find((step) => step.share !== undefined)?.share;
  let work: Int32Array | undefined;
  if (run !== null && sharesEveryArray(mesh)) {
    work = shared?.work(mesh, run.memory);
    run.post({ scheme, oldVertices, mesh: shareMesh(mesh), work });
  }
  return {
    take(recording) {
      const helped = run?.begun() ?? false;
      if (helped) {
        if (work !== undefined) shared!.join(mesh, oldVertices, work);
        const slots = run!.join();
        mesh.vertexSlots = slots.vertexSlots;
        mesh.edgeSlots = slots.edgeSlots;
        mesh.faceSlots = slots.faceSlots;
      }
      return (i) => {
        if (!helped) steps[i](mesh, recording, oldVertices);
      };
    },
  };
}

function sharesEveryArray(mesh: HalfedgeMesh): boolean {
  const attributes = elementKinds.flatMap((kind) => [...attributeSetOf(mesh, kind)].map((a) => a.data));
  return [...meshArrays.map(({ name }) => mesh[name]), ...attributes].every(isShared);
}
