/**
 * The plane cut: cut a mesh with the plane a·x + b·y + c·z + d = 0, really cutting it (new
 * vertices where edges cross, faces split along the plane, the two sides pulled apart), then
 * optionally keep one side and cap the cut with flat faces.
 *
 * ```
 *        ╭──────╮               ╭──────╮
 *       ╱        ╲             ╱ above  ╲               ╭──────╮
 *   ┄┄┄┼┄┄┄┄┄┄┄┄┄┄┼┄┄┄  ──►   ○──────────○     ──►      ╱        ╲
 *      │          │           ○──────────○            ●━━━━━━━━━━●  ← cap
 *       ╲        ╱             ╲ below  ╱
 *        ╰──────╯               ╰──────╯
 *   a mesh and a plane      cut, the sides apart      one side kept, capped
 * ```
 * The phases, each leaving a valid mesh:
 *   1. classify vertices by signed distance (snapping those within the tolerance onto the plane);
 *   2. split every edge that crosses the plane at the crossing point;
 *   3. split every face the plane crosses along the plane (`split-faces.ts`);
 *   4. separate the sides: cut edges and cut vertices are duplicated (`separate.ts`);
 *   5. remove one side (unless both are kept, as separate pieces);
 *   6. cap each loop of the cut with triangulated faces (`caps.ts`).
 * A face lying in the plane belongs to the side behind it (the one its normal points away from),
 * so a cube cut along its bottom face keeps that face, above the plane.
 *
 * Cost: phases 1, 2, 4 and 5 are passes over typed arrays (vertices, edges, faces); only the
 * faces and vertices at the cut get individual work, and the caps are triangulated per loop.
 * Deleted elements are marked, not compacted, so ids stay stable from phase to phase.
 */
import { splitEdgeAt } from '../edits/split-edge.js';
import { PointerWriter } from '../change/writer.js';
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import { type ElementIds, type Operation, type Phase, runOperation } from '../change/operation.js';
import { ChangeRecorder } from '../change/recorder.js';
import { capLoops } from './caps.js';
import { type Plane, type UnitPlane, unitPlane } from './plane.js';
import { faceSides, separateSides } from './separate.js';
import { splitCrossedFaces } from './split-faces.js';

export type KeepSide = 'above' | 'below' | 'both';

export interface PlaneCutOptions {
  /**
   * What to keep: the side 'above' (a·x + b·y + c·z + d > 0), the side 'below', or 'both' as
   * separate pieces of one mesh (the default).
   */
  keep?: KeepSide;
  /** Close each loop of the cut with a flat, triangulated cap (default true). */
  cap?: boolean;
  /**
   * Vertices closer to the plane than this times the mesh's size (its bounding-box diagonal)
   * count as on the plane and are moved onto it (default 1e-10).
   */
  tolerance?: number;
  /** Whether each phase carries its change record (default true: a cut stepped in the app; `cutMesh` runs without). */
  record?: boolean;
}

/**
 * The plane cut as a steppable operation: six phases (see above), each yielding what it did.
 * @example
 *   for (const phase of planeCut(mesh, [0, 0, 1, -0.1], { keep: 'below' })) show(phase);
 * @throws InvalidInputError for a plane that is not four finite numbers with (a, b, c) ≠ 0, or a
 *   bad option (right away, before any phase runs).
 */
export function planeCut(mesh: HalfedgeMesh, plane: Plane, options: PlaneCutOptions = {}): Operation {
  const unit = unitPlane(plane);
  const keep = options.keep ?? 'both';
  if (keep !== 'above' && keep !== 'below' && keep !== 'both') {
    throw new InvalidInputError(`keep must be 'above', 'below' or 'both', not '${String(keep)}'`);
  }
  const tolerance = options.tolerance ?? 1e-10;
  if (!(tolerance >= 0 && Number.isFinite(tolerance))) {
    throw new InvalidInputError(`the tolerance must be a finite number ≥ 0, not ${tolerance}`);
  }
  return cutInPhases(new PlaneCut(mesh, unit, options.record ?? true), keep, options.cap ?? true, tolerance);
}

