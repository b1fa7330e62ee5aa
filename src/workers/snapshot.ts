/**
 * The snapshot the session sends after every change: a copy of the mesh arrays (the page builds
 * its own read-only `HalfedgeMesh` over them), buffers ready to draw, and the counts and checks
 * the page shows. Everything that takes time in proportion to the mesh is computed here, in the
 * worker, so the page's thread only uploads buffers and stays responsive.
 */
import { cannotDecimate, faceNormal, type HalfedgeMesh, meshStats, serializeMesh, validate } from '../core/index.js';
import { cannotSmooth } from '../core/smoothing/index.js';
import { cannotSubdivide, subdivisionSchemes } from '../core/subdivision/index.js';
import { PICK_IN_WORKER_ABOVE, type RenderBuffers, type Snapshot } from './protocol.js';
import { triangulateFaces } from './triangulate.js';

type Computed = 'mesh' | 'render' | 'stats' | 'problems' | 'unavailable';

export function makeSnapshot(mesh: HalfedgeMesh, extras: Omit<Snapshot, Computed>): Snapshot {
  return {
    ...extras,
    mesh: serializeMesh(mesh),
    render: renderBuffers(mesh),
    stats: meshStats(mesh, extras.report ?? undefined),
    problems: validate(mesh, { limit: 200 }),
    unavailable: unavailable(mesh),
  };
}

/** The checks of every face that the page would otherwise run on its thread. */
function unavailable(mesh: HalfedgeMesh): Snapshot['unavailable'] {
  const reasons = Object.fromEntries(subdivisionSchemes.map((scheme) => [scheme, cannotSubdivide(mesh, scheme)]));
  return {
    ...reasons,
    cotan: cannotSmooth(mesh, { method: 'cotan' }),
    decimate: cannotDecimate(mesh),
  } as Snapshot['unavailable'];
}

export function renderBuffers(mesh: HalfedgeMesh): RenderBuffers {
  const edges = new Uint32Array(2 * mesh.nEdges);
  let n = 0;
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (mesh.eDeleted[e]) continue;
    edges[n++] = mesh.heVertex[2 * e];
    edges[n++] = mesh.heVertex[2 * e + 1];
  }
  const vertices = new Uint32Array(mesh.nVertices);
  n = 0;
  for (let v = 0; v < mesh.vertexSlots; v++) if (!mesh.vDeleted[v]) vertices[n++] = v;
  const positions = new Float32Array(mesh.positions.subarray(0, 3 * mesh.vertexSlots));
  const { triangles, triangleFace } = triangulateFaces(mesh);
  return {
    positions,
    triangles,
    triangleFace,
    edges,
    vertices,
    planeNormal: planeNormal(mesh),
    picking: triangles.length / 3 > PICK_IN_WORKER_ABOVE ? { positions: positions.slice(), triangles: triangles.slice() } : null,
  };
}

/** The normal of the plane every face lies in (a 2D mesh), or null. */
export function planeNormal(mesh: HalfedgeMesh): [number, number, number] | null {
  let reference: number[] | null = null;
  const n = [0, 0, 0];
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (mesh.fDeleted[f]) continue;
    faceNormal(mesh, f, n);
    if (n[0] === 0 && n[1] === 0 && n[2] === 0) continue;
    if (!reference) reference = [...n];
    else if (Math.abs(reference[0] * n[0] + reference[1] * n[1] + reference[2] * n[2]) < 0.9999) return null;
  }
  return reference as [number, number, number] | null;
}
