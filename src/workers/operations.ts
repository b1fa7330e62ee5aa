/**
 * What the session can be asked to do: the stepped operations (subdivision, the plane cut,
 * smoothing, decimation, remeshing) and
 * the local edits, as plain requests that cross the worker boundary, each with the sentence that
 * says why it does not apply (so the page can disable a button with that sentence as its tooltip).
 */
import {
  canCollapseEdge,
  canFlipEdge,
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
} from '../core/edits/index.js';
import { type KeepSide, planeCut } from '../core/cut/index.js';
import { cannotDecimate, type DecimationOptions, decimation } from '../core/decimation/index.js';
import { type HalfedgeMesh, type Operation, TopologyError } from '../core/index.js';
import { cannotRemesh, remeshing, type RemeshingOptions } from '../core/remeshing/index.js';
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
  | { kind: 'triangulate-mesh' };

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

/** Null when the edit applies, else the sentence saying why not. */
export function cannotEdit(mesh: HalfedgeMesh, request: EditRequest): string | null {
  switch (request.kind) {
    case 'flip-edge':
      return canFlipEdge(mesh, request.edge);
    case 'split-edge':
      return request.triangulate ? canSplitEdgeTriangulated(mesh, request.edge) : canSplitEdge(mesh, request.edge);
    case 'collapse-edge':
      return canCollapseEdge(mesh, request.edge);
    case 'split-face':
      return canSplitFace(mesh, request.face, request.from, request.to);
    case 'poke-face':
      return canPokeFace(mesh, request.face);
    case 'erase-edge':
      return canMergeFaces(mesh, request.edge);
    case 'triangulate-face':
      return canTriangulateFace(mesh, request.face);
    case 'triangulate-mesh':
      return mesh.nFaces === 0 ? 'there are no faces to triangulate' : null;
  }
}

/**
 * Applies a local edit to `mesh`, recording every pointer it rewires.
 * @throws TopologyError with the `cannotEdit` sentence when it does not apply.
 */
export function applyEdit(mesh: HalfedgeMesh, request: EditRequest): EditResult & { label: string } {
  const reason = cannotEdit(mesh, request);
  if (reason) throw new TopologyError(reason);
  switch (request.kind) {
    case 'flip-edge':
      return { label: `flip e${request.edge}`, ...flipEdge(mesh, request.edge) };
    case 'split-edge':
      return request.triangulate
        ? { label: `split e${request.edge} (and its triangles)`, ...splitEdgeTriangulated(mesh, request.edge) }
        : { label: `split e${request.edge}`, ...splitEdge(mesh, request.edge) };
    case 'collapse-edge':
      return { label: `collapse e${request.edge}`, ...collapseEdge(mesh, request.edge) };
    case 'split-face':
      return { label: `split f${request.face} from v${request.from} to v${request.to}`, ...splitFace(mesh, request.face, request.from, request.to) };
    case 'poke-face':
      return { label: `poke f${request.face}`, ...pokeFace(mesh, request.face) };
    case 'erase-edge':
      return { label: `erase e${request.edge}`, ...mergeFaces(mesh, request.edge) };
    case 'triangulate-face':
      return { label: `triangulate f${request.face}`, ...triangulateFace(mesh, request.face) };
    case 'triangulate-mesh':
      return { label: 'triangulate every face', ...triangulateMesh(mesh) };
  }
}

function hasBoundary(mesh: HalfedgeMesh): boolean {
  for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heFace[h] === -1 && !mesh.eDeleted[h >> 1]) return true;
  return false;
}
