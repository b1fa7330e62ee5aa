/**
 * What the selection (or the hover) lights up, drawn over the mesh: arrows in the legend's
 * colours, a tint over faces, dots on vertices, and labels ("h17", "next h18") in large type.
 */
import {
  BufferGeometry,
  CanvasTexture,
  Color,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  Mesh,
  MeshBasicMaterial,
  type Object3D,
  Points,
  PointsMaterial,
} from 'three';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { LineSegments2 } from 'three/examples/jsm/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/examples/jsm/lines/LineSegmentsGeometry.js';
import { CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { faceVertices, type HalfedgeMesh } from '../../core/index.js';
import { newPlacement, placeArrow } from './arrow-placement.js';
import { arrowShape, writeArrowMatrix } from './arrows.js';
import { labelPoint } from './label-point.js';
import type { Selection } from '../selection.js';

export interface HighlightSpec {
  /** `hollow`: drawn with a white core, the second cue beside the colour (see `hollowRoles`). */
  halfedges: Array<{ id: number; color: string; hollow?: boolean }>;
  faces: Array<{ id: number; color: string }>;
  vertices: Array<{ id: number; color: string }>;
  edges: Array<{ id: number; color: string }>;
  /**
   * Each on an element, which the layer finds on the mesh it draws (see label-point.ts);
   * `sentence`: words rather than an id, which may wrap onto a second line (see repair-story.ts).
   */
  labels: Array<{ text: string; on: Selection; color: string; sentence?: boolean }>;
}

export function emptyHighlight(): HighlightSpec {
  return { halfedges: [], faces: [], vertices: [], edges: [], labels: [] };
}

const shape = arrowShape(1);
/** How wide a highlighted edge is drawn, in CSS pixels (times the presentation scale). */
const EDGE_LINE_PIXELS = 3;

export class HighlightLayer {
  readonly group = new Group();
  private readonly dotTexture = roundDot();
  /** Counts the calls of `clear` (every show begins with one), so a show in tasks knows when it was overtaken. */
  private shown = 0;
  /** A show in tasks has parts yet to lay out (the view waits for them). */
  laying = false;

  /**
   * `opacity` < 1 for the hover preview; `widthScale` makes the highlighted arrows stand out;
   * `dotSize` (pixels) of vertex markers, smaller where a phase marks thousands of them.
   */
  constructor(
    private readonly opacity = 1,
    private readonly widthScale = 2,
    private readonly dotSize = 18,
  ) {}

  /**
   * Compiles the shaders of every kind of mark this layer draws ahead of their first use, on any
   * mesh with a face: the first thousands of marks of a phase would otherwise hold up the frame
   * that draws them by a hundred milliseconds on a software renderer. Three.js keeps the programs.
   */
  prepare(mesh: HalfedgeMesh, precompile: (object: Object3D) => Promise<unknown>): Promise<unknown> {
    const face = mesh.faces().next();
    if (face.done) return Promise.resolve();
    const halfedge = mesh.faceHalfedge(face.value);
    const trial = new HighlightLayer(this.opacity, this.widthScale, this.dotSize);
    trial.show(mesh, { halfedges: [{ id: halfedge, color: '#000', hollow: true }], faces: [{ id: face.value, color: '#000' }], vertices: [{ id: mesh.origin(halfedge), color: '#000' }], edges: [{ id: halfedge >> 1, color: '#000' }], labels: [] }, 1);
    // the programs are chosen as the call begins: the marks may go at once
    const compiled = precompile(trial.group);
    trial.clear();
    return compiled;
  }

  show(mesh: HalfedgeMesh, spec: HighlightSpec, scale: number): void {
    this.clear();
    for (const part of this.parts(mesh, spec, scale)) part();
  }

  /**
   * The same, a part per task (the tint, the arrows, the lines, the dots, the labels): a phase's
   * thousands of marks at once would keep the page's input waiting. Resolves once all are drawn,
   * or to false when another `show` or `clear` came first.
   */
  async showInTasks(mesh: HalfedgeMesh, spec: HighlightSpec, scale: number): Promise<boolean> {
    this.clear();
    const shown = this.shown;
    this.laying = true;
    for (const part of this.parts(mesh, spec, scale)) {
      await new Promise((resolve) => setTimeout(resolve));
      if (this.shown !== shown) return false;
      part();
    }
    this.laying = false;
    return true;
  }

  /** What `show` draws, in parts. */
  private parts(mesh: HalfedgeMesh, spec: HighlightSpec, scale: number): Array<() => void> {
    const transparent = this.opacity < 1;
    // labels keep off the marks: points on each where there are few enough to mark
    const labelsAvoid = (marks: number) => spec.labels.length > 0 && marks <= MAX_MARKED;
    const parts: Array<() => void> = [];
    if (spec.faces.length) parts.push(() => {
      this.group.add(this.faceTint(mesh, spec.faces));
      // the tinted faces' centres, and halfway to each corner
      if (!labelsAvoid(spec.faces.length)) return;
      for (const { id } of spec.faces) {
        const corners = [...faceVertices(mesh, id)].map((v) => mesh.position(v));
        const centre = [0, 1, 2].map((k) => corners.reduce((sum, p) => sum + p[k], 0) / corners.length);
        this.group.add(avoidMarker(centre, centre, 0), ...corners.map((corner) => avoidMarker(centre, corner, 0.5)));
      }
    });
    if (spec.halfedges.length) parts.push(() => {
      const arrows = new InstancedMesh(
        shape,
        new MeshBasicMaterial({
          side: DoubleSide,
          transparent,
          opacity: this.opacity,
          polygonOffset: true,
          polygonOffsetFactor: -1,
          polygonOffsetUnits: -4,
        }),
        spec.halfedges.length,
      );
      const placement = newPlacement();
      // points along each arrow
      const markArrows = labelsAvoid(spec.halfedges.length);
      spec.halfedges.forEach(({ id, color }, i) => {
        const arrow = placeArrow(mesh, id, placement, scale);
        writeArrowMatrix(arrow, arrows.instanceMatrix.array, 16 * i, this.widthScale);
        arrows.setColorAt(i, colour(color));
        if (markArrows) for (const t of ARROW_MARKS) this.group.add(avoidMarker(arrow.start, arrow.end, t));
      });
      arrows.renderOrder = 2;
      this.group.add(asMarks(arrows));
      const hollow = spec.halfedges.filter((h) => h.hollow);
      if (hollow.length) this.group.add(this.hollowCores(mesh, hollow.map((h) => h.id), scale));
    });
    if (spec.edges.length) parts.push(() => {
      const points: number[] = [];
      const lineColors: number[] = [];
      for (const { id, color } of spec.edges) {
        const c = colour(color);
        for (const v of [mesh.origin(mesh.edgeHalfedge(id)), mesh.origin(mesh.twin(mesh.edgeHalfedge(id)))]) {
          points.push(...mesh.position(v));
          lineColors.push(c.r, c.g, c.b);
        }
      }
      // lines of a few pixels whatever the zoom: a WebGL line is one pixel, too thin for a room
      const lines = new LineSegments2(
        new LineSegmentsGeometry().setPositions(points).setColors(lineColors),
        new LineMaterial({ vertexColors: true, linewidth: EDGE_LINE_PIXELS * scale, transparent, opacity: this.opacity }),
      );
      lines.renderOrder = 2;
      this.group.add(asMarks(lines));
    });
    if (spec.vertices.length) parts.push(() => {
      const points: number[] = [];
      const dotColors: number[] = [];
      // the dots themselves
      const markDots = labelsAvoid(spec.vertices.length);
      for (const { id, color } of spec.vertices) {
        const c = colour(color);
        const at = mesh.position(id);
        points.push(...at);
        dotColors.push(c.r, c.g, c.b);
        if (markDots) this.group.add(avoidMarker(at, at, 0));
      }
      const dots = new Points(
        geometry(points, dotColors),
        new PointsMaterial({ size: this.dotSize * scale, sizeAttenuation: false, vertexColors: true, map: this.dotTexture, alphaTest: 0.5, transparent, opacity: this.opacity }),
      );
      dots.renderOrder = 3;
      this.group.add(asMarks(dots));
    });
    if (spec.labels.length) parts.push(() => {
      for (const { text, on, color, sentence } of spec.labels) {
        // the anchor is what the label renderer positions; the tag inside may be nudged off others
        const anchor = document.createElement('div');
        const tag = document.createElement('span');
        tag.className = sentence ? 'label sentence' : 'label';
        tag.textContent = text; // text, never HTML
        tag.style.borderColor = color;
        anchor.append(tag);
        const label = new CSS2DObject(anchor);
        label.position.set(...labelPoint(mesh, on));
        this.group.add(label);
      }
    });
    return parts;
  }

  /**
   * White cores inside arrows (a shorter, narrower arrow on top), which makes them read as hollow.
   */
  private hollowCores(mesh: HalfedgeMesh, ids: number[], scale: number): InstancedMesh {
    const cores = new InstancedMesh(
      shape,
      new MeshBasicMaterial({ color: 0xffffff, side: DoubleSide, transparent: this.opacity < 1, opacity: this.opacity, polygonOffset: true, polygonOffsetFactor: -2, polygonOffsetUnits: -8 }),
      ids.length,
    );
    const placement = newPlacement();
    ids.forEach((id, i) => {
      const arrow = placeArrow(mesh, id, placement, scale);
      // the core starts a little after the tail and ends well before the tip, inside the head
      const along = [0, 1, 2].map((k) => arrow.end[k] - arrow.start[k]);
      for (let k = 0; k < 3; k++) {
        arrow.start[k] += 0.08 * along[k];
        arrow.end[k] -= 0.12 * along[k];
      }
      writeArrowMatrix(arrow, cores.instanceMatrix.array, 16 * i, this.widthScale * 0.4);
    });
    cores.renderOrder = 2.5;
    return asMarks(cores);
  }

  clear(): void {
    this.shown++;
    this.laying = false;
    for (const child of [...this.group.children]) {
      if (child instanceof CSS2DObject) child.element.remove();
      if ('geometry' in child && child.geometry instanceof BufferGeometry && child.geometry !== shape) child.geometry.dispose();
      this.group.remove(child);
    }
  }

  private faceTint(mesh: HalfedgeMesh, faces: HighlightSpec['faces']): Mesh {
    const points: number[] = [];
    const tint: number[] = [];
    for (const { id, color } of faces) {
      const c = colour(color);
      const loop: number[] = [];
      const start = mesh.faceHalfedge(id);
      let h = start;
      do {
        loop.push(mesh.origin(h));
        h = mesh.next(h);
      } while (h !== start);
      // a fan is enough for a tint, even on a non-convex face it only overdraws
      for (let i = 1; i + 1 < loop.length; i++) {
        for (const v of [loop[0], loop[i], loop[i + 1]]) {
          points.push(...mesh.position(v));
          tint.push(c.r, c.g, c.b);
        }
      }
    }
    const material = new MeshBasicMaterial({
      vertexColors: true,
      side: DoubleSide,
      transparent: true,
      opacity: 0.5 * this.opacity,
      depthWrite: false,
      polygonOffset: true,
      polygonOffsetFactor: 0.5,
      polygonOffsetUnits: 1,
    });
    return asMarks(new Mesh(geometry(points, tint), material));
  }
}

function geometry(points: number[], pointColors: number[]): BufferGeometry {
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(points, 3));
  g.setAttribute('color', new Float32BufferAttribute(pointColors, 3));
  return g;
}

