/**
 * Isotropic remeshing (Botsch & Kobbelt 2004, §4): make every triangle of a triangle mesh about
 * equilateral with edges of one target length L, on the same surface. Each iteration takes four
 * steps, each a local edit repeated over the whole mesh (see `remesher.ts`):
 * ```
 *   split edges      collapse edges     flip edges towards      move each vertex towards its
 *   longer than  ──► shorter than   ──► valence 6 (4 on the ──► neighbours in its tangent
 *   4/3 L            4/5 L              boundary)               plane, then onto the input
 * ```
 * The first two even out the lengths, the flips the valences, and the smoothing the angles; the
 * projection onto the input surface (the mesh as it was given, kept in a grid of its triangles)
 * keeps the shape from shrinking or drifting. A few iterations take a mesh of long thin triangles,
 * or of any sizes, to one of nearly equilateral triangles of about the same size.
 *
 * The boundary keeps its shape: a rim vertex stays on the input's rim polyline, the rim's corners
 * stay put (see `remesher.ts`). A closed mesh stays closed, with its genus.
 *
 * Phases: four per iteration, "split long edges (iteration 1 of 3)", "collapse short edges …",
 * "flip edges towards valence 6 …", "smooth and project …". The topological ones list what they
 * created, removed and rewired; the smoothing one the vertices it moved, with how far each went as
 * `values.vertices`. Stepping, deleted elements stay in their slots (ids are stable from phase to
 * phase; `mesh.compact()` drops them); straight through (`remesh`), the mesh is compacted at the end.
 *
 * @example
 *   remesh(mesh);                                             // the mean edge length, 3 iterations
 *   remesh(mesh, { targetEdgeLength: 0.02, iterations: 5 });
 *   for (const phase of remeshing(mesh)) show(phase);         // step by step
 */
import { InvalidInputError, TopologyError } from '../errors.js';
import { ChangeRecorder } from '../change/recorder.js';
import { PointerWriter } from '../change/writer.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation, Phase } from '../change/operation.js';
import { spatialOrder } from '../spatial-order.js';
import { needsTriangles } from '../triangles.js';
import { meanEdgeLength, Remesher, TANGENTIAL_STEP } from './remesher.js';

export { meanEdgeLength } from './remesher.js';

export interface RemeshingOptions {
  /** The edge length to aim for, in the mesh's units (default: the mean edge length of the input). */
  targetEdgeLength?: number;
  /** Iterations of the four steps (default 3). */
  iterations?: number;
}

interface RemeshingSettings {
  targetEdgeLength: number;
  iterations: number;
}

/**
 * Null when remeshing applies to `mesh`, else a sentence saying why not: it needs triangles.
 * @example cannotRemesh(buildMesh(cube()).mesh) // "remeshing needs triangles; f0 is a quad. Triangulate the mesh first."
 * @throws InvalidInputError for a target length that is not a number > 0, or iterations that are
 *   not a whole number ≥ 0.
 */
export function cannotRemesh(mesh: HalfedgeMesh, options: RemeshingOptions = {}): string | null {
  checkOptions(options);
  if (mesh.nFaces === 0) return 'there are no faces to remesh';
  const reason = needsTriangles(mesh, 'remeshing');
  return reason && `${reason} Triangulate the mesh first.`;
}

/**
 * Remeshing as a steppable operation that edits `mesh` in place (see above for the phases).
 * @example runOperation(remeshing(mesh, { iterations: 1 }));
 * @throws TopologyError with the `cannotRemesh` sentence when the mesh has other polygons than
 *   triangles, or none (nothing is changed); InvalidInputError for bad options.
 */
export function remeshing(mesh: HalfedgeMesh, options: RemeshingOptions = {}): Operation {
  requireApplicable(mesh, options);
  return remeshingPhases(mesh, settingsOf(mesh, options), true);
}

/**
 * Remeshes `mesh` in place, straight through, and compacts it. The mesh is renumbered first
 * (`spatialOrder`), so that neighbours are near each other in memory: every step walks the whole
 * mesh and looks up the input surface near each vertex, and in the order of a mesh refined level
 * by level most of those reads would miss the cache (the projection alone took four times as long).
 * @example remesh(mesh, { targetEdgeLength: 0.7 * meanEdgeLength(mesh) }); // about twice the triangles
 * @throws as `remeshing`.
 */
