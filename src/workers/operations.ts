/**
 * What the session can be asked to do: the stepped operations (subdivision, the plane cut,
 * smoothing, decimation, remeshing) and
 * the local edits, as plain requests that cross the worker boundary, each with the sentence that
 * says why it does not apply (so the page can disable a button with that sentence as its tooltip).
 */
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
  canMergeFaces,
  canPokeFace,
  canSplitEdge,
  canSplitEdgeTriangulated,
  canSplitFace,
  canTriangulateFace,
  canWeldEdges,
  collapseEdge,
  collapseFace,
  dissolveEdge,
  dissolveVertex,
  type EditResult,
  extrudeFace,
  flipEdge,
  makeBoundary,
  mergeFaces,
  pokeFace,
  splitEdge,
  splitEdgeTriangulated,
  splitFace,
  triangulateFace,
  triangulateMesh,
  weldEdges,
} from '../core/edits/index.js';
import { type KeepSide, planeCut } from '../core/cut/index.js';
import { cannotDecimate, type DecimationOptions, decimation } from '../core/decimation/index.js';
import { type HalfedgeMesh, type Operation, TopologyError } from '../core/index.js';
import type { ExerciseInput } from '../core/practice/exercise.js';
import { cannotRemesh, meanEdgeLength, remeshing, type RemeshingOptions } from '../core/remeshing/index.js';
import { cannotSmooth, smoothing, type SmoothingOptions } from '../core/smoothing/index.js';
import { cannotSubdivide, type SubdivisionScheme, subdivisionOperation } from '../core/subdivision/index.js';

export type OperationRequest =
  /** `level`: how many levels of the scheme ran before (√3 splits an open mesh's boundary on odd levels). */
  | { kind: 'subdivide'; scheme: SubdivisionScheme; level?: number }
  | { kind: 'cut'; plane: [number, number, number, number]; keep?: KeepSide; cap?: boolean }
  | { kind: 'smooth'; options: SmoothingOptions }
  | { kind: 'decimate'; options: DecimationOptions }
  | { kind: 'remesh'; options: RemeshingOptions };

export type EditRequest =
  | { kind: 'flip-edge'; edge: number }
  | { kind: 'split-edge'; edge: number; triangulate?: boolean }
  | { kind: 'collapse-edge'; edge: number }
  | { kind: 'split-face'; face: number; from: number; to: number }
  | { kind: 'poke-face'; face: number }
  | { kind: 'erase-edge'; edge: number }
  | { kind: 'triangulate-face'; face: number }
  | { kind: 'triangulate-mesh' }
  /** `offset` along the face's normal (default: half its mean side, so the new quads show), `inset` toward its centre, 0 … 1. */
  | { kind: 'extrude-face'; face: number; offset?: number; inset?: number }
  /** `amount`: how far along each edge the new corners go, 0 … 1 (default 0.25, so the new face shows). */
  | { kind: 'bevel-vertex'; vertex: number; amount?: number }
  | { kind: 'bevel-edge'; edge: number; amount?: number }
  | { kind: 'dissolve-vertex'; vertex: number }
  | { kind: 'dissolve-edge'; edge: number }
  | { kind: 'collapse-face'; face: number }
  | { kind: 'make-boundary'; face: number }
  | { kind: 'weld-edges'; edges: [number, number] };

export type EditKind = EditRequest['kind'];

const schemeNames: Record<SubdivisionScheme, string> = {
  loop: 'Loop subdivision',
  'catmull-clark': 'Catmull-Clark subdivision',
  butterfly: 'Modified Butterfly subdivision',
  sqrt3: '√3 subdivision',
  linear: 'linear subdivision',
};

/** Phases of one level of each scheme (√3 adds two on the odd levels of an open mesh). */
const schemePhases: Record<SubdivisionScheme, number> = { loop: 4, 'catmull-clark': 4, butterfly: 3, sqrt3: 3, linear: 3 };
const CUT_PHASES = 6;

