/**
 * Steppable operations. Every operation that changes a mesh (subdivision, the plane cut,
 * smoothing, decimation) is a generator that edits the mesh in place and yields a `Phase` after
 * each stage, with the mesh valid at every yield. The same code runs straight through for the
 * library and the CLI (`runOperation`) or one phase at a time for the app.
 *
 * @example
 *   for (const phase of loopSubdivision(mesh)) console.log(phase.name, validate(mesh).length);
 *   runOperation(loopSubdivision(mesh)); // or all at once
 */

/** Ids of elements, by kind. */
export interface ElementIds {
  vertices?: Int32Array;
  edges?: Int32Array;
  faces?: Int32Array;
  halfedges?: Int32Array;
}

export interface Phase {
  /** A short name: "split every edge". */
  name: string;
  /** Two sentences for a student: what this stage does, and why. */
  explanation: string;
  /** Elements this phase added (ids in the mesh as it is after the phase). */
  created?: ElementIds;
  /** Vertices whose position this phase changed. */
  moved?: ElementIds;
  /** Existing elements whose pointers this phase wrote (every one it changed; `phaseDiff` compares only these, with the created and removed). */
  rewired?: ElementIds;
  /** Elements this phase deleted (ids before compaction; gone afterwards). */
  removed?: ElementIds;
  /** Per-element values worth a colour map (e.g. the quadric error of each vertex). */
  values?: { vertices?: Float32Array; faces?: Float32Array; edges?: Float32Array };
}

/** A stepped operation: yields a phase after each stage; returns when the operation is done. */
export type Operation = Generator<Phase, void, void>;

/** Runs an operation to the end and returns its phases. */
export function runOperation(operation: Operation): Phase[] {
  const phases: Phase[] = [];
  for (const phase of operation) phases.push(phase);
  return phases;
}

/** `[start, start + 1, …, end - 1]` as ids: what a phase that appends elements created. */
export function idRange(start: number, end: number): Int32Array {
  const ids = new Int32Array(Math.max(0, end - start));
  for (let i = 0; i < ids.length; i++) ids[i] = start + i;
  return ids;
}

/** The ids of both lists, each once (the first list's order first): a phase's own list with what its writer saw. */
export function unionIds(a: ElementIds, b: ElementIds = {}): ElementIds {
  const union: ElementIds = {};
  for (const kind of ['vertices', 'edges', 'faces', 'halfedges'] as const) {
    if (a[kind] || b[kind]) union[kind] = Int32Array.from(new Set([...(a[kind] ?? []), ...(b[kind] ?? [])]));
  }
  return union;
}
