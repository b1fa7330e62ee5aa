/**
 * The edit-sequence fuzzer: random meshes put through random sequences of every local edit and
 * every operation, as fast-check commands. Each command asks its predicate first (`canFlipEdge`,
 * `cannotSubdivide`, …); when refused, the mesh must be untouched; when allowed, it must not throw,
 * and after it `validate()` finds nothing, an edit's reported changes are exactly the pointers
 * that changed, and the mesh survives save and reload (`reload.ts`).
 *
 * Case (seed, index) runs one fast-check run whose seed mixes the two numbers (`caseSeed`), so
 * a failure replays from them alone; fast-check shrinks it first, and the failure's input is the
 * shrunk sequence, written as the steps that ran ("cube; collapse e7; merge e10; …").
 */
import fc from 'fast-check';
import { buildMesh } from '../src/core/build.js';
import { cutMesh } from '../src/core/cut/index.js';
import { cannotDecimate, decimate } from '../src/core/decimation/index.js';
import { applyChange } from '../src/core/change/record.js';
import { diffPointers } from '../src/core/change/diff.js';
import { meshFingerprint } from '../src/core/fingerprint.js';
import {
  bevelEdge,
  bevelVertex,
  canBevelEdge,
  canBevelVertex,
  canCollapseEdge,
  canCollapseFace,
  canDissolveEdge,
  canDissolveVertex,
  canExtrudeFace,
  canFlipEdge,
  canMakeBoundary,
  canWeldEdges,
  collapseFace,
  dissolveEdge,
  dissolveVertex,
  extrudeFace,
  makeBoundary,
  weldEdges,
  canMergeFaces,
  canPokeFace,
  canSplitEdge,
  canSplitEdgeTriangulated,
  canSplitFace,
  canTriangulateFace,
  collapseEdge,
  type EditResult,
  flipEdge,
  mergeFaces,
  pokeFace,
  splitEdge,
  splitEdgeTriangulated,
  splitFace,
  triangulateFace,
  triangulateMesh,
} from '../src/core/edits/index.js';
import type { HalfedgeMesh } from '../src/core/mesh.js';
import { annulus, bowTie, cube, disk, fan, grid, moebiusStrip, strip, tetrahedron, torus, uvSphere } from '../src/core/shapes.js';
import { cannotSmooth, type SmoothingMethod, smooth } from '../src/core/smoothing/index.js';
import type { PolygonSoup } from '../src/core/soup.js';
import { cannotSubdivide, type SubdivisionScheme, subdivide } from '../src/core/subdivision/index.js';
import { validate } from '../src/core/validate.js';
import { reloadDifference } from './reload.js';
import { type CaseOutcome, caseSeed, type FuzzTarget } from './target.js';

/** Start meshes: closed and open, triangles, quads and polygons, repaired ones too. */
export const shapes: Record<string, () => PolygonSoup> = {
  tetrahedron,
  cube,
  'torus 4×3': () => torus(4, 3),
  'sphere 4×6': () => uvSphere(4, 6),
  'fan 5': () => fan(5),
  'strip 3': () => strip(3),
  'annulus 6': () => annulus(6),
  'disk 2': () => disk(2),
  'quad grid 3×2': () => grid(3, 2, true),
  'Möbius strip 6': () => moebiusStrip(6),
  'bow tie': bowTie,
};

/** Operations run only on meshes up to this many faces, so a case stays within milliseconds. */
const MAX_FACES_FOR_OPERATIONS = 400;

/** What a step found wrong: ends the case as a failure, with the steps of its run that led there. */
class StepFailure extends Error {
  constructor(
    message: string,
    readonly steps: string[],
  ) {
    super(message);
  }
}

interface Real {
  mesh: HalfedgeMesh;
  /** The start mesh and the steps so far, as they ran (the ids and planes they chose). */
  log: string[];
}

/** The `k`-th live element (by `pick` modulo the count), or -1 when there is none. */
function nth(ids: Generator<number>, pick: number): number {
  const list = [...ids];
  return list.length === 0 ? -1 : list[pick % list.length];
}