export function operationLabel(request: OperationRequest): string {
  switch (request.kind) {
    case 'subdivide':
      return schemeNames[request.scheme] ?? `subdivide (${String(request.scheme)})`;
    case 'cut': {
      const [a, b, c, d] = request.plane.map((x) => +x.toFixed(4));
      return `plane cut ${a}x + ${b}y + ${c}z + ${d} = 0`;
    }
    case 'smooth': {
      const { method, iterations = 10 } = request.options;
      return `${smoothingNames[method] ?? method} smoothing, ${iterations} iteration${iterations === 1 ? '' : 's'}`;
    }
    case 'decimate':
      return request.options.targetFaces !== undefined ? `decimate to ${request.options.targetFaces} faces` : 'decimate';
    case 'remesh': {
      const { targetEdgeLength, iterations = 3 } = request.options;
      const target = targetEdgeLength !== undefined ? ` to edges of ${+targetEdgeLength.toPrecision(4)}` : '';
      return `isotropic remeshing${target}, ${iterations} iteration${iterations === 1 ? '' : 's'}`;
    }
  }
}

const smoothingNames: Record<string, string> = { laplacian: 'uniform Laplacian', cotan: 'cotangent Laplacian', taubin: 'Taubin' };

/** Null when the operation applies to `mesh`, else the sentence saying why not. */
export function cannotStart(mesh: HalfedgeMesh, request: OperationRequest): string | null {
  switch (request.kind) {
    case 'subdivide':
      return cannotSubdivide(mesh, request.scheme);
    case 'cut':
      return mesh.nFaces === 0 ? 'there are no faces to cut' : null;
    case 'smooth':
      return cannotSmooth(mesh, request.options);
    case 'decimate':
      return cannotDecimate(mesh, request.options);
    case 'remesh':
      return cannotRemesh(mesh, request.options);
  }
}

/**
 * The operation, ready to step, on `mesh` (which it will change).
 * @throws TopologyError with the `cannotStart` sentence when it does not apply.
 */
export function startOperation(mesh: HalfedgeMesh, request: OperationRequest): { operation: Operation; phases: number | null } {
  const reason = cannotStart(mesh, request);
  if (reason) throw new TopologyError(reason);
  switch (request.kind) {
    case 'subdivide': {
      const level = request.level ?? 0;
      const splitsBoundary = request.scheme === 'sqrt3' && level % 2 === 1 && hasBoundary(mesh);
      const phases = schemePhases[request.scheme] + (splitsBoundary ? 2 : 0);
      return { operation: subdivisionOperation(mesh, request.scheme, { level }), phases };
    }
    case 'cut':
      return { operation: planeCut(mesh, request.plane, { keep: request.keep, cap: request.cap }), phases: CUT_PHASES };
    case 'smooth': {
      // one phase per iteration; Taubin's shrink and inflate steps are a phase each
      const iterations = request.options.iterations ?? 10;
      return { operation: smoothing(mesh, request.options), phases: request.options.method === 'taubin' ? 2 * iterations : iterations };
    }
    case 'decimate':
      // as many batches as it takes
      return { operation: decimation(mesh, request.options), phases: null };
    case 'remesh':
      // split, collapse, flip, smooth and project: four phases per iteration
      return { operation: remeshing(mesh, request.options), phases: 4 * (request.options.iterations ?? 3) };
  }
}

/** How far a bevel's new corners go along their edges when a request does not say: far enough to see the new face. */
const BEVEL_AMOUNT = 0.25;

/**
 * The Practice exercise whose solution does what a request asks, and the input the solution is
 * called with: the numbers the library's edit would use, defaults included. With "Use my code" on,
 * the app runs the student's solution instead of the library's function (docs/practice.md).
 */
export interface SolutionCall {
  exercise: string;
  input: ExerciseInput | undefined;
  /** What the history calls the request (`flip e10`, `Loop subdivision`). */
  label: string;
}

