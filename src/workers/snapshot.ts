/**
 * The snapshot the session sends after every change: a copy of the mesh arrays (the page builds
 * its own read-only `HalfedgeMesh` over them), the triangles to draw, and the counts and checks
 * the page shows. Everything heavy is computed here, in the worker, so the page only uploads
 * buffers.
 */
import { type HalfedgeMesh, meshStats, serializeMesh, validate } from '../core/index.js';
import { triangulateFaces } from './triangulate.js';
import type { Snapshot } from './protocol.js';

export function makeSnapshot(mesh: HalfedgeMesh, extras: Omit<Snapshot, 'mesh' | 'render' | 'stats' | 'problems'>): Snapshot {
  return {
    ...extras,
    mesh: serializeMesh(mesh),
    render: triangulateFaces(mesh),
    stats: meshStats(mesh, extras.report ?? undefined),
    problems: validate(mesh, { limit: 200 }),
  };
}