/**
 * One step: `plan` looks at the mesh and returns the step's name, why it is refused (or null),
 * and how to do it. A refused step must leave the mesh untouched; an allowed one is checked.
 */
export type Plan = { name: string; refusal: string | null; apply: () => EditResult | void } | null;

export class Step implements fc.Command<object, Real> {
  private ran = '';
  constructor(
    private readonly label: string,
    private readonly plan: (mesh: HalfedgeMesh) => Plan,
  ) {}
  check(): boolean {
    return true;
  }
  run(_model: object, real: Real): void {
    const { mesh } = real;
    const plan = this.plan(mesh);
    if (!plan) {
      this.ran = `${this.label} (nothing to apply it to)`;
      return;
    }
    this.ran = plan.name;
    real.log.push(plan.name);
    const fail = (message: string) => new StepFailure(message, real.log);
    const before = mesh.clone();
    if (plan.refusal !== null) {
      const changed = diffPointers(before, mesh, 1).total;
      if (changed > 0 || mesh.nFaces !== before.nFaces) throw fail(`${plan.name} was refused but changed the mesh`);
      return;
    }
    let result: EditResult | void;
    try {
      result = plan.apply();
    } catch (error) {
      throw fail(`${plan.name}: its predicate allowed it, then it threw ${(error as Error).stack ?? error}`);
    }
    const problems = validate(mesh, { limit: 3 });
    if (problems.length > 0) throw fail(`${plan.name} left an invalid mesh: ${problems.map((p) => p.message).join('; ')}`);
    if (result) {
      const found = JSON.stringify(diffPointers(before, mesh, Infinity).changes);
      if (JSON.stringify(result.changes) !== found) throw fail(`${plan.name} reported other pointer changes than it made`);
      if (result.record) {
        // the record is the undo entry: backwards it must give the mesh before, forwards the mesh after
        const after = meshFingerprint(mesh);
        applyChange(mesh, result.record, 'backward');
        if (meshFingerprint(mesh) !== meshFingerprint(before)) throw fail(`${plan.name}: its change record, undone, does not give the mesh before`);
        applyChange(mesh, result.record, 'forward');
        if (meshFingerprint(mesh) !== after) throw fail(`${plan.name}: its change record, redone, does not give the mesh after`);
      }
    }
    const difference = reloadDifference(mesh);
    if (difference) throw fail(`${plan.name}: saved and read back, ${difference}`);
  }
  toString(): string {
    return this.ran || this.label;
  }
}

const pick = fc.nat();
const fraction = fc.double({ min: 0.05, max: 0.95, noNaN: true });

/** An edit of one element, the `k`-th live edge (`e`) or face (`f`), with its predicate. */
export interface ElementEdit {
  name: string;
  on: 'e' | 'f' | 'v';
  can: (mesh: HalfedgeMesh, id: number) => string | null;
  edit: (mesh: HalfedgeMesh, id: number) => EditResult;
}

/** The local edits that need nothing but their element. */
export const elementEdits: ElementEdit[] = [
  { name: 'flip', on: 'e', can: canFlipEdge, edit: flipEdge },
  { name: 'split-triangulated', on: 'e', can: canSplitEdgeTriangulated, edit: splitEdgeTriangulated },
  { name: 'collapse', on: 'e', can: canCollapseEdge, edit: collapseEdge },
  { name: 'merge', on: 'e', can: canMergeFaces, edit: mergeFaces },
  { name: 'poke', on: 'f', can: canPokeFace, edit: pokeFace },
  { name: 'triangulate', on: 'f', can: canTriangulateFace, edit: triangulateFace },
  { name: 'extrude', on: 'f', can: (m, f) => canExtrudeFace(m, f, { offset: 0.2, inset: 0.3 }), edit: (m, f) => extrudeFace(m, f, { offset: 0.2, inset: 0.3 }) },
  { name: 'bevel-vertex', on: 'v', can: (m, v) => canBevelVertex(m, v, 0.25), edit: (m, v) => bevelVertex(m, v, { amount: 0.25 }) },
  { name: 'bevel-edge', on: 'e', can: (m, e) => canBevelEdge(m, e, 0.25), edit: (m, e) => bevelEdge(m, e, { amount: 0.25 }) },
  { name: 'dissolve-vertex', on: 'v', can: canDissolveVertex, edit: dissolveVertex },
  { name: 'dissolve-edge', on: 'e', can: canDissolveEdge, edit: dissolveEdge },
  { name: 'collapse-face', on: 'f', can: canCollapseFace, edit: collapseFace },
  { name: 'make-boundary', on: 'f', can: canMakeBoundary, edit: makeBoundary },
];