/**
 * Each edit in one place: why it does not apply (null: it does), what it does, its history label,
 * its exercise, and its button in the Operate panel.
 */
interface EditDefinition<R extends EditRequest> {
  cannot(mesh: HalfedgeMesh, request: R): string | null;
  apply(mesh: HalfedgeMesh, request: R): EditResult;
  label(request: R): string;
  /** The exercise that practises this edit (none for the edits no exercise sets). */
  solution?(mesh: HalfedgeMesh, request: R): Omit<SolutionCall, 'label'> | null;
  /** Its button, and what the selection must be for it (a face split has a form of its own instead). */
  button?: { label: string; needs: EditNeeds };
}

/** What an edit's button acts on: the selected edge, vertex or face, the whole mesh, or two edges chosen one after the other. */
export type EditNeeds = 'edge' | 'vertex' | 'face' | 'mesh' | 'two edges';

type EditDefinitions = { [K in EditKind]: EditDefinition<Extract<EditRequest, { kind: K }>> };

const editDefinitions: EditDefinitions = {
  'flip-edge': { cannot: (m, r) => canFlipEdge(m, r.edge), apply: (m, r) => flipEdge(m, r.edge), label: (r) => `flip e${r.edge}`, solution: (_, r) => call('flip-edge', r.edge), button: { label: 'Flip edge', needs: 'edge' } },
  'split-edge': {
    cannot: (m, r) => (r.triangulate ? canSplitEdgeTriangulated(m, r.edge) : canSplitEdge(m, r.edge)),
    apply: (m, r) => (r.triangulate ? splitEdgeTriangulated(m, r.edge) : splitEdge(m, r.edge)),
    label: (r) => (r.triangulate ? `split e${r.edge} (and its triangles)` : `split e${r.edge}`),
    // the exercise splits the triangles too
    solution: (_, r) => (r.triangulate ? call('split-edge', r.edge) : null),
    button: { label: 'Split edge', needs: 'edge' },
  },
  'collapse-edge': {
    cannot: (m, r) => canCollapseEdge(m, r.edge),
    apply: (m, r) => collapseEdge(m, r.edge),
    label: (r) => `collapse e${r.edge}`,
    solution: (_, r) => call('collapse-edge', r.edge),
    button: { label: 'Collapse edge', needs: 'edge' },
  },
  'erase-edge': { cannot: (m, r) => canMergeFaces(m, r.edge), apply: (m, r) => mergeFaces(m, r.edge), label: (r) => `erase e${r.edge}`, button: { label: 'Erase edge', needs: 'edge' } },
  'dissolve-edge': {
    cannot: (m, r) => canDissolveEdge(m, r.edge),
    apply: (m, r) => dissolveEdge(m, r.edge),
    label: (r) => `dissolve e${r.edge}`,
    solution: (_, r) => call('dissolve-edge', r.edge),
    button: { label: 'Dissolve edge', needs: 'edge' },
  },
  'bevel-edge': {
    cannot: (m, r) => canBevelEdge(m, r.edge, r.amount ?? BEVEL_AMOUNT),
    apply: (m, r) => bevelEdge(m, r.edge, { amount: r.amount ?? BEVEL_AMOUNT }),
    label: (r) => `bevel e${r.edge}`,
    solution: (_, r) => call('bevel-edge', { edge: r.edge, amount: r.amount ?? BEVEL_AMOUNT }),
    button: { label: 'Bevel edge', needs: 'edge' },
  },
  'weld-edges': {
    cannot: (m, r) => (Array.isArray(r.edges) && r.edges.length === 2 ? canWeldEdges(m, r.edges[0], r.edges[1]) : 'a weld needs two boundary edges: edges: [e1, e2]'),
    apply: (m, r) => weldEdges(m, r.edges[0], r.edges[1]),
    label: (r) => `weld e${r.edges[0]} and e${r.edges[1]}`,
    solution: (_, r) => call('weld-edges', [r.edges[0], r.edges[1]]),
    button: { label: 'Weld edges', needs: 'two edges' },
  },
  'dissolve-vertex': {
    cannot: (m, r) => canDissolveVertex(m, r.vertex),
    apply: (m, r) => dissolveVertex(m, r.vertex),
    label: (r) => `dissolve v${r.vertex}`,
    solution: (_, r) => call('dissolve-vertex', r.vertex),
    button: { label: 'Dissolve vertex', needs: 'vertex' },
  },
  'bevel-vertex': {
    cannot: (m, r) => canBevelVertex(m, r.vertex, r.amount ?? BEVEL_AMOUNT),
    apply: (m, r) => bevelVertex(m, r.vertex, { amount: r.amount ?? BEVEL_AMOUNT }),
    label: (r) => `bevel v${r.vertex}`,
    solution: (_, r) => call('bevel-vertex', { vertex: r.vertex, amount: r.amount ?? BEVEL_AMOUNT }),
    button: { label: 'Bevel vertex', needs: 'vertex' },
  },
  'poke-face': { cannot: (m, r) => canPokeFace(m, r.face), apply: (m, r) => pokeFace(m, r.face), label: (r) => `poke f${r.face}`, solution: (_, r) => call('inset-vertex', r.face), button: { label: 'Poke face', needs: 'face' } },
  'extrude-face': {
    cannot: (m, r) => canExtrudeFace(m, r.face, extrudePlacement(m, r)),
    apply: (m, r) => extrudeFace(m, r.face, extrudePlacement(m, r)),
    label: (r) => `extrude f${r.face}`,
    solution: (m, r) => call('extrude-face', { face: r.face, ...extrudePlacement(m, r) }),
    button: { label: 'Extrude face', needs: 'face' },
  },
  'collapse-face': {
    cannot: (m, r) => canCollapseFace(m, r.face),
    apply: (m, r) => collapseFace(m, r.face),
    label: (r) => `collapse f${r.face}`,
    solution: (_, r) => call('collapse-face', r.face),
    button: { label: 'Collapse face', needs: 'face' },
  },
  'make-boundary': {
    cannot: (m, r) => canMakeBoundary(m, r.face),
    apply: (m, r) => makeBoundary(m, r.face),
    label: (r) => `make f${r.face} a hole`,
    solution: (_, r) => call('make-boundary', r.face),
    button: { label: 'Make a hole', needs: 'face' },
  },
  'triangulate-face': { cannot: (m, r) => canTriangulateFace(m, r.face), apply: (m, r) => triangulateFace(m, r.face), label: (r) => `triangulate f${r.face}`, button: { label: 'Triangulate face', needs: 'face' } },
  'split-face': {
    cannot: (m, r) => canSplitFace(m, r.face, r.from, r.to),
    apply: (m, r) => splitFace(m, r.face, r.from, r.to),
    label: (r) => `split f${r.face} from v${r.from} to v${r.to}`,
  },
  'triangulate-mesh': {
    cannot: (m) => (m.nFaces === 0 ? 'there are no faces to triangulate' : null),
    apply: (m) => triangulateMesh(m),
    label: () => 'triangulate every face',
    solution: () => call('triangulate', undefined),
    button: { label: 'Triangulate all', needs: 'mesh' },
  },
};

