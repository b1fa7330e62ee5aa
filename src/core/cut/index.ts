/**
 * The plane cut: `planeCut` steps through it phase by phase, `cutMesh` runs it in one go.
 * @example
 *   cutMesh(mesh, [0, 0, 1, 0], { keep: 'below' }); // the half below z = 0, capped
 */
export { cutMesh, type KeepSide, planeCut, type PlaneCutOptions } from './plane-cut.js';
export { type Plane, type UnitPlane, unitPlane } from './plane.js';
