/**
 * Every halfedge drawn as a flat arrow in its face's plane, one instance each (instanced drawing
 * keeps tens of thousands smooth). Boundary halfedges get a dashed arrow in grey, outside the
 * surface. On very large meshes only the arrows near a focus (the selection, or the centre of the
 * view) are drawn, and the layer says how many.
 */
import {
  BufferGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  Matrix4,
  MeshBasicMaterial,
  Vector3,
} from 'three';
import type { HalfedgeMesh } from '../../core/index.js';
import { colors } from '../colors.js';
import { newPlacement, placeArrow, type ArrowPlacement } from './arrow-placement.js';

/** Beyond this many halfedges, draw only those near the focus. */
export const MAX_ARROWS = 120_000;

/** A flat arrow from (0,0) to (1,0), head 1 wide; `dashes` breaks the shaft into pieces. */
export function arrowShape(dashes: number): BufferGeometry {
  const points: number[] = [];
  const quad = (x0: number, x1: number, half: number) =>
    points.push(x0, -half, 0, x1, -half, 0, x1, half, 0, x0, -half, 0, x1, half, 0, x0, half, 0);
  const headStart = 0.78;
  const shaftHalfWidth = 0.18;
  if (dashes <= 1) quad(0, headStart + 0.02, shaftHalfWidth);
  else {
    const piece = headStart / (2 * dashes - 1);
    for (let i = 0; i < dashes; i++) quad(2 * i * piece, (2 * i + 1) * piece, shaftHalfWidth);
  }
  points.push(headStart, -0.5, 0, 1, 0, 0, headStart, 0.5, 0);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
  return geometry;
}

const interiorShape = arrowShape(1);
const boundaryShape = arrowShape(3);

/** The matrix that maps the unit arrow onto a placement. */
export function arrowMatrix(placement: ArrowPlacement, out: Matrix4, widthScale = 1): Matrix4 {
  const start = new Vector3(...placement.start);
  const along = new Vector3(...placement.end).sub(start);
  const normal = new Vector3(...placement.normal);
  const across = new Vector3().crossVectors(normal, along).normalize().multiplyScalar(placement.width * widthScale);
  return out.makeBasis(along, across, normal.multiplyScalar(placement.width)).setPosition(start);
}

export class ArrowLayer {
  readonly group = new Group();
  /** Halfedges drawn (all of them, or those near the focus). */
  shown: Int32Array = new Int32Array(0);
  private readonly interiorMaterial = new MeshBasicMaterial({ color: colors.halfedge, side: DoubleSide });
  private readonly boundaryMaterial = new MeshBasicMaterial({ color: colors.boundary, side: DoubleSide });

  /** Draws the arrows of `halfedges` (every live halfedge when null). */
  update(mesh: HalfedgeMesh, halfedges: Int32Array | null, scale: number): void {
    this.dispose();
    this.shown = halfedges ?? liveHalfedges(mesh);
    let boundaryCount = 0;
    for (const h of this.shown) if (mesh.heFace[h] === -1) boundaryCount++;
    const interior = new InstancedMesh(interiorShape, this.interiorMaterial, this.shown.length - boundaryCount);
    const boundary = new InstancedMesh(boundaryShape, this.boundaryMaterial, boundaryCount);
    const placement = newPlacement();
    const matrix = new Matrix4();
    let i = 0;
    let b = 0;
    for (const h of this.shown) {
      arrowMatrix(placeArrow(mesh, h, placement, scale), matrix);
      if (placement.boundary) boundary.setMatrixAt(b++, matrix);
      else interior.setMatrixAt(i++, matrix);
    }
    for (const arrows of [interior, boundary]) {
      arrows.instanceMatrix.needsUpdate = true;
      arrows.computeBoundingSphere();
      arrows.raycast = () => {}; // picking measures distances to arrows itself
    }
    this.group.add(interior, boundary);
  }

  private dispose(): void {
    for (const child of [...this.group.children]) {
      (child as InstancedMesh).dispose();
      this.group.remove(child);
    }
  }
}

export function liveHalfedges(mesh: HalfedgeMesh): Int32Array {
  const live = new Int32Array(mesh.nHalfedges);
  let n = 0;
  for (let h = 0; h < mesh.halfedgeSlots; h++) if (!mesh.eDeleted[h >> 1]) live[n++] = h;
  return live;
}

/**
 * The halfedges of the faces nearest `focus` (grown face by face across edges), up to `limit`,
 * with the boundary halfedges beside them: what to draw when drawing all is too much.
 */
export function halfedgesNear(mesh: HalfedgeMesh, focusFace: number, limit = MAX_ARROWS): Int32Array {
  const chosen: number[] = [];
  const seen = new Uint8Array(mesh.faceSlots);
  const queue = [focusFace];
  seen[focusFace] = 1;
  for (let i = 0; i < queue.length && chosen.length < limit; i++) {
    const f = queue[i];
    const start = mesh.fHalfedge[f];
    let h = start;
    do {
      chosen.push(h);
      const across = mesh.heFace[h ^ 1];
      if (across === -1) chosen.push(h ^ 1);
      else if (!seen[across]) {
        seen[across] = 1;
        queue.push(across);
      }
      h = mesh.heNext[h];
    } while (h !== start);
  }
  return Int32Array.from(chosen);
}