/** The edits the Operate panel has a button for, in the table's order (by what they act on): kind, label, what the selection must be. */
export const editButtons = Object.entries(editDefinitions).flatMap(([kind, definition]) =>
  definition.button ? [{ kind: kind as Exclude<EditKind, 'split-face'>, ...(definition.button as { label: string; needs: EditNeeds }) }] : [],
);

function call(exercise: string, input: ExerciseInput | undefined): Omit<SolutionCall, 'label'> {
  return { exercise, input };
}

/**
 * The exercise whose solution does what `request` asks, and its input (see `SolutionCall`); null
 * for a request no exercise sets (a cut, smoothing, a face split, another subdivision scheme).
 */
export function solutionCall(mesh: HalfedgeMesh, request: { verb: 'edit'; request: EditRequest } | { verb: 'start'; request: OperationRequest }): SolutionCall | null {
  if (request.verb === 'edit') {
    const definition = definitionOf(request.request);
    const found = definition.solution?.(mesh, request.request);
    return found ? { ...found, label: definition.label(request.request) } : null;
  }
  const found = operationExercise(mesh, request.request);
  return found && { ...found, label: operationLabel(request.request) };
}

function operationExercise(mesh: HalfedgeMesh, operation: OperationRequest): Omit<SolutionCall, 'label'> | null {
  switch (operation.kind) {
    case 'subdivide': {
      const exercises: Partial<Record<SubdivisionScheme, string>> = { loop: 'loop-subdivision', 'catmull-clark': 'catmull-clark', linear: 'linear-subdivision' };
      const exercise = exercises[operation.scheme];
      return exercise ? call(exercise, undefined) : null;
    }
    case 'remesh':
      return call('isotropic-remesh', { targetEdgeLength: operation.options.targetEdgeLength ?? meanEdgeLength(mesh), iterations: operation.options.iterations ?? 3 });
    case 'decimate':
      // the exercise's target is a face count: decimation's default, half the faces
      return operation.options.maxError === undefined ? call('simplify', { faces: operation.options.targetFaces ?? Math.floor(mesh.nFaces / 2) }) : null;
    default:
      return null;
  }
}