export function remesh(mesh: HalfedgeMesh, options: RemeshingOptions = {}): void {
  requireApplicable(mesh, options);
  const settings = settingsOf(mesh, options);
  spatialOrder(mesh);
  const phases = remeshingPhases(mesh, settings, false);
  while (!phases.next().done) {
    // straight through: the phases matter only when stepping
  }
  // collect the garbage: the collapses left deleted slots, and the splits grew the arrays
  mesh.compact();
}

/** The phases; `recording` false leaves their records and values out (a run straight through). */
function* remeshingPhases(mesh: HalfedgeMesh, settings: RemeshingSettings, recording: boolean): Operation {
  const { targetEdgeLength: L, iterations } = settings;
  const remesher = new Remesher(mesh, L);
  const length = +L.toPrecision(3);
  // one record per phase when stepping, and one writer writing it
  let recorder: ChangeRecorder | null = null;
  const record = () => (recorder = recording ? new ChangeRecorder(mesh) : null);
  const writer = () => new PointerWriter(mesh, { recorder: record(), ids: false });
  const recorded = (): Partial<Phase> => (recorder ? { change: recorder.record() } : {});

  for (let i = 1; i <= iterations; i++) {
    const of = `iteration ${i} of ${iterations}`;

    // split long edges
    let w = writer();
    remesher.splitLongEdges(w);
    yield {
      name: `split long edges (${of})`,
      explanation:
        `Every edge longer than 4/3 of the target length L = ${length} is split at its midpoint, and the triangles beside it are split through the new vertex. ` +
        'New edges that are still too long are split in turn, so afterwards no edge is longer than 4/3 L.',
      ...recorded(),
    };

    // collapse short edges
    w = writer();
    remesher.collapseShortEdges(w);
    yield {
      name: `collapse short edges (${of})`,
      explanation:
        'Every edge shorter than 4/5 L shrinks to a point, unless that would break the surface (the link condition), turn a triangle over, or make an edge longer than 4/3 L. ' +
        'Two inside vertices merge at their midpoint (or at one end, where the midpoint is too far from a neighbour), while an edge that reaches the boundary keeps its boundary end, so the rim keeps its shape.',
      ...recorded(),
    };

    // flip edges towards valence 6
    w = writer();
    remesher.flipToValence(w);
    yield {
      name: `flip edges towards valence 6 (${of})`,
      explanation:
        'An edge between two triangles is flipped when that brings its two ends and the two corners facing it closer to the valence of a regular mesh: 6 edges at a vertex inside, 4 on the boundary. ' +
        'Regular valences let the next step make the triangles nearly equilateral.',
      ...recorded(),
    };

    // smooth and project
    const distances = recording ? new Float32Array(mesh.vertexSlots) : null;
    record()?.valueRange('vertex', 0, mesh.vertexSlots);
    remesher.smoothAndProject(distances);
    yield {
      name: `smooth and project (${of})`,
      explanation:
        `Each vertex moves ${TANGENTIAL_STEP === 0.2 ? 'a fifth' : TANGENTIAL_STEP} of the way towards the centroid of its neighbours, but only along the surface (in its tangent plane), every new place worked out from the old ones before any vertex moves. ` +
        'Then each inside vertex goes to the nearest point of the input surface, so the triangles even out while the shape stays; the colours show how far each vertex went.',
      ...recorded(),
      ...(distances ? { values: { vertices: distances } } : {}),
    };
  }
}

function requireApplicable(mesh: HalfedgeMesh, options: RemeshingOptions): void {
  const reason = cannotRemesh(mesh, options);
  if (reason !== null) throw new TopologyError(reason);
}

function checkOptions(options: RemeshingOptions): void {
  const { targetEdgeLength, iterations = 3 } = options;
  if (targetEdgeLength !== undefined && !(targetEdgeLength > 0 && targetEdgeLength < Infinity)) {
    throw new InvalidInputError(`remeshing: targetEdgeLength must be a number > 0, not ${targetEdgeLength}`);
  }
  if (!Number.isInteger(iterations) || iterations < 0) {
    throw new InvalidInputError(`remeshing: iterations must be a whole number ≥ 0, not ${iterations}`);
  }
}

/** Fills in the defaults (checked by `cannotRemesh` first). */
function settingsOf(mesh: HalfedgeMesh, options: RemeshingOptions): RemeshingSettings {
  return { targetEdgeLength: options.targetEdgeLength ?? meanEdgeLength(mesh), iterations: options.iterations ?? 3 };
}
