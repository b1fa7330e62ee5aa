/**
 * The three.js stage: renderer, lights, a perspective camera for 3D and an orthographic one for
 * the top view of planar meshes, orbit controls, and a label layer (HTML text placed in 3D).
 * It draws only when something changed, so an idle page costs nothing.
 */
import {
  AmbientLight,
  Box3,
  Color,
  DirectionalLight,
  type Object3D,
  OrthographicCamera,
  PerspectiveCamera,
  Raycaster,
  Scene,
  Vector2,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DRenderer } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { clearSpot, covered, type Rect, type Spot } from './clear-spot.js';
import { placeLabels } from './label-placement.js';
import { colors } from '../colors.js';

export type ViewMode = 'perspective' | 'top';

export class Viewer {
  readonly renderer: WebGLRenderer;
  readonly labels: CSS2DRenderer;
  /** The overlays on the view (legend, counts…), as screen rectangles: labels keep off them, and framing puts the mesh clear of them. */
  overlays: () => DOMRect[] = () => [];
  readonly scene = new Scene();
  readonly perspective = new PerspectiveCamera(40, 1, 0.01, 1000);
  readonly orthographic = new OrthographicCamera(-1, 1, 1, -1, 0.01, 1000);
  readonly controls: OrbitControls;
  mode: ViewMode = 'perspective';
  /** Animation frames so far (tests watch it move while the worker works). */
  frames = 0;
  /** When the scene was last drawn (performance.now()). */
  lastDrawAt = 0;
  /** Called before each draw (the app shows or hides detail for the zoom). */
  beforeDraw: (() => void) | null = null;
  /**
   * Work at the start of every animation frame that drawing waits for: true while it is not done
   * (the surface's arrays going to the GPU a slice per frame). The canvas keeps the last frame meanwhile.
   */
  beforeFrame: (() => boolean) | null = null;
  private needsRender = true;
  /** Where the framed mesh sits, from the middle of the view, as a share of its width and height (see `frame`). */
  private shift = { x: 0, y: 0 };
  /**
   * The circle the last `frame` filled clear of the overlays (canvas pixels), until the user
   * turns, moves or zooms the view, or a link places the camera; null too when no circle was
   * clear (the mesh then took the whole view).
   */
  private framed: Spot | null = null;
  private disposed = false;
  private readonly resizeObserver = new ResizeObserver(() => this.resize());
  private readonly light = new DirectionalLight(0xffffff, 1.6);