/** The extrusion a request asks for; without an offset, half the face's mean side along its normal, so the new quads show. */
function extrudePlacement(mesh: HalfedgeMesh, request: Extract<EditRequest, { kind: 'extrude-face' }>): { offset: number; inset: number } {
  return { offset: request.offset ?? 0.5 * meanSide(mesh, request.face), inset: request.inset ?? 0 };
}

/** The mean length of face f's sides (0 for an id that is not a live face: the predicate then says why). */
function meanSide(mesh: HalfedgeMesh, f: number): number {
  if (!Number.isInteger(f) || f < 0 || f >= mesh.faceSlots || mesh.fDeleted[f]) return 0;
  let total = 0;
  let sides = 0;
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    const [a, b] = [mesh.position(mesh.origin(h)), mesh.position(mesh.target(h))];
    total += Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    sides++;
    h = mesh.next(h);
  } while (h !== start && sides < mesh.halfedgeSlots);
  return total / sides;
}

/** The definition of a request's edit; a kind there is none of (from a link, from a script) is refused by name. */
function definitionOf(request: EditRequest): EditDefinition<EditRequest> {
  const kind = String((request as { kind?: unknown }).kind);
  // a kind that comes as data counts only as one of the table's own entries, never as a prototype's
  if (!Object.hasOwn(editDefinitions, kind)) throw new TopologyError(`there is no edit '${kind}' (edits: ${Object.keys(editDefinitions).join(', ')})`);
  return (editDefinitions as unknown as Record<string, EditDefinition<EditRequest>>)[kind]!;
}

/** Null when the edit applies, else the sentence saying why not. */
export function cannotEdit(mesh: HalfedgeMesh, request: EditRequest): string | null {
  return definitionOf(request).cannot(mesh, request);
}

/**
 * Applies a local edit to `mesh`, recording every pointer it rewires.
 * @throws TopologyError with the `cannotEdit` sentence when it does not apply.
 */
export function applyEdit(mesh: HalfedgeMesh, request: EditRequest): EditResult & { label: string } {
  const definition = definitionOf(request);
  const reason = definition.cannot(mesh, request);
  if (reason) throw new TopologyError(reason);
  return { label: definition.label(request), ...definition.apply(mesh, request) };
}

function hasBoundary(mesh: HalfedgeMesh): boolean {
  for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heFace[h] === -1 && !mesh.eDeleted[h >> 1]) return true;
  return false;
}
