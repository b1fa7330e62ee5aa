/**
 * Counts and topology of a mesh: V, E, F, boundary loops, connected components, the Euler
 * characteristic χ = V − E + F and, for each orientable component, its genus from
 * χ = 2 − 2g − b (b = number of boundary loops).
 */
import { boundingBox, type BoundingBox, signedVolume, surfaceArea, triangleQuality, type TriangleQuality } from './geometry.js';
import type { HalfedgeMesh } from './mesh.js';
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

  // components: union the two ends of every edge
  const parent = new Int32Array(mesh.vertexSlots);
  for (let v = 0; v < parent.length; v++) parent[v] = v;
  const find = (v: number): number => {
    while (parent[v] !== v) {
      parent[v] = parent[parent[v]];
      v = parent[v];
    }
    return v;
  };
  for (let e = 0; e < mesh.edgeSlots; e++) {
    if (eDeleted[e]) continue;
    const a = find(heVertex[2 * e]);
    const b = find(heVertex[2 * e + 1]);
    if (a !== b) parent[a < b ? b : a] = a < b ? a : b;
  }
  const componentOf = new Int32Array(mesh.vertexSlots).fill(-1);
  const components: ComponentStats[] = [];
  const componentAt = (v: number): ComponentStats => {
    const root = find(v);
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
    closed,
    manifold,
    orientable,
    faceDegrees,
    boundingBox: boundingBox(mesh),
    surfaceArea: surfaceArea(mesh),
    volume: closed && mesh.nFaces > 0 ? signedVolume(mesh) : null,
    triangleQuality: triangleQuality(mesh),
    componentDetails: components,
  };
}

function nonOrientableIncidents(report: BuildReport | undefined) {
  return report?.repairs.find((r) => r.kind === 'non-orientable')?.incidents ?? [];
}