const elementCommand = ({ name, on, can, edit }: ElementEdit) => pick.map((k) => new Step(name, (m) => elementStep(m, on, k, name, can, edit)));
const [flip, ...othersOnOneElement] = elementEdits.map(elementCommand);

/** Every edit and operation, each with the choices it needs. */
export const editCommands: Array<fc.Arbitrary<Step>> = [
  flip,
  fc.tuple(pick, fraction).map(([k, t]) => new Step('split', (m) => elementStep(m, 'e', k, 'split', (mesh, e) => canSplitEdge(mesh, e, t), (mesh, e) => splitEdge(mesh, e, { t })))),
  ...othersOnOneElement,
  fc.tuple(pick, pick, pick).map(([k, i, j]) => new Step('split-face', (m) => splitFaceStep(m, k, i, j))),
  fc.tuple(pick, pick).map(([i, j]) => new Step('weld', (m) => weldStep(m, i, j))),
  fc.constant(null).map(() => new Step('triangulate-all', (m) => ({ name: 'triangulate-all', refusal: null, apply: () => void triangulateMesh(m, { record: false }) }))),
  fc.constantFrom<SubdivisionScheme>('loop', 'catmull-clark', 'butterfly', 'sqrt3').map(
    (scheme) => new Step(`subdivide ${scheme}`, (m) => operationStep(m, `subdivide ${scheme}`, cannotSubdivide(m, scheme), () => subdivide(m, scheme, 1))),
  ),
  fc.tuple(fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true }), fc.double({ min: -1, max: 1, noNaN: true }), pick, fc.constantFrom('above', 'below', 'both' as const), fc.boolean()).map(
    ([a, b, c, k, keep, cap]) => new Step('cut', (m) => cutStep(m, [a, b, c], k, keep, cap)),
  ),
  fc.tuple(fc.constantFrom<SmoothingMethod>('laplacian', 'cotan', 'taubin'), fc.integer({ min: 1, max: 3 })).map(
    ([method, iterations]) => new Step(`smooth ${method}`, (m) => operationStep(m, `smooth ${method} ×${iterations}`, cannotSmooth(m, { method }), () => smooth(m, { method, iterations }))),
  ),
  fraction.map((share) => new Step('decimate', (m) => decimateStep(m, share))),
];

/** A step on the `k`-th live edge, face or vertex (`kind`), asking `can` first. */
function elementStep(
  mesh: HalfedgeMesh,
  kind: 'e' | 'f' | 'v',
  k: number,
  name: string,
  can: (mesh: HalfedgeMesh, id: number) => string | null,
  edit: (mesh: HalfedgeMesh, id: number) => EditResult,
): Plan {
  const id = elementOf(mesh, kind, k);
  return id === -1 ? null : { name: `${name} ${kind}${id}`, refusal: can(mesh, id), apply: () => edit(mesh, id) };
}

/** The `k`-th live edge (`e`), face (`f`) or vertex (`v`), modulo their count, or -1 when there is none. */
export function elementOf(mesh: HalfedgeMesh, kind: 'e' | 'f' | 'v', k: number): number {
  return nth(kind === 'e' ? mesh.edges() : kind === 'f' ? mesh.faces() : mesh.vertices(), k);
}

