/**
 * The cutting plane, drawn as a translucent square the student can drag and rotate, with a
 * preview of where it would cut: the segments where the plane crosses each face.
 */
import {
  BufferGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  PlaneGeometry,
  Quaternion,
  Vector3,
} from 'three';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import type { HalfedgeMesh } from '../../core/index.js';
import { colors } from '../colors.js';
import type { Viewer } from './viewer.js';

export type Plane = [number, number, number, number];

export class PlaneGizmo {
  readonly group = new Group();
  private readonly square: Mesh;
  private readonly preview = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: colors.twin, depthTest: false }));
  private readonly controls: TransformControls;
  private mesh: HalfedgeMesh | null = null;

  constructor(
    private readonly viewer: Viewer,
    private readonly onChange: (plane: Plane) => void,
  ) {
    this.square = new Mesh(
      new PlaneGeometry(1, 1),
      new MeshBasicMaterial({ color: colors.prev, transparent: true, opacity: 0.18, side: DoubleSide, depthWrite: false }),
    );
    this.square.raycast = () => {};
    this.preview.renderOrder = 4;
    this.preview.raycast = () => {};
    this.group.add(this.square, this.preview);
    this.controls = new TransformControls(viewer.camera, viewer.renderer.domElement);
    this.controls.attach(this.square);
    this.controls.setSize(1.2);
    // while the gizmo is dragged, the camera stays put
    this.controls.addEventListener('dragging-changed', (event) => {
      viewer.controls.enabled = !event.value;
      if (!event.value) this.onChange(this.plane());
    });
    this.controls.addEventListener('objectChange', () => {
      this.updatePreview();
      viewer.requestRender();
    });
    this.controls.addEventListener('change', () => viewer.requestRender());
    this.hide();
  }

  show(mesh: HalfedgeMesh, plane: Plane): void {
    this.mesh = mesh;
    this.controls.camera = this.viewer.camera;
    this.setPlane(plane);
    this.group.visible = true;
    this.controls.enabled = true;
    if (!this.controls.getHelper().parent) this.viewer.add(this.controls.getHelper());
    this.controls.getHelper().visible = true;
    this.viewer.requestRender();
  }

  get shown(): boolean {
    return this.group.visible;
  }

  hide(): void {
    this.group.visible = false;
    this.controls.enabled = false;
    this.controls.getHelper().visible = false;
    this.viewer.requestRender();
  }

  setMode(mode: 'translate' | 'rotate'): void {
    this.controls.setMode(mode);
  }

  /** Puts the square on the plane, centred on the point of the plane nearest the mesh's centre. */
  setPlane([a, b, c, d]: Plane): void {
    const mesh = this.mesh;
    const normal = new Vector3(a, b, c);
    const length = normal.length();
    if (!mesh || !(length > 0)) return;
    normal.divideScalar(length);
    const { centre, radius } = meshSphere(mesh);
    const distance = normal.dot(centre) + d / length;
    this.square.position.copy(centre).addScaledVector(normal, -distance);
    this.square.quaternion.copy(new Quaternion().setFromUnitVectors(new Vector3(0, 0, 1), normal));
    this.square.scale.setScalar(2.4 * radius);
    this.updatePreview();
  }

  /** The plane the square lies in, a·x + b·y + c·z + d = 0 with (a, b, c) a unit normal. */
  plane(): Plane {
    const normal = new Vector3(0, 0, 1).applyQuaternion(this.square.quaternion).normalize();
    return [normal.x, normal.y, normal.z, -normal.dot(this.square.position)];
  }

  /** The segments where the plane crosses the faces: a preview of the cut. */
  private updatePreview(): void {
    const mesh = this.mesh;
    if (!mesh) return;
    const [a, b, c, d] = this.plane();
    const p = mesh.positions;
    const side = (v: number) => a * p[3 * v] + b * p[3 * v + 1] + c * p[3 * v + 2] + d;
    const points: number[] = [];
    const crossing: number[] = [];
    for (const f of mesh.faces()) {
      crossing.length = 0;
      const start = mesh.faceHalfedge(f);
      let h = start;
      do {
        const u = mesh.origin(h);
        const v = mesh.target(h);
        const su = side(u);
        const sv = side(v);
        if ((su < 0 && sv >= 0) || (su >= 0 && sv < 0)) {
          const t = su / (su - sv);
          for (let k = 0; k < 3; k++) crossing.push(p[3 * u + k] + t * (p[3 * v + k] - p[3 * u + k]));
        }
        h = mesh.next(h);
      } while (h !== start);
      // crossings come in pairs around the face: in, out, in, out
      for (let i = 0; i + 5 < crossing.length; i += 6) points.push(...crossing.slice(i, i + 6));
    }
    this.preview.geometry.dispose();
    this.preview.geometry = new BufferGeometry();
    this.preview.geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
  }
}

function meshSphere(mesh: HalfedgeMesh): { centre: Vector3; radius: number } {
  const min = new Vector3(Infinity, Infinity, Infinity);
  const max = new Vector3(-Infinity, -Infinity, -Infinity);
  const point = new Vector3();
  for (const v of mesh.vertices()) {
    point.fromArray(mesh.positions, 3 * v);
    min.min(point);
    max.max(point);
  }
  return { centre: min.clone().add(max).multiplyScalar(0.5), radius: Math.max(max.distanceTo(min) / 2, 1e-6) };
}
