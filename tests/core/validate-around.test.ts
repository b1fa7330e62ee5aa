/**
 * The local check against the whole one: after random edits (and their undos) both find nothing;
 * with a pointer the edit wrote set wrong, both find something, and every violation the local
 * check names is one `validate` names, in the same words.
 */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  applyChange,
  bowTie,
  buildMesh,
  canFlipEdge,
  type ChangeRecord,
  ChangeRecorder,
  flipEdge,
  grid,
  type HalfedgeMesh,
  invertChange,
  meshArrayIndex,
  meshArrays,
  positionsChange,
  soupFromArrays,
  splitEdgeTriangulated,
  touchedElements,
  type TouchedElements,
  validate,
  validateAround,
  type Violation,
} from '../../src/index.js';
import { edgeBetween, square } from '../edits/helpers.js';
import { editSequences, runEdits } from './edit-sequences.js';

const SEED = 20261126;

const ids = (list: Iterable<number>) => Int32Array.from(list);

describe('touchedElements', () => {
  it('lists what a flip rewired and what its old and new pointers name: both triangles, all four corners', () => {
    const mesh = buildMesh(square()).mesh;
    const diagonal = edgeBetween(mesh, 0, 2);
    const touched = touchedElements(flipEdge(mesh, diagonal).record!);
    const inFaces = [...mesh.halfedges()].filter((h) => mesh.heFace[h] !== -1);
    expect(touched).toEqual({ halfedges: ids(inFaces), vertices: ids([0, 1, 2, 3]), faces: ids([0, 1]) });
  });

  it('lists the slots a split brings into use, and the same for its undo', () => {
    const mesh = buildMesh(square()).mesh;
    const before = mesh.slotState;
    const record = splitEdgeTriangulated(mesh, edgeBetween(mesh, 0, 2)).record!;
    const touched = touchedElements(record);
    expect([...touched.vertices]).toContain(before.vertexSlots);
    for (let h = 2 * before.edgeSlots; h < mesh.halfedgeSlots; h++) expect([...touched.halfedges]).toContain(h);
    for (let f = before.faceSlots; f < mesh.faceSlots; f++) expect([...touched.faces]).toContain(f);
    expect(touchedElements(invertChange(record))).toEqual(touched);
  });

  it('lists nothing for a change that only moves vertices: no invariant reads a position', () => {
    const mesh = buildMesh(square()).mesh;
    const old = mesh.positions.slice(0, 3 * mesh.vertexSlots);
    mesh.positions[0] += 1;
    expect(touchedElements(positionsChange(mesh, old))).toEqual({ halfedges: ids([]), vertices: ids([]), faces: ids([]) });
  });
});

