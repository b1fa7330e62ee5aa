/**
 * The surface itself: flat-shaded faces (the back side in a darker shade, so a student sees which
 * way a face is oriented), every edge as a line, and vertices as dots while the mesh is small.
 * Picking casts rays against the triangles: here for a modest mesh, in a worker holding a
 * bounding-volume hierarchy (three-mesh-bvh) for a large one.
 */
import {
  BufferAttribute,
  BufferGeometry,
  Color,
  DoubleSide,
  FrontSide,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Points,
  PointsMaterial,
  type Raycaster,
  Sphere,
  Vector3,
} from 'three';
import { type Remote, transfer, wrap } from 'comlink';
import type { RenderBuffers, RenderPatch } from '../../workers/protocol.js';
import { colors } from '../colors.js';
import type { ColourScale } from '../../workers/colour-scale.js';
import type { PickingApi, PickingWrite } from './picking.worker.js';

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
  /** Both sides in one draw (half the work of two), the back in its own shade. */
  private readonly surface: Mesh<BufferGeometry, MeshStandardMaterial>;
  /** The back side's colour, a uniform of the surface's shader. */
  private readonly backColour = { value: new Color(colors.surfaceBack) };
  private readonly edges: LineSegments;
  private readonly dots: Points;
  /** Tests rays against both sides of every face; not drawn. */
  private readonly pickTarget = new Mesh(this.faces, new MeshBasicMaterial({ side: DoubleSide }));
  private triangleFace: Int32Array = new Int32Array(0);
  /** The median length of a sample of the edges: how fine the mesh is. */
  edgeLength = 0;
  private pickingWorker: Remote<PickingApi> | null = null;
  private pickingThread: Worker | null = null;
  /** Resolves when the picking worker holds the current mesh; null while picking happens here. */
  private workerReady: Promise<void> | null = null;

  constructor() {
    // the surface sits a little behind the arrows and lines drawn in its plane
    const offset = { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 2 };
    const material = new MeshStandardMaterial({ color: colors.surface, flatShading: true, side: DoubleSide, ...offset });
    material.onBeforeCompile = (shader) => {
      shader.uniforms.backColour = this.backColour;
      shader.fragmentShader = shader.fragmentShader
        .replace('void main() {', 'uniform vec3 backColour;\nvoid main() {')
        .replace('vec4 diffuseColor = vec4( diffuse, opacity );', 'vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backColour, opacity );');
    };
    this.surface = new Mesh(this.faces, material);
    this.edges = new LineSegments(this.lines, new LineBasicMaterial({ color: colors.edge }));
    this.dots = new Points(this.vertices, new PointsMaterial({ color: colors.edge, size: 4, sizeAttenuation: false }));
    // what is drawn is not what is picked: rays go to the pick target
    for (const drawn of [this.surface, this.edges, this.dots]) drawn.raycast = () => {};
    this.group.add(this.surface, this.edges, this.dots);
  }

  /**
   * Draws new buffers, or, with a patch, uploads again only the ranges it rewrote (the buffers
   * themselves were patched in place by the session client).
   */
  update(render: RenderBuffers, patch: RenderPatch | null = null): void {
    const { counts } = render;
    const triangles = counts.triangles;
    if (patch && this.faces.getAttribute('position')?.array === render.positions) {
      const attributes = {
        positions: this.faces.getAttribute('position') as BufferAttribute,
        triangles: this.faces.getIndex()!,
        edges: this.lines.getIndex()!,
        vertices: this.vertices.getIndex()!,
      };
      for (const { buffer, offset, data } of patch.writes) {
        if (buffer === 'triangleFace') continue; // read here, never uploaded
        const attribute = attributes[buffer];
        attribute.addUpdateRange(offset, data.length);
        attribute.needsUpdate = true;
      }
      this.boundMoved(patch);
      if (this.workerReady) this.workerReady = this.patchPickingWorker(patch);
    } else {
      const position = new BufferAttribute(render.positions, 3);
      this.faces.setAttribute('position', position);
      this.faces.setIndex(new BufferAttribute(render.triangles, 1));
      this.triangleFace = render.triangleFace;
      this.workerReady = render.picking ? this.sendToPickingWorker(render.picking) : null;
      // the lines and dots share the positions
      this.lines.setAttribute('position', position);
      this.lines.setIndex(new BufferAttribute(render.edges, 1));
      this.vertices.setAttribute('position', position);
      this.vertices.setIndex(new BufferAttribute(render.vertices, 1));
      this.faces.boundingSphere = new Sphere(new Vector3(...render.bounds.center), render.bounds.radius);
      this.edgeLength = medianEdgeLength(render.positions, render.edges, counts.edges);
    }
    this.faces.setDrawRange(0, 3 * triangles);
    this.lines.setDrawRange(0, 2 * counts.edges);
    this.vertices.setDrawRange(0, counts.vertices);
    // the lines and dots share the bounds of the positions (one pass over them, not three)
    this.lines.boundingSphere = this.faces.boundingSphere!.clone();
    this.vertices.boundingSphere = this.faces.boundingSphere!.clone();
    // a point set (no faces) shows its vertices however many there are
    this.dots.visible = counts.vertices <= MAX_DOTS || triangles === 0;
  }

  /**
   * Keeps the bounding sphere around the positions a patch wrote: measured again in the worker
   * when many moved (a smoothing step), else grown here to take in the few that did (an edit).
   * Grown only, it may be larger than it need be, which costs nothing but a little culling.
   */
  private boundMoved(patch: RenderPatch): void {
    const sphere = this.faces.boundingSphere!;
    if (patch.bounds) {
      sphere.set(new Vector3(...patch.bounds.center), patch.bounds.radius);
      return;
    }
    const point = new Vector3();
    for (const { buffer, data } of patch.writes) {
      if (buffer !== 'positions') continue;
      for (let i = 0; i + 2 < data.length; i += 3) sphere.expandByPoint(point.set(data[i], data[i + 1], data[i + 2]));
    }
  }

  /**
   * Draws only the front of the faces when no back can show: a closed surface facing outwards,
   * seen from outside its bounding sphere. Half the work for a renderer without a GPU.
   */
  cullBackFaces(closedFacingOut: boolean, eye: Vector3): void {
    const sphere = this.faces.boundingSphere;
    const frontOnly = closedFacingOut && sphere !== null && eye.distanceTo(sphere.center) > sphere.radius;
    const side = frontOnly ? FrontSide : DoubleSide;
    if (this.surface.material.side === side) return;
    this.surface.material.side = side;
    this.surface.material.needsUpdate = true;
  }

  /** Shows or hides the edge lines (hidden where they would be denser than pixels). */
  showEdges(on: boolean): void {
    this.edges.visible = on;
  }

  /** Whether picking is quick enough to follow the pointer (hover previews). */
  get quickToPick(): boolean {
    return this.workerReady === null;
  }

  /** The face under the ray, and where the ray meets it. */
  async raycast(raycaster: Raycaster): Promise<SurfaceHit | null> {
    const triangleFace = this.triangleFace;
    if (!this.workerReady) {
      const hit = raycaster.intersectObject(this.pickTarget, false)[0];
      return hit?.faceIndex === undefined || hit.faceIndex === null ? null : { face: triangleFace[hit.faceIndex], point: hit.point };
    }
    await this.workerReady;
    const hit = await this.pickingWorker!.raycast(raycaster.ray.origin.toArray(), raycaster.ray.direction.toArray());
    return hit ? { face: triangleFace[hit.triangle], point: new Vector3().fromArray(hit.point) } : null;
  }

  /**
   * Colours the surface by a value per vertex (what a phase reports), or back to plain with null.
   * Returns the scale, for the legend.
   */
  setVertexColours(scale: ColourScale | null): ColourScale | null {
    const material = this.surface.material;
    // plain and plain again: nothing to change (a new shader variant costs a frame)
    if (!scale && !material.vertexColors) return null;
    if (scale) {
      // as long as the positions (which keep room for more vertices); the next phase's colours
      // go into the same buffer
      const room = this.faces.getAttribute('position').array.length;
      const held = this.faces.getAttribute('color') as BufferAttribute | undefined;
      const attribute = held?.array.length === room ? held : new BufferAttribute(new Float32Array(room), 3);
      (attribute.array as Float32Array).set(scale.colours);
      attribute.clearUpdateRanges();
      attribute.addUpdateRange(0, scale.colours.length);
      attribute.needsUpdate = true;
      if (attribute !== held) this.faces.setAttribute('color', attribute);
    } else this.faces.deleteAttribute('color');
    if (material.vertexColors === (scale !== null)) return scale;
    // coloured by value, both sides show the colours
    material.vertexColors = scale !== null;
    material.color.set(scale ? '#ffffff' : colors.surface);
    this.backColour.value.set(scale ? '#ffffff' : colors.surfaceBack);
    material.needsUpdate = true;
    return scale;
  }

  /**
   * Compiles the surface's shader for colours by value ahead of their first use, which would
   * otherwise hold up the first phase that reports values (tens of milliseconds on a software
   * renderer). Three.js keeps a material's programs, so switching to colours later finds it ready.
   */
  prepareColours(viewer: { precompile: (object: Mesh) => Promise<unknown> }): Promise<unknown> {
    const material = this.surface.material;
    if (material.vertexColors) return Promise.resolve();
    const side = material.side;
    material.vertexColors = true;
    // both sides drawn, and the front only (see `cullBackFaces`): each its own variant. The
    // variant is chosen as the call begins: the material can go back to what it was at once
    const compiled = [DoubleSide, FrontSide].map((variant) => {
      material.side = variant;
      material.needsUpdate = true;
      return viewer.precompile(this.surface);
    });
    material.vertexColors = false;
    material.side = side;
    material.needsUpdate = true;
    return Promise.all(compiled);
  }

  /** Line width and dot size, larger for a lecture hall. */
  setEmphasis(scale: number): void {
    (this.dots.material as PointsMaterial).size = 4 * scale;
  }

  /** Passes a patch's positions and triangles on to the picking worker (the session's copies, transferred), which refits or rebuilds its hierarchy. */
  private patchPickingWorker(patch: RenderPatch): Promise<void> {
    const writes = (patch.picking ?? []) as PickingWrite[];
    return this.pickingWorker!.patch(transfer(writes, writes.map((w) => w.data.buffer as ArrayBuffer)), patch.counts.triangles);
  }

  /** Hands the session's copies to the picking worker (transferred: the page copies nothing). */
  private sendToPickingWorker({ positions, triangles }: NonNullable<RenderBuffers['picking']>): Promise<void> {
    this.pickingThread ??= new Worker(new URL('./picking.worker.ts', import.meta.url), { type: 'module' });
    this.pickingWorker ??= wrap<PickingApi>(this.pickingThread);
    return this.pickingWorker.setMesh(transfer(positions, [positions.buffer]), transfer(triangles, [triangles.buffer]));
  }

  /** Stops the picking worker (an embed taken out of its page). */
  dispose(): void {
    this.pickingThread?.terminate();
  }
}

/** The median length of up to a thousand of the first `count` edges, spread over the list (0 with none). */
export function medianEdgeLength(positions: Float32Array, edges: Uint32Array, count = edges.length / 2): number {
  const step = Math.max(1, Math.floor(count / 1000));
  const lengths: number[] = [];
  for (let e = 0; e < count; e += step) {
    const a = 3 * edges[2 * e];
    const b = 3 * edges[2 * e + 1];
    lengths.push(Math.hypot(positions[a] - positions[b], positions[a + 1] - positions[b + 1], positions[a + 2] - positions[b + 2]));
  }
  lengths.sort((p, q) => p - q);
  return lengths.length ? lengths[lengths.length >> 1] : 0;
}