/**
 * Drawn over the mesh as they are: no ray tests them (picking goes to the surface), and no
 * culling first measures a sphere around them (a phase's thousands lie all over the mesh).
 */
function asMarks<T extends Mesh | Points>(object: T): T {
  object.raycast = () => {};
  object.frustumCulled = false;
  return object;
}

const colours = new Map<string, Color>();

/** The colour of a CSS colour string, parsed once: a phase marks thousands of elements in a few colours. */
function colour(css: string): Color {
  let parsed = colours.get(css);
  if (!parsed) colours.set(css, (parsed = new Color(css)));
  return parsed;
}

/** A round dot for vertex markers (points are squares otherwise). */
function roundDot(): CanvasTexture {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 64;
  const g = canvas.getContext('2d')!;
  g.fillStyle = '#fff';
  g.beginPath();
  g.arc(32, 32, 28, 0, 2 * Math.PI);
  g.fill();
  g.strokeStyle = '#000';
  g.lineWidth = 5;
  g.stroke();
  return new CanvasTexture(canvas);
}

/** Highlights with more arrows (or dots, or faces) than this (a phase's thousands) have no labels to keep off them. */
const MAX_MARKED = 40;
/** Where along an arrow (from its tail, 0, to its tip, 1) labels are kept off. */
const ARROW_MARKS = [0, 0.25, 0.5, 0.75, 1];

/** An empty element at a point of an arrow (or at a dot: `start` = `end`), which the label placement keeps labels off. */
function avoidMarker(start: ArrayLike<number>, end: ArrayLike<number>, t: number): CSS2DObject {
  const marker = document.createElement('div');
  marker.className = 'label-avoid';
  const object = new CSS2DObject(marker);
  object.position.set(start[0] + t * (end[0] - start[0]), start[1] + t * (end[1] - start[1]), start[2] + t * (end[2] - start[2]));
  return object;
}
