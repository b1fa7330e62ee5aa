/**
 * Counts and topology of a mesh: V, E, F, boundary loops, connected components, the Euler
 * characteristic χ = V − E + F and, for each orientable component, its genus from
 * χ = 2 − 2g − b (b = number of boundary loops).
 */
import { type ChangeRecord, forEachPointerWrite } from './change/record.js';
import { componentRoots } from './components.js';
import { boundingBox, type BoundingBox, signedVolume, surfaceArea, triangleQuality, type TriangleQuality } from './geometry.js';
import type { HalfedgeMesh } from './mesh.js';
import { meshArrayIndex, meshArrays } from './mesh-arrays.js';
import type { BuildReport } from './report.js';

export interface ComponentStats {
  vertices: number;
  edges: number;
  faces: number;
  boundaryLoops: number;
  eulerCharacteristic: number;
  /** Null for a non-orientable component. */
  genus: number | null;
  orientable: boolean;
  closed: boolean;
}

export interface MeshStats {
  vertices: number;
  edges: number;
  faces: number;
  halfedges: number;
  boundaryEdges: number;
  boundaryLoops: number;
  /** Connected pieces made of faces (isolated vertices are counted apart). */
  components: number;
  isolatedVertices: number;
  eulerCharacteristic: number;
  /** Sum of the components' genera; null with no faces or when a component is non-orientable. */
  genus: number | null;
  /**
   * Each component's genus, in the order of `componentDetails`; null for a non-orientable one. Two
   * tori read `[1, 1]`, where `genus` alone (2) would say one double torus.
   */
  genusPerPart: (number | null)[];
  closed: boolean;
  /** False when the build had to split non-manifold edges or vertices. */
  manifold: boolean;
  /** False when the build had to cut a non-orientable surface open. */
  orientable: boolean;
  /** Face degree → number of faces. */
  faceDegrees: Record<number, number>;
  boundingBox: BoundingBox | null;
  surfaceArea: number;
  /** Enclosed volume of a closed mesh, null otherwise. */
  volume: number | null;
  triangleQuality: TriangleQuality | null;
  componentDetails: ComponentStats[];
}

/**
 * Computes the statistics of `mesh`. Pass the build report to carry what the build learned about
 * the input (manifold, orientable) into the flags.
 */
export function meshStats(mesh: HalfedgeMesh, report?: BuildReport): MeshStats {
  const { heNext, heVertex, heFace, eDeleted } = mesh;
  const nH = mesh.halfedgeSlots;

  // components: numbered in the order they are first met, each vertex's part named by its root
  const roots = componentRoots(mesh);
  const componentOf = new Int32Array(mesh.vertexSlots).fill(-1);
  const components: ComponentStats[] = [];
  const componentAt = (v: number): ComponentStats => {
    const root = roots[v];
    if (componentOf[root] === -1) {
      componentOf[root] = components.length;
      components.push({
        vertices: 0,
        edges: 0,
        faces: 0,
        boundaryLoops: 0,
        eulerCharacteristic: 0,
        genus: null,
        orientable: true,
        closed: true,
      });
    }
    return components[componentOf[root]];
  };

  let isolatedVertices = 0;
  for (const v of mesh.vertices()) {
    if (mesh.vHalfedge[v] === -1) isolatedVertices++;
    else componentAt(v).vertices++;
  }
  let boundaryEdges = 0;
  for (const e of mesh.edges()) {
    componentAt(heVertex[2 * e]).edges++;
    if (heFace[2 * e] === -1 || heFace[2 * e + 1] === -1) boundaryEdges++;
  }
  const faceDegrees: Record<number, number> = {};
  for (const f of mesh.faces()) {
    componentAt(heVertex[mesh.fHalfedge[f]]).faces++;
    const degree = mesh.faceDegree(f);
    faceDegrees[degree] = (faceDegrees[degree] ?? 0) + 1;
  }
  let boundaryLoops = 0;
  const seen = new Uint8Array(nH);
  for (let h = 0; h < nH; h++) {
    if (heFace[h] !== -1 || seen[h] || eDeleted[h >> 1]) continue;
    boundaryLoops++;
    const component = componentAt(heVertex[h]);
    component.boundaryLoops++;
    component.closed = false;
    let g = h;
    do {
      seen[g] = 1;
      g = heNext[g];
    } while (g !== h && !seen[g]);
  }
  for (const incident of nonOrientableIncidents(report)) {
    for (const f of incident.faces ?? []) {
      if (f < mesh.faceSlots && !mesh.fDeleted[f]) componentAt(heVertex[mesh.fHalfedge[f]]).orientable = false;
    }
  }
  for (const c of components) {
    c.eulerCharacteristic = c.vertices - c.edges + c.faces;
    c.genus = c.orientable ? (2 - c.boundaryLoops - c.eulerCharacteristic) / 2 : null;
  }

  const orientable = (report?.orientable ?? true) && components.every((c) => c.orientable);
  const closed = boundaryLoops === 0;
  const manifold = !report?.repairs.some((r) => r.kind === 'non-manifold-edge' || r.kind === 'non-manifold-vertex');
  return {
    vertices: mesh.nVertices,
    edges: mesh.nEdges,
    faces: mesh.nFaces,
    halfedges: mesh.nHalfedges,
    boundaryEdges,
    boundaryLoops,
    components: components.length,
    isolatedVertices,
    eulerCharacteristic: mesh.nVertices - mesh.nEdges + mesh.nFaces,
    genus:
      components.length > 0 && components.every((c) => c.genus !== null)
        ? components.reduce((sum, c) => sum + (c.genus ?? 0), 0)
        : null,
    genusPerPart: components.map((c) => c.genus),
    closed,
    manifold,
    orientable,
    faceDegrees,
    ...geometryStats(mesh, closed),
    componentDetails: components,
  };
}