/** A weld of the `i`-th and `j`-th boundary edges, asking `canWeldEdges` first. */
function weldStep(mesh: HalfedgeMesh, i: number, j: number): Plan {
  const boundary = [...mesh.edges()].filter((e) => mesh.heFace[2 * e] === -1 || mesh.heFace[2 * e + 1] === -1);
  if (boundary.length < 2) return null;
  const e1 = boundary[i % boundary.length]!;
  const e2 = boundary[j % boundary.length]!;
  return { name: `weld e${e1} e${e2}`, refusal: canWeldEdges(mesh, e1, e2), apply: () => weldEdges(mesh, e1, e2) };
}

function splitFaceStep(mesh: HalfedgeMesh, k: number, i: number, j: number): Plan {
  const f = nth(mesh.faces(), k);
  if (f === -1) return null;
  const corners: number[] = [];
  let h = mesh.fHalfedge[f];
  do {
    corners.push(mesh.heVertex[h]);
    h = mesh.heNext[h];
  } while (h !== mesh.fHalfedge[f] && corners.length <= mesh.halfedgeSlots);
  const u = corners[i % corners.length];
  const v = corners[j % corners.length];
  return { name: `split-face f${f} v${u} v${v}`, refusal: canSplitFace(mesh, f, u, v), apply: () => splitFace(mesh, f, u, v) };
}

function operationStep(mesh: HalfedgeMesh, name: string, refusal: string | null, apply: () => void): Plan {
  if (mesh.nFaces > MAX_FACES_FOR_OPERATIONS) return null;
  return { name, refusal, apply };
}

/** A plane with the given normal through a vertex of the mesh (so vertices on the plane are common). */
function cutStep(mesh: HalfedgeMesh, normal: number[], k: number, keep: 'above' | 'below' | 'both', cap: boolean): Plan {
  const v = nth(mesh.vertices(), k);
  if (v === -1 || Math.hypot(normal[0], normal[1], normal[2]) < 1e-3) return null;
  const d = -(normal[0] * mesh.positions[3 * v] + normal[1] * mesh.positions[3 * v + 1] + normal[2] * mesh.positions[3 * v + 2]);
  const plane: [number, number, number, number] = [normal[0], normal[1], normal[2], d];
  const name = `cut ${plane.map((x) => +x.toFixed(6)).join(',')} keep ${keep}${cap ? '' : ' no-cap'}`;
  return operationStep(mesh, name, null, () => void cutMesh(mesh, plane, { keep, cap }));
}

function decimateStep(mesh: HalfedgeMesh, share: number): Plan {
  const targetFaces = Math.max(1, Math.floor(share * mesh.nFaces));
  return operationStep(mesh, `decimate to ${targetFaces} faces`, cannotDecimate(mesh, { targetFaces }), () => void decimate(mesh, { targetFaces }));
}

/**
 * The fuzz target over `commands` (every edit and operation by default; the tests add a broken
 * one to see that it is caught).
 */
export function editSequenceTarget(commands = editCommands): FuzzTarget<CaseOutcome> {
  const sequence = fc.record({
    shape: fc.constantFrom(...Object.keys(shapes)),
    commands: fc.commands(commands, { maxCommands: 12 }),
  });
  const run = ({ shape, commands: steps }: { shape: string; commands: Iterable<fc.Command<object, Real>> }) => {
    fc.modelRun(() => ({ model: {}, real: { mesh: buildMesh(shapes[shape]()).mesh, log: [shape] } }), steps);
  };
  return {
    name: 'edits',
    runCase(seed: number, index: number): CaseOutcome {
      const details = fc.check(fc.property(sequence, run), { seed: caseSeed(seed, index), numRuns: 1 });
      if (!details.failed) return { kind: 'accepted' };
      // the failing run's own log of steps (the shrunk one): the sequence that replays it
      const error = details.errorInstance;
      const reason = error instanceof StepFailure ? error.message : `${(error as Error | undefined)?.stack ?? String(error)}`;
      const input = error instanceof StepFailure ? error.steps.join('; ') : String(details.counterexample?.[0]?.shape);
      return { kind: 'failure', reason, input: `${input}   [fast-check seed ${details.seed}, path ${details.counterexamplePath}]` };
    },
  };
}

export const editsTarget = editSequenceTarget();