/**
 * Cuts `mesh` in one go: runs `planeCut` to the end and returns its phases.
 * @example cutMesh(mesh, { a: 0, b: 0, c: 1, d: 0 }, { keep: 'above' }); // the upper half, capped
 */
export function cutMesh(mesh: HalfedgeMesh, plane: Plane, options: PlaneCutOptions = {}): Phase[] {
  return runOperation(planeCut(mesh, plane, { record: false, ...options }));
}

function* cutInPhases(cut: PlaneCut, keep: KeepSide, cap: boolean, tolerance: number): Operation {
  yield cut.classifyVertices(tolerance);
  yield cut.splitCrossingEdges();
  yield cut.splitCrossedFaces();
  yield cut.separateSides();
  yield cut.removeSide(keep);
  yield cut.capLoops(cap ? (keep === 'both' ? [1, -1] : keep === 'above' ? [1] : [-1]) : []);
}

/** What the phases hand on to each other. */
class PlaneCut {
  /** +1 above, −1 below, 0 on the plane, per vertex (vertices made by phase 2 included). */
  private side: Int8Array = new Int8Array(0);
  /** Signed distance of each vertex of the input (0 for those snapped onto the plane). */
  private distance: Float64Array = new Float64Array(0);
  /** The vertices on the plane. */
  private readonly onPlane: number[] = [];
  /** +1 or −1 per face, from phase 4 on. */
  private faceSide: Int8Array = new Int8Array(0);
  /** The edges along the cut after phase 4: both copies of each. */
  private readonly cutEdges: number[] = [];

  /** The record of the phase under way (null: not recording). */
  private recorder: ChangeRecorder | null = null;

  constructor(
    private readonly mesh: HalfedgeMesh,
    private readonly plane: UnitPlane,
    private readonly recording: boolean,
  ) {}

  /** Starts the record of a phase (when recording); returns it. */
  private record(): ChangeRecorder | null {
    return (this.recorder = this.recording ? new ChangeRecorder(this.mesh) : null);
  }

  /** The phase's record, for its `Phase`. */
  private recorded(): Pick<Phase, 'change'> {
    return this.recorder ? { change: this.recorder.record() } : {};
  }

  classifyVertices(tolerance: number): Phase {
    const { mesh, onPlane } = this;
    const { nx, ny, nz, d } = this.plane;
    const { positions: p, vDeleted } = mesh;
    const n = mesh.vertexSlots;
    const epsilon = tolerance * diagonal(mesh);
    const side = (this.side = new Int8Array(n));
    const distance = (this.distance = new Float64Array(n));
    const values = new Float32Array(n);
    const recorder = this.record();
    let moved = 0;
    let above = 0;
    let below = 0;
    for (let v = 0; v < n; v++) {
      if (vDeleted[v]) continue;
      const i = 3 * v;
      const s = nx * p[i] + ny * p[i + 1] + nz * p[i + 2] + d;
      values[v] = s;
      if (s > epsilon) {
        side[v] = 1;
        distance[v] = s;
        above++;
      } else if (s < -epsilon) {
        side[v] = -1;
        distance[v] = s;
        below++;
      } else {
        onPlane.push(v);
        if (s !== 0) {
          // snap: move along the normal by the distance
          recorder?.element('vertex', v);
          p[i] -= s * nx;
          p[i + 1] -= s * ny;
          p[i + 2] -= s * nz;
          moved++;
        }
      }
    }
    const crosses = above > 0 && below > 0;
    return {
      name: 'classify vertices',
      explanation:
        `Each vertex gets its signed distance to the plane: ${above} are above it, ${below} below and ${onPlane.length} on it ` +
        `(within ${epsilon.toPrecision(2)}, the tolerance times the mesh's size; ${moved} of those were moved onto it, so the cut makes no sliver faces and no second vertex beside them). ` +
        (crosses
          ? 'Where an edge or a face has vertices on both sides, the next phases cut it.'
          : 'No edge or face has vertices on both sides: the plane does not cross the mesh, and the next phases find nothing to cut.'),
      values: { vertices: values },
      ...this.recorded(),
    };
  }

