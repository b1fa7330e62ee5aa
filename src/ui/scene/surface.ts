/**
 * The surface itself: flat-shaded faces (the back side in a darker shade, so a student sees which
 * way a face is oriented), every edge as a line, and vertices as dots while the mesh is small.
 * Picking casts rays against the triangles: here for a modest mesh, in a worker holding a
 * bounding-volume hierarchy (three-mesh-bvh) for a large one.
 */
import {
  Box3,
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
  type WebGLRenderer,
} from 'three';
import { type Remote, transfer, wrap } from 'comlink';
import type { RenderBounds, RenderBuffers, RenderPatch } from '../../workers/protocol.js';
import { GpuArray, SliceSize } from './gpu-array.js';
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
  /** The arrays on the GPU, which the page puts there a slice per frame (see gpu-array.ts). */
  private readonly gpu = {
    // the lines and dots share the positions (three.js draws from a GLBufferAttribute as from
    // its own, though its types allow only those)
    positions: new GpuArray(false, (a) => [this.faces, this.lines, this.vertices].forEach((g) => g.setAttribute('position', a as unknown as BufferAttribute))),
    triangles: new GpuArray(true, (a) => this.faces.setIndex(a as unknown as BufferAttribute)),
    edges: new GpuArray(true, (a) => this.lines.setIndex(a as unknown as BufferAttribute)),
    vertices: new GpuArray(true, (a) => this.vertices.setIndex(a as unknown as BufferAttribute)),
  };
  /** The render buffers drawn (the page patches them in place). */
  private render: RenderBuffers | null = null;
  /** Whether the edge lines and the vertex dots are to show (each does once its array is on the GPU: see `uploadSlice`). */
  private wanted = { edges: true, dots: false };
  /** How much of an array goes to the GPU per frame. */
  private readonly slice = new SliceSize();
  /** Signalled once the GPU has taken the last slice sent (see `lastSliceTaken`). */
  private sliceSent: WebGLSync | null = null;
  /** The box and the sphere around what is drawn, for framing and culling (see `boundMoved`); every geometry has the one sphere. */
  private readonly box = new Box3();
  private readonly sphere = new Sphere();
  /** Both sides in one draw (half the work of two), the back in its own shade. */
  private readonly surface: Mesh<BufferGeometry, MeshStandardMaterial>;
  /** The back side's colour, a uniform of the surface's shader. */
  private readonly backColour = { value: new Color(colors.surfaceBack) };
  private readonly edges: LineSegments;
  private readonly dots: Points;
  /** Tests rays against both sides of every face, on the page's copies of the arrays; not drawn. */
  private readonly pickFaces = new BufferGeometry();
  private readonly pickTarget = new Mesh(this.pickFaces, new MeshBasicMaterial({ side: DoubleSide }));
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
    // the lines and dots share the bounds of the positions; the sphere is measured in the worker (three.js cannot read the GPU's arrays)
    for (const geometry of [this.faces, this.pickFaces, this.lines, this.vertices]) geometry.boundingSphere = this.sphere;
    this.group.add(this.surface, this.edges, this.dots);
  }

  /**
   * Draws new buffers, or, with a patch, uploads again only the ranges it rewrote (the buffers
   * themselves were patched in place by the session client). Either reaches the GPU over the next
   * frames (see `uploadSlice`).
   */
  update(render: RenderBuffers, patch: RenderPatch | null = null): void {
    const { counts } = render;
    const triangles = counts.triangles;
    if (patch && this.render?.positions === render.positions) {
      for (const { buffer, offset, data } of patch.writes) {
        if (buffer !== 'triangleFace') this.gpu[buffer].rewrote(offset, data.length); // triangleFace is read here, never uploaded
      }
      this.boundMoved(patch);
      if (this.workerReady) this.workerReady = this.patchPickingWorker(patch);
    } else {
      for (const name of ['positions', 'triangles', 'edges', 'vertices'] as const) this.gpu[name].set(render[name]);
      this.pickFaces.setAttribute('position', new BufferAttribute(render.positions, 3));
      this.pickFaces.setIndex(new BufferAttribute(render.triangles, 1));
      this.triangleFace = render.triangleFace;
      this.workerReady = render.picking ? this.sendToPickingWorker(render.picking) : null;
      this.bound(render.bounds);
      this.edgeLength = medianEdgeLength(render.positions, render.edges, counts.edges);
    }
    this.render = render;
    this.faces.setDrawRange(0, 3 * triangles);
    this.pickFaces.setDrawRange(0, 3 * triangles);
    this.lines.setDrawRange(0, 2 * counts.edges);
    this.vertices.setDrawRange(0, counts.vertices);
    // a point set (no faces) shows its vertices however many there are
    this.wanted.dots = counts.vertices <= MAX_DOTS || triangles === 0;
  }

  /**
   * Puts the next slice of what the GPU lacks there (what is drawn first: the surface, then the
   * lines and dots when they show). True while the surface is not all there: the view then keeps
   * its last frame rather than draw new corners on old positions. The lines and dots show once
   * theirs are there; hidden, theirs wait (a dense mesh never shows its lines).
   */
  uploadSlice(renderer: WebGLRenderer): boolean {
    const { positions, triangles, edges, vertices } = this.gpu;
    const drawn = [positions, triangles, ...(this.wanted.edges ? [edges] : []), ...(this.wanted.dots ? [vertices] : [])];
    const gl = renderer.getContext() as WebGL2RenderingContext;
    if (drawn.some((array) => !array.current) && this.lastSliceTaken(gl)) {
      // three.js's vertex array objects keep their element buffers: bind none of them here
      renderer.resetState();
      const start = performance.now();
      let bytes = this.slice.bytes;
      for (const array of drawn) if (bytes > 0) bytes -= array.upload(gl, bytes);
      this.slice.took(performance.now() - start);
      this.sliceSent = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
    }
    this.edges.visible = this.wanted.edges && positions.current && edges.current;
    this.dots.visible = this.wanted.dots && positions.current && vertices.current;
    return !(positions.current && triangles.current);
  }

  /**
   * Whether the GPU has taken the last slice sent. A slice sent before would wait for it on the
   * page's thread: the renderer's process shares two cores with the workers, and fell behind by
   * hundreds of milliseconds while they worked (a picking hierarchy built, a full check).
   */
  private lastSliceTaken(gl: WebGL2RenderingContext): boolean {
    if (!this.sliceSent) return true;
    if (gl.getSyncParameter(this.sliceSent, gl.SYNC_STATUS) !== gl.SIGNALED) return false;
    gl.deleteSync(this.sliceSent);
    this.sliceSent = null;
    return true;
  }

  /** The box and the sphere around what is drawn, for framing it. */
  get bounds(): { box: Box3; radius: number } {
    return { box: this.box.clone(), radius: this.sphere.radius };
  }

  /** Takes bounds the worker measured. */
  private bound({ min, max, center, radius }: RenderBounds): void {
    this.box.set(new Vector3(...min), new Vector3(...max));
    this.sphere.set(new Vector3(...center), radius);
  }

  /**
   * Keeps the bounds around the positions a patch wrote: measured again in the worker when many
   * moved (a smoothing step), else grown here to take in the few that did (an edit). Grown only,
   * they may be larger than they need be, which costs a little culling and framing.
   */
  private boundMoved(patch: RenderPatch): void {
    if (patch.bounds) {
      this.bound(patch.bounds);
      return;
    }
    const point = new Vector3();
    for (const { buffer, data } of patch.writes) {
      if (buffer !== 'positions') continue;
      for (let i = 0; i + 2 < data.length; i += 3) {
        point.set(data[i], data[i + 1], data[i + 2]);
        this.box.expandByPoint(point);
        this.sphere.expandByPoint(point);
      }
    }
  }

  /**
   * Draws only the front of the faces when no back can show: a closed surface facing outwards,
   * seen from outside its bounding sphere. Half the work for a renderer without a GPU.
   */
  cullBackFaces(closedFacingOut: boolean, eye: Vector3): void {
    const frontOnly = closedFacingOut && eye.distanceTo(this.sphere.center) > this.sphere.radius;
    const side = frontOnly ? FrontSide : DoubleSide;
    if (this.surface.material.side === side) return;
    this.surface.material.side = side;
    this.surface.material.needsUpdate = true;
  }

  /** Shows or hides the edge lines (hidden where they would be denser than pixels), once their array is on the GPU. */
  showEdges(on: boolean): void {
    this.wanted.edges = on;
    this.edges.visible = on && this.gpu.positions.current && this.gpu.edges.current;
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
      const room = this.render!.positions.length;
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
