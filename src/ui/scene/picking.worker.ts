/**
 * Picking on a large mesh: this worker holds a bounding-volume hierarchy of its triangles
 * (three-mesh-bvh) and answers "which triangle does this ray hit first?", so the page's thread
 * neither builds the hierarchy nor carries its code. (Small meshes are picked on the page.)
 */
import { expose } from 'comlink';
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';

export interface PickingWrite {
  buffer: 'positions' | 'triangles';
  offset: number;
  data: Float32Array | Uint32Array | Int32Array;
}

let bvh: MeshBVH | null = null;
let held: { positions: Float32Array; triangles: Uint32Array } | null = null;
/** How many triangles are held (the hierarchy covers as many once it is current)… */
let count = 0;
/**
 * …and what the hierarchy needs before the next ray: nothing, its boxes refit (the same triangles
 * moved), or a build. Done when a ray asks, not when the mesh comes: a build over millions of
 * triangles takes a core for seconds, which a subdivision's next phase would share (about a second
 * of each Catmull-Clark phase at 1.31M triangles), and most phases are stepped past unpicked.
 */
let needs: 'nothing' | 'refit' | 'build' = 'nothing';

/** Spare triangles kept for patches that add some. */
const SPARE_TRIANGLES = 4096;

const api = {
  /** Takes the mesh to pick from (send its arrays transferred). */
  setMesh(positions: Float32Array, triangles: Uint32Array): void {
    const room = new Uint32Array(triangles.length + 3 * SPARE_TRIANGLES);
    room.set(triangles);
    held = { positions, triangles: room };
    count = triangles.length / 3;
    needs = 'build';
  },
  /**
   * Rewrites ranges of the positions and triangles (an edit's patch). The same triangles, moved or
   * rewired (a flip, a smoothing step, an undo), keep the hierarchy with its boxes refit, a
   * fraction of a rebuild; a different number of triangles, or grown arrays, need a new one.
   */
  patch(writes: PickingWrite[], triangles: number): void {
    if (!held) return;
    let grown = false;
    for (const { buffer, offset, data } of writes) {
      const target = held[buffer];
      if (offset + data.length > target.length) {
        const larger = new (target.constructor as new (n: number) => typeof target)(2 * (offset + data.length));
        larger.set(target);
        held[buffer] = larger as never;
        grown = true;
      }
      (held[buffer] as Float32Array).set(data as Float32Array, offset);
    }
    if (grown || triangles !== count) needs = 'build';
    // nothing moved (starting an operation): no pass over every node for nothing
    else if (needs === 'nothing' && writes.length > 0) needs = 'refit';
    count = triangles;
  },
  /** The first triangle the ray meets (from either side) and where; null when it misses. */
  raycast(origin: number[], direction: number[]): { triangle: number; point: number[] } | null {
    if (!held) return null;
    if (needs === 'build') build();
    else if (needs === 'refit') bvh!.refit();
    needs = 'nothing';
    const hit = bvh!.raycastFirst(new Ray(new Vector3().fromArray(origin), new Vector3().fromArray(direction)), DoubleSide);
    return hit?.faceIndex === undefined || hit.faceIndex === null ? null : { triangle: hit.faceIndex, point: hit.point.toArray() };
  },
};

function build(): void {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(held!.positions, 3));
  geometry.setIndex(new BufferAttribute(held!.triangles, 1));
  geometry.setDrawRange(0, 3 * count);
  // indirect: the triangles keep their order, which maps them to their faces (the hierarchy covers the draw range)
  bvh = new MeshBVH(geometry, { indirect: true });
}

export type PickingApi = typeof api;

expose(api);
