/**
 * Subdivision: refine a mesh again and again, each level splitting every face into smaller ones and
 * moving the vertices by fixed weighted averages of their neighbours (*stencils*), so that the
 * levels converge to a smooth surface. Four classic schemes, and linear subdivision (Catmull-Clark's
 * topology with plain averages: the faces get smaller, the shape stays):
 *
 * | scheme        | faces        | each level                                      | old vertices          |
 * |---------------|--------------|-------------------------------------------------|-----------------------|
 * | Loop          | triangles    | a triangle becomes 4 (split edges, cut corners) | move (approximating)  |
 * | Catmull-Clark | any polygons | an n-gon becomes n quads                        | move (approximating)  |
 * | Butterfly     | triangles    | a triangle becomes 4, as in Loop                | stay (interpolating)  |
 * | √3            | triangles    | a triangle becomes 3 (face points, edge flips)  | move (approximating)  |
 * | linear        | any polygons | an n-gon becomes n quads, as in Catmull-Clark   | stay (plain averages) |
 *
 * Each scheme is a steppable operation (see `operation.ts`): one run is one level, done in
 * phases that each leave a valid mesh, named and explained for a student, with the ids of what
 * they created, moved and rewired. Topology and positions are separate phases, so a student sees
 * first how the connectivity is refined, then where the new points go. The shared topology (split
 * every edge, cut the corners, insert face points) lives in `topology.ts`; Loop, Butterfly,
 * Catmull-Clark and linear subdivision describe their level as data (counts, stencils, phases),
 * which `level.ts` runs.
 *
 * Attributes: vertex attributes of three floats that interpolate linearly (positions, normals,
 * float colours) follow the same stencils as positions; other vertex attributes (labels, integer
 * colours, texture coordinates) keep their values on old vertices and take one source vertex's
 * value on new ones (an edge point its edge's first end, a face point its face's first corner). A
 * face's attributes pass to every face cut from it (√3's flips then trade edges between those
 * pieces). Halfedge and edge attributes are removed: the schemes define no values for the corners
 * and edges they create.
 *
 * @example
 *   subdivide(mesh, 'loop', 2);                          // two levels, straight through
 *   for (const phase of catmullClark(mesh)) show(phase); // one level, phase by phase
 */
import { InvalidInputError } from '../errors.js';
import type { HalfedgeMesh } from '../mesh.js';
import type { Operation } from '../change/operation.js';
import { butterflyLevel, butterflySubdivision } from './butterfly.js';
import { catmullClark, catmullClarkLevel } from './catmull-clark.js';
import { levelPhases } from './level.js';
import { linearLevel, linearSubdivision } from './linear.js';
import { loopLevel, loopSubdivision } from './loop.js';
import { requireApplicable, type SubdivisionScheme, unknownScheme } from './preconditions.js';
import { type SubdivisionOptions, sqrt3Level, sqrt3Subdivision } from './sqrt3.js';

export { butterflySubdivision } from './butterfly.js';
export { catmullClark } from './catmull-clark.js';
export { type HelperThread, useHelperThread } from './helper-thread.js';
export { linearSubdivision } from './linear.js';
export { loopSubdivision } from './loop.js';
export { cannotSubdivide, type SubdivisionScheme, subdivisionSchemes } from './preconditions.js';
export { type SubdivisionOptions, sqrt3Subdivision } from './sqrt3.js';

/**
 * One level of `scheme` as a steppable operation (`options.level` matters to √3 only: it splits
 * the boundary on odd levels).
 * @throws TopologyError when the scheme does not apply (see `cannotSubdivide`); nothing is changed.
 * @throws InvalidInputError for an unknown scheme.
 */
export function subdivisionOperation(mesh: HalfedgeMesh, scheme: SubdivisionScheme, options: SubdivisionOptions = {}): Operation {
  switch (scheme) {
    case 'loop':
      return loopSubdivision(mesh);
    case 'catmull-clark':
      return catmullClark(mesh);
    case 'butterfly':
      return butterflySubdivision(mesh);
    case 'sqrt3':
      return sqrt3Subdivision(mesh, options);
    case 'linear':
      return linearSubdivision(mesh);
    default:
      return unknownScheme(scheme);
  }
}

/** Each scheme's phases, with or without their id lists. */
const phasesOf: Record<SubdivisionScheme, (mesh: HalfedgeMesh, recording: boolean, level: number) => Operation> = {
  loop: (mesh, recording) => levelPhases(mesh, loopLevel, recording),
  'catmull-clark': (mesh, recording) => levelPhases(mesh, catmullClarkLevel, recording),
  butterfly: (mesh, recording) => levelPhases(mesh, butterflyLevel, recording),
  sqrt3: sqrt3Level,
  linear: (mesh, recording) => levelPhases(mesh, linearLevel, recording),
};

/**
 * Subdivides `mesh` in place by `levels` levels of `scheme`, straight through (level i runs with
 * `{ level: i }`, so √3 alternates its boundary rule).
 * @example subdivide(mesh, 'catmull-clark', 3);
 * @throws TopologyError with the `cannotSubdivide` sentence when the scheme does not apply.
 * @throws InvalidInputError when `levels` is not a whole number ≥ 0 or the scheme is unknown.
 */
export function subdivide(mesh: HalfedgeMesh, scheme: SubdivisionScheme, levels = 1): void {
  if (!Object.hasOwn(phasesOf, scheme)) unknownScheme(scheme);
  if (!Number.isInteger(levels) || levels < 0) {
    throw new InvalidInputError(`subdivide: levels must be a whole number ≥ 0, not ${levels}`);
  }
  for (let level = 0; level < levels; level++) {
    requireApplicable(mesh, scheme);
    const phases = phasesOf[scheme](mesh, false, level);
    while (!phases.next().done) {
      // straight through: the phases matter only when stepping
    }
  }
}

