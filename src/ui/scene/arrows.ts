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
  MeshBasicMaterial,
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

/**
 * Writes the matrix that maps the unit arrow onto a placement into `out` at `offset` (column-major,
 * as three.js keeps it): straight into an instanced mesh's matrix array, as a hundred thousand
 * arrows must not make a hundred thousand matrices.
 */
export function writeArrowMatrix(placement: ArrowPlacement, out: { [index: number]: number }, offset: number, widthScale = 1): void {
  const { start, end, normal, width } = placement;
  const ax = end[0] - start[0];
  const ay = end[1] - start[1];
  const az = end[2] - start[2];
  // across = normal × along, scaled to the arrow's width
  const cx = normal[1] * az - normal[2] * ay;
  const cy = normal[2] * ax - normal[0] * az;
  const cz = normal[0] * ay - normal[1] * ax;
  const across = (width * widthScale) / (Math.hypot(cx, cy, cz) || 1);
  const o = offset;
  // columns: along, across, normal × width, start
  out[o] = ax;
  out[o + 1] = ay;
  out[o + 2] = az;
  out[o + 3] = 0;
  out[o + 4] = cx * across;
  out[o + 5] = cy * across;
  out[o + 6] = cz * across;
  out[o + 7] = 0;
  out[o + 8] = normal[0] * width;
  out[o + 9] = normal[1] * width;
  out[o + 10] = normal[2] * width;
  out[o + 11] = 0;
  out[o + 12] = start[0];
  out[o + 13] = start[1];
  out[o + 14] = start[2];
  out[o + 15] = 1;
}

export class ArrowLayer {
  readonly group = new Group();
  /** Halfedges drawn (all of them, or those near the focus). */
  shown: Int32Array = new Int32Array(0);
  private interior = arrowInstances(interiorShape, new MeshBasicMaterial({ color: colors.halfedge, side: DoubleSide }), 0);
  private boundary = arrowInstances(boundaryShape, new MeshBasicMaterial({ color: colors.boundary, side: DoubleSide }), 0);

  constructor() {
    this.group.add(this.interior, this.boundary);
  }

  /** Draws the arrows of `halfedges` (every live halfedge when null). */
  update(mesh: HalfedgeMesh, halfedges: Int32Array | null, scale: number): void {
    this.shown = halfedges ?? liveHalfedges(mesh);
    let boundaryCount = 0;
    for (const h of this.shown) if (mesh.face(h) === -1) boundaryCount++;
    const interior = (this.interior = this.withRoom(this.interior, this.shown.length - boundaryCount));
    const boundary = (this.boundary = this.withRoom(this.boundary, boundaryCount));
    const placement = newPlacement();
    let i = 0;
    let b = 0;
    for (const h of this.shown) {
      placeArrow(mesh, h, placement, scale);
      if (placement.boundary) writeArrowMatrix(placement, boundary.instanceMatrix.array, 16 * b++);
      else writeArrowMatrix(placement, interior.instanceMatrix.array, 16 * i++);
    }
    for (const arrows of [interior, boundary]) {
      arrows.instanceMatrix.clearUpdateRanges();
      arrows.instanceMatrix.addUpdateRange(0, 16 * arrows.count);
      arrows.instanceMatrix.needsUpdate = true;
    }
  }

  /**
   * `arrows` with `count` instances in use: the same object while it has room for them, as a new
   * one costs a loop that sets every instance to the identity and a fresh buffer on the GPU.
   */
  private withRoom(arrows: InstancedMesh, count: number): InstancedMesh {
    if (count > arrows.instanceMatrix.count) {
      const larger = arrowInstances(arrows.geometry, arrows.material as MeshBasicMaterial, count);
      this.group.remove(arrows);
      arrows.dispose();
      this.group.add(larger);
      arrows = larger;
    }
    arrows.count = count;
    return arrows;
  }
}

function arrowInstances(shape: BufferGeometry, material: MeshBasicMaterial, capacity: number): InstancedMesh {
  const arrows = new InstancedMesh(shape, material, capacity);
  // the arrows lie on the mesh, which is what the camera frames: no culling, so no bounding
  // sphere to compute over every instance
  arrows.frustumCulled = false;
  arrows.raycast = () => {}; // picking measures distances to arrows itself
  return arrows;
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
    const start = mesh.faceHalfedge(f);
    let h = start;
    do {
      chosen.push(h);
      const across = mesh.face(mesh.twin(h));
      if (across === -1) chosen.push(mesh.twin(h));
      else if (!seen[across]) {
        seen[across] = 1;
        queue.push(across);
      }
      h = mesh.next(h);
    } while (h !== start);
  }
  return Int32Array.from(chosen);
}