describe(`validateAround (seed ${SEED})`, () => {
  it('finds nothing after every edit of random sequences, nor after its undo, as validate finds nothing', () => {
    let edits = 0;
    fc.assert(
      fc.property(editSequences, (sequence) => {
        edits += runEdits(sequence, (mesh, record, step) => {
          const touched = touchedElements(record);
          expect(validate(mesh), step).toEqual([]);
          expect(validateAround(mesh, touched), step).toEqual([]);
          applyChange(mesh, record, 'backward');
          expect(validateAround(mesh, touched), `${step}, undone`).toEqual([]);
          applyChange(mesh, record, 'forward');
        });
      }),
      { seed: SEED, numRuns: 300 },
    );
    expect(edits).toBeGreaterThan(1000);
  });

  it('finds a fault when a pointer an edit wrote is set wrong, and names only faults validate names', () => {
    let broken = 0;
    const corruption = fc.record({ sequence: editSequences, entry: fc.nat(), value: fc.nat() });
    fc.assert(
      fc.property(corruption, ({ sequence, entry, value }) => {
        const end: { mesh?: HalfedgeMesh; record?: ChangeRecord } = {};
        runEdits(sequence, (mesh, record) => Object.assign(end, { mesh, record }));
        const { mesh, record } = end;
        if (!mesh || !record) return;
        const written = pointerWrites(record);
        if (written.length === 0) return;
        const i = written[entry % written.length];
        const { name, refers } = meshArrays[record.pointers.array[i]];
        const index = record.pointers.index[i];
        const live = liveIds(mesh, refers!).filter((id) => id !== mesh[name][index]);
        if (live.length === 0) return;
        mesh[name][index] = live[value % live.length];
        const whole = validate(mesh);
        const local = validateAround(mesh, touchedElements(record));
        if (whole.length > 0) broken++;
        expect(local.length > 0, `${name}[${index}] = ${mesh[name][index]}`).toBe(whole.length > 0);
        expect(whole).toEqual(expect.arrayContaining(local));
      }),
      { seed: SEED, numRuns: 400 },
    );
    expect(broken).toBeGreaterThan(200);
  });

  it('finds a fault when an edit leaves out one of its writes, as validate does, and names only faults validate names', () => {
    let broken = 0;
    fc.assert(
      fc.property(editSequences, fc.nat(), (sequence, entry) => {
        const end: { mesh?: HalfedgeMesh; record?: ChangeRecord } = {};
        runEdits(sequence, (mesh, record) => Object.assign(end, { mesh, record }));
        const { mesh, record } = end;
        if (!mesh || !record || record.pointers.array.length === 0) return;
        // the mesh as an edit that forgot write i would leave it, and the record such an edit would keep
        const i = entry % record.pointers.array.length;
        const { array, index, old } = record.pointers;
        mesh[meshArrays[array[i]].name][index[i]] = old[i];
        const kept = (list: Int32Array | Uint8Array) => list.filter((_, j) => j !== i);
        const partial = { ...record, pointers: { array: kept(array), index: kept(index), old: kept(old), new: kept(record.pointers.new) } };
        const whole = validate(mesh);
        const local = validateAround(mesh, touchedElements(partial as ChangeRecord));
        if (whole.length > 0) broken++;
        expect(byMessage(local), `${meshArrays[array[i]].name}[${index[i]}] left at ${old[i]}`).toEqual(byMessage(whole));
      }),
      { seed: SEED, numRuns: 400 },
    );
    expect(broken).toBeGreaterThan(200);
  });

  it.each([
    ['vertex', meshArrayIndex.vDeleted, meshArrayIndex.vHalfedge, (mesh: HalfedgeMesh) => mesh.deleteVertex(0)],
    ['face', meshArrayIndex.fDeleted, meshArrayIndex.fHalfedge, (mesh: HalfedgeMesh) => mesh.deleteFace(0)],
  ])('finds a %s deleted while live halfedges still name it', (_, flag, halfedge, remove) => {
    const mesh = buildMesh(square()).mesh;
    const recorder = new ChangeRecorder(mesh);
    recorder.field(flag, 0);
    recorder.field(halfedge, 0);
    remove(mesh);
    sameAsValidate(mesh, touchedElements(recorder.record()));
  });

  it('looks only around the change: a fault far from it is left to validate', () => {
    const mesh = buildMesh(grid(60, 40)).mesh;
    const first = [...mesh.edges()].find((e) => canFlipEdge(mesh, e) === null)!;
    const touched = touchedElements(flipEdge(mesh, first).record!);
    const far = mesh.halfedgeSlots - 2;
    mesh.heNext[far] = mesh.heNext[far - 2];
    expect(validate(mesh).length).toBeGreaterThan(0);
    expect(validateAround(mesh, touched)).toEqual([]);
  });

  it('counts every halfedge leaving a vertex with two fans, as validate does', () => {
    // the builder splits the bow tie's centre into v0 and v5; merge them back by hand
    const mesh = buildMesh(bowTie()).mesh;
    const moved = [...mesh.halfedges()].filter((h) => mesh.heVertex[h] === 5);
    for (const h of moved) mesh.heVertex[h] = 0;
    mesh.deleteVertex(5);
    const found = sameAsValidate(mesh, { halfedges: ids(moved), vertices: ids([0, 5]), faces: ids([]) });
    expect(found.map((v) => v.invariant)).toEqual(['vertex-fan']);
  });

  it('names two edges joining the same vertices from the lower one, as validate does, from either end', () => {
    // two separate triangles, the second's first two corners then relabelled as the first's
    const soup = soupFromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, -1, 0], [[0, 1, 2], [4, 3, 5]]);
    const mesh = buildMesh(soup).mesh;
    const moved = [...mesh.halfedges()].filter((h) => mesh.heVertex[h] === 3 || mesh.heVertex[h] === 4);
    for (const h of moved) mesh.heVertex[h] = mesh.heVertex[h] === 3 ? 0 : 1;
    mesh.deleteVertex(3);
    mesh.deleteVertex(4);
    // touched: the relabelled halfedges only (v1 is the higher end: the pair is still named at v0)
    const found = sameAsValidate(mesh, { halfedges: ids(moved.filter((h) => mesh.heVertex[h] === 1)), vertices: ids([]), faces: ids([]) });
    expect(found.map((v) => v.invariant)).toContain('parallel-edge');
  });
});

function byMessage(violations: Violation[]): Violation[] {
  return [...violations].sort((a, b) => a.message.localeCompare(b.message));
}

/** Entries of the record that write a pointer (not a flag). */
function pointerWrites(record: ChangeRecord): number[] {
  return [...record.pointers.array.keys()].filter((i) => meshArrays[record.pointers.array[i]].refers !== null);
}

function liveIds(mesh: HalfedgeMesh, kind: 'vertex' | 'halfedge' | 'edge' | 'face'): number[] {
  if (kind === 'vertex') return [...mesh.vertices()];
  if (kind === 'face') return [...mesh.faces()];
  return [...mesh.halfedges()];
}

/** validateAround on `touched` finds something, and only what validate finds; returns it. */
function sameAsValidate(mesh: HalfedgeMesh, touched: TouchedElements): Violation[] {
  const local = validateAround(mesh, touched);
  expect(local.length).toBeGreaterThan(0);
  expect(validate(mesh)).toEqual(expect.arrayContaining(local));
  return local;
}
