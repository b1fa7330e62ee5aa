/**
 * The surface itself: flat-shaded faces (the back side in a darker shade, so a student sees which
 * way a face is oriented), every edge as a line, and vertices as dots while the mesh is small.
 * Picking casts rays against the triangles through a bounding-volume hierarchy (three-mesh-bvh).
 */
import {
  BackSide,
  BufferAttribute,
  BufferGeometry,
  FrontSide,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshStandardMaterial,
  Points,
  PointsMaterial,
  type Raycaster,
  Vector3,
} from 'three';
import { acceleratedRaycast, computeBoundsTree, disposeBoundsTree } from 'three-mesh-bvh';
import type { HalfedgeMesh } from '../../core/index.js';
import type { RenderBuffers } from '../../workers/protocol.js';
import { colors } from '../colors.js';

BufferGeometry.prototype.computeBoundsTree = computeBoundsTree;
BufferGeometry.prototype.disposeBoundsTree = disposeBoundsTree;
Mesh.prototype.raycast = acceleratedRaycast;

/** Draw vertices as dots up to this many. */
const MAX_DOTS = 1_000;

export interface SurfaceHit {
  face: number;
  point: Vector3;
}

export class SurfaceLayer {
  readonly group = new Group();
  private readonly faces = new BufferGeometry();
  private readonly lines = new BufferGeometry();
  private readonly vertices = new BufferGeometry();
  private readonly front: Mesh;
  private readonly back: Mesh;
  private readonly edges: LineSegments;
  private readonly dots: Points;
  private triangleFace: Int32Array = new Int32Array(0);

  constructor() {
    // the surface sits a little behind the arrows and lines drawn in its plane
    const offset = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 2 };
    this.front = new Mesh(this.faces, new MeshStandardMaterial({ color: colors.surface, flatShading: true, side: FrontSide, ...offset }));
    this.back = new Mesh(this.faces, new MeshStandardMaterial({ color: colors.surfaceBack, flatShading: true, side: BackSide, ...offset }));
    this.edges = new LineSegments(this.lines, new LineBasicMaterial({ color: colors.edge }));
    this.dots = new Points(this.vertices, new PointsMaterial({ color: colors.edge, size: 4, sizeAttenuation: false }));
    this.back.raycast = () => {}; // one hit per face is enough: the front mesh answers
    this.edges.raycast = () => {};
    this.dots.raycast = () => {};
    this.group.add(this.front, this.back, this.edges, this.dots);
  }

  update(mesh: HalfedgeMesh, render: RenderBuffers): void {
    const positions = new Float32Array(mesh.positions.subarray(0, 3 * mesh.vertexSlots));
    const position = new BufferAttribute(positions, 3);
    this.faces.disposeBoundsTree();
    this.faces.setAttribute('position', position);
    this.faces.setIndex(new BufferAttribute(render.triangles, 1));
    this.faces.computeBoundingSphere();
    this.faces.computeBoundingBox();
    // indirect: the BVH must not reorder the triangles, whose order maps them to their faces
    if (render.triangles.length > 0) this.faces.computeBoundsTree({ indirect: true });
    this.triangleFace = render.triangleFace;

    const ends = new Uint32Array(2 * mesh.edgeSlots);
    let n = 0;
    for (let e = 0; e < mesh.edgeSlots; e++) {
      if (mesh.eDeleted[e]) continue;
      ends[n++] = mesh.heVertex[2 * e];
      ends[n++] = mesh.heVertex[2 * e + 1];
    }
    this.lines.setAttribute('position', position);
    this.lines.setIndex(new BufferAttribute(ends.subarray(0, n), 1));
    this.lines.computeBoundingSphere();
    const live = new Uint32Array(mesh.nVertices);
    n = 0;
    for (let v = 0; v < mesh.vertexSlots; v++) if (!mesh.vDeleted[v]) live[n++] = v;
    this.vertices.setAttribute('position', position);
    this.vertices.setIndex(new BufferAttribute(live, 1));
    this.vertices.computeBoundingSphere();
    // a point set (no faces) shows its vertices however many there are
    this.dots.visible = mesh.nVertices <= MAX_DOTS || mesh.nFaces === 0;
  }

  /** The face under the ray, and where the ray meets it. */
  raycast(raycaster: Raycaster): SurfaceHit | null {
    raycaster.firstHitOnly = true;
    const hit = raycaster.intersectObject(this.front, false)[0];
    if (!hit || hit.faceIndex === undefined || hit.faceIndex === null) return null;
    return { face: this.triangleFace[hit.faceIndex], point: hit.point };
  }

  /** Line width and dot size, larger for a lecture hall. */
  setEmphasis(scale: number): void {
    (this.dots.material as PointsMaterial).size = 4 * scale;
  }
}