  constructor(readonly container: HTMLElement) {
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.domElement.setAttribute('aria-label', '3D view of the mesh');
    this.renderer.domElement.setAttribute('role', 'img');
    container.append(this.renderer.domElement);
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'labels';
    container.append(this.labels.domElement);

    this.scene.background = new Color(colors.background);
    this.scene.add(new AmbientLight(0xffffff, 1.1), this.light);
    this.controls = new OrbitControls(this.perspective, this.renderer.domElement);
    this.controls.enableDamping = false;
    // a camera that moves during a gesture (not a click that picks) is where the user put it
    let gesture = false;
    this.controls.addEventListener('start', () => (gesture = true));
    this.controls.addEventListener('end', () => (gesture = false));
    this.controls.addEventListener('change', () => {
      if (gesture) this.framed = null;
      this.requestRender();
    });
    this.resizeObserver.observe(container);
    this.resize();
    const loop = () => {
      if (this.disposed) return;
      this.frames++;
      const waiting = this.beforeFrame?.() ?? false;
      if (this.needsRender && !waiting) {
        this.needsRender = false;
        this.draw();
      }
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }

  get camera(): PerspectiveCamera | OrthographicCamera {
    return this.mode === 'top' ? this.orthographic : this.perspective;
  }

  requestRender(): void {
    this.needsRender = true;
  }

  /** Stops drawing and gives the WebGL context back (a page holds only a few at once). */
  dispose(): void {
    this.disposed = true;
    this.resizeObserver.disconnect();
    this.controls.dispose();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
  }

  add(...objects: Object3D[]): void {
    this.scene.add(...objects);
    this.requestRender();
  }

  /** Compiles the shaders of `object` as the scene would draw it now, without drawing. */
  precompile(object: Object3D): Promise<unknown> {
    return this.renderer.compileAsync(object, this.camera, this.scene);
  }

  /**
   * Points the camera at `box`. In the top view the orthographic camera looks down `normal`
   * (the plane of a planar mesh), like the figures in a textbook; the perspective camera keeps
   * the direction it looks from, or takes `from` (pointing from the box towards the camera).
   */
  frame(box: Box3, normal: Vector3 = new Vector3(0, 0, 1), sphereRadius?: number, from?: Vector3): void {
    if (box.isEmpty()) return;
    const centre = box.getCenter(new Vector3());
    // the box's half-diagonal bounds the points, but a sphere around the points is often tighter;
    // it goes where the overlays leave room, as large as that room (see clear-spot.ts)
    const spot = this.clearSpot();
    this.framed = covered(spot.pixels, spot.overlays) ? null : spot.pixels;
    const radius = Math.max(sphereRadius ?? box.getSize(new Vector3()).length() / 2, 1e-6) / spot.scale;
    this.shift = spot.shift;
    this.applyShift();
    const camera = this.camera;
    if (camera instanceof OrthographicCamera) {
      const up = Math.abs(normal.y) > 0.9 ? new Vector3(0, 0, -1) : new Vector3(0, 1, 0);
      camera.up.copy(up);
      camera.position.copy(centre).addScaledVector(normal, 4 * radius);
      // fit the box's extent across and up the screen, not its diagonal
      const right = new Vector3().crossVectors(up, normal).normalize();
      const screenUp = new Vector3().crossVectors(normal, right).normalize();
      let across = 0;
      let upward = 0;
      for (const corner of boxCorners(box)) {
        const offset = corner.sub(centre);
        across = Math.max(across, Math.abs(offset.dot(right)));
        upward = Math.max(upward, Math.abs(offset.dot(screenUp)));
      }
      const aspect = this.aspect();
      const half = (Math.max(upward, across / aspect, 1e-6) * 1.12) / spot.scale;
      Object.assign(camera, { left: -half * aspect, right: half * aspect, top: half, bottom: -half, near: 0.01 * radius, far: 10 * radius, zoom: 1 });
      camera.updateProjectionMatrix();
    } else {
      const direction = from?.clone() ?? camera.position.clone().sub(this.controls.target);
      // a three-quarter view from the front, y up (three.js's and most scanners' convention)
      if (direction.lengthSq() === 0 || !Number.isFinite(direction.lengthSq())) direction.set(0.55, 0.45, 1);
      direction.normalize();
      const distance = radius / Math.sin((camera.fov * Math.PI) / 360);
      camera.position.copy(centre).addScaledVector(direction, distance * 1.05);
      camera.near = distance / 1000;
      camera.far = distance * 100;
      camera.updateProjectionMatrix();
    }
    this.controls.target.copy(centre);
    this.controls.update();
    this.requestRender();
  }

  /** Where the point the camera orbits is drawn: its shift from the middle, as a share of the width and height. */
  get targetShift(): [number, number] {
    return [this.shift.x, this.shift.y];
  }

  /** Where the point the camera orbits is drawn, in the canvas's pixels. */
  targetPoint(): { x: number; y: number } {
    const { width, height } = this.size();
    return { x: (0.5 + this.shift.x) * width, y: (0.5 + this.shift.y) * height };
  }

  /**
   * Whether framing again would help: an overlay now covers part of the circle the view was framed
   * into clear of them all (a phase card that appeared over the mesh), and the overlays still
   * leave a clear spot. False once the user has moved the view: where they put it stays.
   */
  overlaysCoverFramed(): boolean {
    if (this.framed === null) return false;
    const overlays = this.canvasOverlays();
    return covered(this.framed, overlays) && !covered(this.clearSpot(overlays).pixels, overlays);
  }

  /** Puts the camera where a shared link says. */
  setCamera(position: number[], target: number[], zoom: number, [x, y]: [number, number] = [0, 0]): void {
    this.framed = null;
    this.shift = { x, y };
    this.applyShift();
    const camera = this.camera;
    camera.position.fromArray(position);
    camera.zoom = zoom;
    camera.updateProjectionMatrix();
    this.controls.target.fromArray(target);
    this.controls.update();
    this.requestRender();
  }

  setMode(mode: ViewMode): void {
    this.mode = mode;
    this.controls.object = this.camera;
    this.controls.enableRotate = mode === 'perspective';
    this.resize();
  }

  /** A ray through a point of the canvas (CSS pixels relative to it). */
  ray(x: number, y: number): Raycaster {
    const { width, height } = this.size();
    const raycaster = new Raycaster();
    raycaster.setFromCamera(new Vector2((x / width) * 2 - 1, -(y / height) * 2 + 1), this.camera);
    return raycaster;
  }

  /** Where a point in space appears on the canvas (CSS pixels), and whether it is in front. */
  project(point: Vector3 | [number, number, number]): { x: number; y: number; visible: boolean } {
    const v = Array.isArray(point) ? new Vector3(...point) : point.clone();
    v.project(this.camera);
    const { width, height } = this.size();
    return { x: ((v.x + 1) / 2) * width, y: ((1 - v.y) / 2) * height, visible: v.z > -1 && v.z < 1 };
  }

  /** How many canvas pixels one unit of length spans at the point the camera orbits. */
  pixelsPerUnit(): number {
    const { height } = this.size();
    const camera = this.camera;
    if (camera instanceof OrthographicCamera) return (height * camera.zoom) / (camera.top - camera.bottom);
    const distance = camera.position.distanceTo(this.controls.target);
    return height / (2 * distance * Math.tan((camera.fov * Math.PI) / 360));
  }

  size(): { width: number; height: number } {
    return { width: this.container.clientWidth || 1, height: this.container.clientHeight || 1 };
  }

  private aspect(): number {
    const { width, height } = this.size();
    return width / height;
  }

  /**
   * Where the overlays leave the most room: that spot's centre relative to the middle (a share of
   * the width and height) and its size relative to the whole view's.
   */
  private clearSpot(overlays = this.canvasOverlays()): { shift: { x: number; y: number }; scale: number; pixels: Spot; overlays: Rect[] } {
    const { width, height } = this.size();
    const spot = clearSpot(width, height, overlays);
    return {
      shift: { x: (spot.x - width / 2) / width, y: (spot.y - height / 2) / height },
      scale: spot.radius / (Math.min(width, height) / 2),
      pixels: spot,
      overlays,
    };
  }

  /** The overlays, in the canvas's pixels. */
  private canvasOverlays(): Rect[] {
    const canvas = this.renderer.domElement.getBoundingClientRect();
    return this.overlays().map((r) => ({ left: r.left - canvas.left, top: r.top - canvas.top, right: r.right - canvas.left, bottom: r.bottom - canvas.top }));
  }

  /** Draws the point the camera orbits at the framed spot rather than in the middle (both cameras, for a switch of mode). */
  private applyShift(): void {
    const { width, height } = this.size();
    for (const camera of [this.perspective, this.orthographic]) {
      if (this.shift.x === 0 && this.shift.y === 0) camera.clearViewOffset();
      else camera.setViewOffset(width, height, -this.shift.x * width, -this.shift.y * height, width, height);
    }
  }

  private resize(): void {
    const { width, height } = this.size();
    this.applyShift();
    this.renderer.setSize(width, height, false);
    this.renderer.domElement.style.width = `${width}px`;
    this.renderer.domElement.style.height = `${height}px`;
    this.labels.setSize(width, height);
    this.perspective.aspect = width / height;
    this.perspective.updateProjectionMatrix();
    const o = this.orthographic;
    const half = (o.top - o.bottom) / 2;
    o.left = -half * (width / height);
    o.right = half * (width / height);
    o.updateProjectionMatrix();
    this.requestRender();
  }

  private draw(): void {
    this.lastDrawAt = performance.now();
    // the light follows the camera, so the side facing the student is always lit
    this.light.position.copy(this.camera.position);
    this.beforeDraw?.();
    this.renderer.render(this.scene, this.camera);
    this.labels.render(this.scene, this.camera);
    placeLabels(this.labels.domElement, this.overlays());
  }
}

function boxCorners(box: Box3): Vector3[] {
  const { min, max } = box;
  const corners: Vector3[] = [];
  for (const x of [min.x, max.x]) for (const y of [min.y, max.y]) for (const z of [min.z, max.z]) corners.push(new Vector3(x, y, z));
  return corners;
}