  splitCrossingEdges(): Phase {
    const { mesh, onPlane, distance, side } = this;
    const { heVertex, eDeleted } = mesh;
    const crossing: number[] = [];
    for (let e = 0; e < mesh.edgeSlots; e++) {
      if (!eDeleted[e] && side[heVertex[2 * e]] * side[heVertex[2 * e + 1]] < 0) crossing.push(e);
    }
    // room for everything the cut will add, so the arrays grow (and are copied) once
    const k = crossing.length + onPlane.length;
    mesh.reserve({ vertices: mesh.vertexSlots + 2 * k, edges: mesh.edgeSlots + 5 * k, faces: mesh.faceSlots + 3 * k });

    const w = new PointerWriter(mesh, { recorder: this.record() });
    for (const e of crossing) {
      const a = distance[mesh.heVertex[2 * e]];
      const b = distance[mesh.heVertex[2 * e + 1]];
      onPlane.push(splitEdgeAt(w, e, a / (a - b)));
    }
    // the new vertices are on the plane: side 0
    this.side = new Int8Array(mesh.vertexSlots);
    this.side.set(side);
    return {
      name: 'split crossing edges',
      explanation:
        `${crossing.length} edges run from one side to the other; each gets a new vertex where it meets the plane, at the fraction d(a) / (d(a) − d(b)) of the way from a to b, with its attributes blended the same way. ` +
        'The faces beside them gain a corner on the plane, and no edge crosses the plane any more.',
      ...this.recorded(),
    };
  }

  splitCrossedFaces(): Phase {
    const w = new PointerWriter(this.mesh, { recorder: this.record() });
    const { split, midpoints } = splitCrossedFaces(w, this.side, this.onPlane, this.plane);
    // the vertices halfway along new edges are on the plane: side 0
    this.onPlane.push(...midpoints);
    const side = this.side;
    this.side = new Int8Array(this.mesh.vertexSlots);
    this.side.set(side);
    return {
      name: 'split crossed faces',
      explanation:
        `${split.length} faces have corners on both sides; each is cut by new edges between its corners on the plane (a face crossed twice, like a U, gets two; two corners already joined round the other way are joined through a new vertex halfway). ` +
        'Now every face lies on one side, touching the plane at most along its edges and corners.',
      ...this.recorded(),
    };
  }

  separateSides(): Phase {
    const { mesh } = this;
    this.faceSide = faceSides(mesh, this.side, this.plane);
    const w = new PointerWriter(mesh, { recorder: this.record() });
    const { cutEdges, newEdges, cutVertices } = separateSides(w, this.onPlane, this.faceSide);
    for (const e of cutEdges) this.cutEdges.push(e);
    for (const e of newEdges) this.cutEdges.push(e);
    const { created } = w.result();
    return {
      name: 'separate the sides',
      explanation:
        `The ${cutEdges.length} edges with a face above and a face below become two edges each, and the ${cutVertices.length} vertices on the cut one vertex per fan of faces (${created.vertices?.length ?? 0} copies). ` +
        'Above and below are now separate pieces of surface, each with the cut as a boundary.',
      values: { faces: Float32Array.from(this.faceSide) },
      ...this.recorded(),
    };
  }

  removeSide(keep: KeepSide): Phase {
    if (keep === 'both') {
      this.record();
      return {
        name: 'remove a side',
        explanation: 'Both sides are kept, as separate pieces of one mesh. Nothing is removed.',
        ...this.recorded(),
      };
    }
    const gone = keep === 'above' ? -1 : 1;
    // deleting a side writes flags across the whole mesh, not through a writer
    this.record()?.wholeMesh();
    const removed = deleteSide(this.mesh, this.faceSide, this.side, gone);
    return {
      name: 'remove a side',
      explanation:
        `The ${removed.faces!.length} faces ${keep === 'above' ? 'below' : 'above'} the plane are deleted, with the ${removed.edges!.length} edges and ${removed.vertices!.length} vertices only they used. ` +
        `What is left lies ${keep} the plane; the other elements keep their ids (deleted slots are only marked).`,
      ...this.recorded(),
    };
  }

