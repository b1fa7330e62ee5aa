/**
 * Steppable operations. Every operation that changes a mesh (subdivision, the plane cut,
 * smoothing, decimation) is a generator that edits the mesh in place and yields a `Phase` after
 * each stage, with the mesh valid at every yield. The same code runs straight through for the
 * library and the CLI (`runOperation`) or one phase at a time for the app. Stepped, each phase
 * carries its change record, written as the phase wrote (`ChangeRecorder`): the app applies it to
 * its copy of the mesh, draws its pointer diff and marks what it created, moved and rewired
 * (`phaseElements`). Run straight through, the phases record nothing and pay nothing for it.
 *
 * @example
 *   for (const phase of loopSubdivision(mesh)) console.log(phase.name, validate(mesh).length);
 *   runOperation(loopSubdivision(mesh)); // or all at once
 */

import type { ChangeRecord } from './record.js';
import { type ElementKind, meshArrays, slotCount } from '../mesh-arrays.js';

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
  /** What the phase changed, when the operation is stepped (run straight through: none). */
  change?: ChangeRecord;
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

/** What a phase did, by element: what the app marks in the stepper's colours. */
export interface PhaseElements {
  /** Elements brought into use (ids after the phase). */
  created: ElementIds;
  /** Vertices whose position changed. */
  moved: ElementIds;
  /** Elements there before whose pointers changed, or that a changed pointer names before or after. */
  rewired: ElementIds;
  /** Elements deleted (not compacted: their slots are still there, marked deleted). */
  removed: ElementIds;
  /** How many vertices moved (`moved` may stop at the limit). */
  movedCount: number;
}

const CREATED = 1;
const REMOVED = 2;
const REWIRED = 4;
const MOVED = 8;

type Marks = Record<ElementKind, Uint8Array>;

/**
 * Marks what one write of a record did, among the elements there before (`slots` of each kind): a
 * flag deleted or brought back, a pointer's owner rewired, and the vertex or face it named before
 * and after too.
 */
function markWrite(marks: Marks, slots: Record<ElementKind, number>, array: number, id: number, old: number, now: number): void {
  const { owner, refers } = meshArrays[array];
  if (refers === null) {
    if (id >= slots[owner]) return;
    const bit = now ? REMOVED : CREATED;
    marks[owner][id] |= bit;
    // an edge's halfedges go and come back with it
    if (owner === 'edge') {
      marks.halfedge[2 * id] |= bit;
      marks.halfedge[2 * id + 1] |= bit;
    }
    return;
  }
  if (id < slots[owner]) marks[owner][id] |= REWIRED;
  if (refers === 'halfedge') return;
  if (old >= 0 && old < slots[refers]) marks[refers][old] |= REWIRED;
  if (now >= 0 && now < slots[refers]) marks[refers][now] |= REWIRED;
}

/**
 * What the phase whose record is `change` created, moved, rewired and removed, read off the record
 * (ids as after it): the first `limit` ids of each, in increasing order.
 */
export function phaseElements(change: ChangeRecord, limit = Infinity): PhaseElements {
  const { before, after } = change;
  const marks: Marks = {
    vertex: new Uint8Array(Math.max(before.vertexSlots, after.vertexSlots)),
    halfedge: new Uint8Array(2 * Math.max(before.edgeSlots, after.edgeSlots)),
    edge: new Uint8Array(Math.max(before.edgeSlots, after.edgeSlots)),
    face: new Uint8Array(Math.max(before.faceSlots, after.faceSlots)),
  };
  for (const kind of ['vertex', 'edge', 'face'] as const) marks[kind].fill(CREATED, slotCount(before, kind), slotCount(after, kind));
  const slots = { vertex: before.vertexSlots, halfedge: 2 * before.edgeSlots, edge: before.edgeSlots, face: before.faceSlots };
  const { array, index, old, new: now } = change.pointers;
  for (let i = 0; i < array.length; i++) markWrite(marks, slots, array[i], index[i], old[i], now[i]);
  for (const range of change.ranges) {
    // slots brought into use are created; what they name is marked through the old slots' own writes
    if (!range.old) continue;
    // a range may hold millions of fields: a plain loop over them
    for (let i = 0; i < range.new.length; i++) if (range.old[i] !== range.new[i]) markWrite(marks, slots, range.array, range.start + i, range.old[i], range.new[i]);
  }
  let movedCount = 0;
  for (const value of change.values) {
    if (value.kind !== 'vertex' || value.name !== 'position' || !value.old) continue;
    const count = value.new.length / 3;
    for (let i = 0; i < count; i++) {
      const v = value.index ? value.index[i] : value.start + i;
      const same = value.old[3 * i] === value.new[3 * i] && value.old[3 * i + 1] === value.new[3 * i + 1] && value.old[3 * i + 2] === value.new[3 * i + 2];
      if (same || v >= before.vertexSlots || marks.vertex[v] & MOVED) continue;
      marks.vertex[v] |= MOVED;
      movedCount++;
    }
  }
  // each category's first `limit` ids of each kind, in one pass over the kind's marks
  const categories = [
    { name: 'created', bit: CREATED, unless: REMOVED, kinds: ['vertex', 'edge', 'face'] },
    { name: 'moved', bit: MOVED, unless: CREATED | REMOVED, kinds: ['vertex'] },
    { name: 'rewired', bit: REWIRED, unless: CREATED | REMOVED, kinds: ['vertex', 'halfedge', 'face'] },
    { name: 'removed', bit: REMOVED, unless: 0, kinds: ['vertex', 'edge', 'face'] },
  ] as const;
  const names = { vertex: 'vertices', edge: 'edges', face: 'faces', halfedge: 'halfedges' } as const;
  const result = { created: {}, moved: {}, rewired: {}, removed: {}, movedCount } as PhaseElements;
  for (const kind of ['vertex', 'edge', 'face', 'halfedge'] as const) {
    const wanted = categories.filter((c) => (c.kinds as readonly string[]).includes(kind));
    const found = wanted.map((): number[] => []);
    const m = marks[kind];
    for (let id = 0; id < m.length; id++) {
      const mark = m[id];
      if (mark === 0) continue;
      let full = true;
      for (let c = 0; c < wanted.length; c++) {
        if (found[c].length < limit && mark & wanted[c].bit && !(mark & wanted[c].unless)) found[c].push(id);
        full &&= found[c].length >= limit;
      }
      if (full) break;
    }
    wanted.forEach((c, i) => {
      if (found[i].length) result[c.name][names[kind]] = Int32Array.from(found[i]);
    });
  }
  return result;
}
