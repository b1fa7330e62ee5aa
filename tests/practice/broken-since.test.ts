/**
 * The grader's search for when each broken invariant began to fail (`brokenSince`, which re-runs
 * only the checks a write touched) against the search it replaced (`validate` after every write),
 * on the traces of the right solutions with writes dropped or set wrong, and of wrong solutions.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, grid, type HalfedgeMesh, seededRandom, validate } from '../../src/core/index.js';
import { brokenSince, findExercise, fixtureMesh, type PracticeWrite, replayWrites } from '../../src/core/practice/index.js';
import { brokenSinceByValidating, inProcess, solution } from './helpers.js';

const SEED = 20260412;

/** Every edit exercise, with the solution that does it right. */
const EDITS = ['flip-edge', 'split-edge', 'collapse-edge', 'inset-vertex', 'extrude-face', 'bevel-vertex', 'bevel-edge', 'dissolve-edge', 'dissolve-vertex', 'collapse-face', 'make-boundary', 'weld-edges', 'triangulate', 'loop-subdivision', 'catmull-clark'];

const WRONG: [exercise: string, solution: string][] = [
  ['flip-edge', 'flip-forgets-vertex'],
  ['split-edge', 'split-forgets-face'],
  ['extrude-face', 'extrude-forgets-corner-halfedge'],
  ['bevel-vertex', 'bevel-forgets-wedge-face'],
  ['dissolve-edge', 'dissolve-edge-keeps-vertex-halfedge'],
  ['make-boundary', 'make-boundary-forgets-corners'],
];

interface Trace {
  name: string;
  before: HalfedgeMesh;
  writes: PracticeWrite[];
}

/** The writes `source` makes on every fixture of `exercise`. */
async function traces(exercise: string, source: string, name: string): Promise<Trace[]> {
  const { fixtures } = findExercise(exercise)!;
  const meshes = fixtures.map((fixture) => fixtureMesh(fixture));
  const outputs = await inProcess(source, meshes.map((mesh, i) => ({ mesh, input: fixtures[i].input })));
  return outputs.map((output, i) => ({ name: `${name} on ${fixtures[i].name}`, before: meshes[i], writes: output.writes }));
}

/** What a pointer write names: a halfedge, a vertex or a face, and whether -1 (none) is a value it may take. */
function kindOf(write: PracticeWrite): { kind: 'halfedge' | 'vertex' | 'face'; none: boolean } | null {
  switch (write.field) {
    case 'next':
    case 'prev':
    case 'faceHalfedge':
      return { kind: 'halfedge', none: false };
    case 'vertexHalfedge':
      return { kind: 'halfedge', none: true };
    case 'origin':
      return { kind: 'vertex', none: false };
    case 'face':
      return { kind: 'face', none: true };
    default:
      return null;
  }
}

/**
 * The trace with one or two of its pointer writes dropped, or set to what an earlier write of the
 * same field set, or to any element of the right kind that exists at that write (as the mesh API
 * allows: never an id not yet made).
 */
function spoiled(trace: Trace, random: () => number): PracticeWrite[] {
  const writes = trace.writes.slice();
  const pick = <T>(list: T[]) => list[Math.floor(random() * list.length)];
  for (let n = 1 + Math.floor(random() * 2); n > 0; n--) {
    const pointers = writes.flatMap((w, i) => (kindOf(w) ? [i] : []));
    if (pointers.length === 0) break;
    const i = pick(pointers);
    const write = writes[i] as Extract<PracticeWrite, { new: number }>;
    const choice = random();
    if (choice < 1 / 3) {
      writes.splice(i, 1);
    } else if (choice < 2 / 3) {
      const same = writes.slice(0, i + 1).filter((w): w is typeof write => w.field === write.field);
      writes[i] = { ...write, new: pick(same).new };
    } else {
      const { kind, none } = kindOf(write)!;
      const made = writes.slice(0, i).filter((w) => w.field === (kind === 'halfedge' ? 'newEdge' : kind === 'vertex' ? 'newVertex' : 'newFace')).length;
      const slots = kind === 'halfedge' ? trace.before.halfedgeSlots + 2 * made : kind === 'vertex' ? trace.before.vertexSlots + made : trace.before.faceSlots + made;
      writes[i] = { ...write, new: Math.floor(random() * (slots + (none ? 1 : 0))) - (none ? 1 : 0) };
    }
  }
  return writes;
}

/** Both searches on `writes`; the number of violations they were asked about. */
function expectSame(trace: Trace, writes: PracticeWrite[]): number {
  const final = validate(replayWrites(trace.before.clone(), writes), { limit: 50 });
  if (final.length > 0) expect(brokenSince(trace.before, writes, final), trace.name).toEqual(brokenSinceByValidating(trace.before, writes, final));
  return final.length;
}

describe('brokenSince', () => {
  it(`finds for each broken invariant the write the validate-after-every-write search finds, on right traces spoiled at random (seed ${SEED})`, async () => {
    const random = seededRandom(SEED);
    let broken = 0;
    let tried = 0;
    for (const exercise of EDITS) {
      for (const trace of await traces(exercise, solution(exercise), exercise)) {
        if (trace.writes.length === 0) continue;
        for (let k = 0; k < 8; k++, tried++) if (expectSame(trace, spoiled(trace, random)) > 0) broken++;
      }
    }
    // most spoiled traces leave something broken, so the searches were compared on many
    expect(broken).toBeGreaterThan(tried / 2);
  });

  it('finds the same as the validate-after-every-write search on the traces of wrong solutions', async () => {
    let broken = 0;
    for (const [exercise, wrong] of WRONG) {
      for (const trace of await traces(exercise, solution(`wrong/${wrong}`), wrong)) if (expectSame(trace, trace.writes) > 0) broken++;
    }
    expect(broken).toBeGreaterThanOrEqual(WRONG.length);
  });

  it("sees a vertex's fan mended when a stray halfedge stops leaving it, not only when one starts to", () => {
    const before = buildMesh(grid(3, 3)).mesh;
    const v = 5; // inside the grid, its fan far from the corners
    const stray = (corner: number) => before.vertexHalfedge(corner);
    const origin = (h: number, to: number): PracticeWrite => ({ field: 'origin', index: h, old: before.heVertex[h], new: to, line: null });
    // a corner's halfedge made to leave v, put back, then another's: v's fan is short of one since the third write
    const writes = [origin(stray(0), v), origin(stray(0), 0), origin(stray(15), v)];
    const final = validate(replayWrites(before.clone(), writes), { limit: 50 });
    const fan = final.findIndex((violation) => violation.invariant === 'vertex-fan' && violation.vertices![0] === v);
    expect(fan).toBeGreaterThanOrEqual(0);
    expect(brokenSince(before, writes, final)[fan]).toBe(2);
    expect(brokenSince(before, writes, final)).toEqual(brokenSinceByValidating(before, writes, final));
  });
});