/** The statistics that depend on where the vertices are; `closed`: whether the mesh has no boundary (then it has a volume). */
export function geometryStats(mesh: HalfedgeMesh, closed: boolean): Pick<MeshStats, 'boundingBox' | 'surfaceArea' | 'volume' | 'triangleQuality'> {
  return {
    boundingBox: boundingBox(mesh),
    surfaceArea: surfaceArea(mesh),
    volume: closed && mesh.nFaces > 0 ? signedVolume(mesh) : null,
    triangleQuality: triangleQuality(mesh),
  };
}

const { heFace: FACE, eDeleted: EDGE_DELETED } = meshArrayIndex;

/**
 * How far a change moved the count of boundary edges (`MeshStats.boundaryEdges`), read off its
 * record instead of a pass over the mesh. An edge is a boundary edge while it is live and one of
 * its halfedges has no face, so only the edges whose faces or flag the record writes can have
 * changed; an edge the change brings into use or gives up is among them, since an edge borders a
 * face. `mesh` is the mesh after the change.
 * @example stats.boundaryEdges += boundaryEdgesChange(mesh, splitEdge(mesh, e).record!);
 */
export function boundaryEdgesChange(mesh: HalfedgeMesh, record: ChangeRecord): number {
  const { before, after } = record;
  const faceBefore = new Map<number, number>();
  const deletedBefore = new Map<number, number>();
  const edges = new Set<number>();
  forEachPointerWrite(record, (array, index, old) => {
    if (array === FACE) {
      faceBefore.set(index, old);
      edges.add(index >> 1);
    } else if (array === EDGE_DELETED) {
      deletedBefore.set(index, old);
      edges.add(index);
    }
  });

  // a field the record does not write was as it is now; on a slot the change gave up, as a new
  // element starts (the change that brought it into use left it so: see applyChange)
  const faceThen = (h: number) => faceBefore.get(h) ?? (h < 2 * after.edgeSlots ? mesh.heFace[h] : meshArrays[FACE].initial);
  const deletedThen = (e: number) => deletedBefore.get(e) ?? (e < after.edgeSlots ? mesh.eDeleted[e] : meshArrays[EDGE_DELETED].initial);
  const wasBoundary = (e: number) => e < before.edgeSlots && deletedThen(e) === 0 && (faceThen(2 * e) === -1 || faceThen(2 * e + 1) === -1);
  const isBoundary = (e: number) => e < after.edgeSlots && mesh.eDeleted[e] === 0 && (mesh.heFace[2 * e] === -1 || mesh.heFace[2 * e + 1] === -1);
  let change = 0;
  for (const e of edges) change += Number(isBoundary(e)) - Number(wasBoundary(e));
  return change;
}

function nonOrientableIncidents(report: BuildReport | undefined) {
  return report?.repairs.find((r) => r.kind === 'non-orientable')?.incidents ?? [];
}