  capLoops(sides: number[]): Phase {
    if (sides.length === 0) {
      this.record();
      return {
        name: 'cap the cut',
        explanation: 'Capping is off, so the cut stays open: each side keeps its loops of boundary edges. With capping on, each loop is filled with a flat polygon.',
        ...this.recorded(),
      };
    }
    const w = new PointerWriter(this.mesh, { recorder: this.record() });
    const { caps, fanned, faces, open } = capLoops(w, this.cutEdges, this.faceSide, this.plane, sides);
    const fanNote = fanned
      ? ` (${fanned === 1 ? 'one is' : `${fanned} are`} a fan from one corner, as ${fanned === 1 ? 'its outline crosses itself' : 'their outlines cross themselves'} where faces lie almost in the plane)`
      : '';
    const openNote = open.length
      ? `${open.length === 1 ? '1 loop stays' : `${open.length} loops stay`} open: ${open.map((o) => `the one through h${o.halfedge}, as ${o.reason}`).join('; ')}.`
      : 'A closed mesh cut this way stays closed.';
    return {
      name: 'cap the cut',
      explanation:
        `Each loop of cut edges is laid flat in the plane, a loop inside another running the other way becomes its hole, and ear clipping fills each outline: ${caps} cap${caps === 1 ? '' : 's'} of ${faces.length} triangles${fanNote}. ` +
        openNote,
      ...this.recorded(),
    };
  }
}

/**
 * Deletes the faces on side `gone`, the edges with no face left beside them, and the vertices
 * left with no edge (isolated vertices by their own side).
 */
function deleteSide(mesh: HalfedgeMesh, faceSide: Int8Array, side: Int8Array, gone: number): ElementIds {
  const { heVertex, heFace, vHalfedge, vDeleted, eDeleted, fDeleted } = mesh;
  const vertices = new Int32Array(mesh.vertexSlots);
  const edges = new Int32Array(mesh.edgeSlots);
  const faces = new Int32Array(mesh.faceSlots);
  let nv = 0;
  let ne = 0;
  let nf = 0;
  // a vertex stays when an edge that stays ends at it: mark them in the pass over the edges
  // (in order, unlike a look-up of each vertex's face)
  const kept = new Uint8Array(mesh.vertexSlots);
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (eDeleted[e]) continue;
    const f = heFace[2 * e];
    const g = heFace[2 * e + 1];
    if ((f === -1 || faceSide[f] === gone) && (g === -1 || faceSide[g] === gone)) {
      edges[ne++] = e;
    } else {
      kept[heVertex[2 * e]] = 1;
      kept[heVertex[2 * e + 1]] = 1;
    }
  }
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (!vDeleted[v] && !kept[v] && (vHalfedge[v] !== -1 || side[v] === gone)) vertices[nv++] = v;
  }
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (!fDeleted[f] && faceSide[f] === gone) faces[nf++] = f;
  }
  for (let i = 0; i < nv; i++) mesh.deleteVertex(vertices[i]);
  for (let i = 0; i < ne; i++) mesh.deleteEdge(edges[i]);
  for (let i = 0; i < nf; i++) mesh.deleteFace(faces[i]);
  return { vertices: vertices.slice(0, nv), edges: edges.slice(0, ne), faces: faces.slice(0, nf) };
}

/** Length of the bounding-box diagonal of the live vertices (0 for none). */
function diagonal(mesh: HalfedgeMesh): number {
  const { positions: p, vDeleted } = mesh;
  let minX = Infinity;
  let minY = Infinity;
  let minZ = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  let maxZ = -Infinity;
  for (let v = 0; v < mesh.vertexSlots; v++) {
    if (vDeleted[v]) continue;
    const x = p[3 * v];
    const y = p[3 * v + 1];
    const z = p[3 * v + 2];
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
    if (z < minZ) minZ = z;
    if (z > maxZ) maxZ = z;
  }
  return maxX >= minX ? Math.hypot(maxX - minX, maxY - minY, maxZ - minZ) : 0;
}
