/**
 * What the page draws, laid out so that a change record becomes a patch of a few ranges: every
 * buffer is indexed by element slot and keeps room to grow, so an edit rewrites the entries of the
 * elements it touched and the page uploads only those ranges to the GPU.
 *
 * ```
 *   positions  x y z per vertex slot
 *   vertices   per vertex slot: the vertex, or (deleted) any live one, drawn twice where it is
 *   edges      per edge slot: its two ends, or (deleted) one end twice, a line of no length
 *   triangles  per face: a range of `degree − 2` triangles; a deleted face's range holds
 *              triangles of no area, and a face that needs more triangles than its range
 *              moves to the end
 * ```
 *
 * The session keeps one `RenderLayout` for what the page holds: `full()` lays the mesh out
 * afresh, `patch(change)` says what to rewrite, or null when a fresh layout is the better answer:
 * a change that outgrows the room left, or one that rewrites most of the mesh (a subdivision
 * phase rewires every face), which the page takes whole: its arrays are transferred, where
 * patching its own would copy hundreds of megabytes on the page's thread.
 */
import type { ChangeRecord, HalfedgeMesh, ValueChange } from '../core/index.js';
import { forEachPointerWrite } from '../core/index.js';
import { boundingBox, boundingSphere, faceNormal } from '../core/index.js';
import { meshArrayIndex } from '../core/mesh-arrays.js';
import { PICK_IN_WORKER_ABOVE, REBOUND_ABOVE, type RenderBounds, type RenderBuffers, type RenderPatch, type RenderWrite } from './protocol.js';
import { faceTriangles, quadSplitCorner, writeFaceTriangles } from '../core/face-triangles.js';

/** Spare room in every buffer, so that edits rarely need a fresh layout. */
const SPARE = 1024;

/** Moved vertices above which a mesh with polygons has every face laid again, in one range, rather than the polygons around each. */
const EVERY_FACE_ABOVE = 4096;

/**
 * A change that writes more pointers and flags than this share of the mesh's halfedges is laid
 * out afresh: the sets of touched elements would cost more than a pass over everything, and the
 * page more to patch its copy than to take a new one. (Moved positions alone do not count: a
 * smoothing step writes one range of them.)
 */
const RELAYOUT_SHARE = 1 / 4;

export class RenderLayout {
  private faceStart = new Int32Array(0);
  /** The triangles each face's range holds room for (a face that shrank keeps its range)… */
  private faceRoom = new Int32Array(0);
  /** …and the triangles it draws now (more than one: a polygon). */
  private faceCount = new Int32Array(0);
  private trianglesUsed = 0;
  private capacity = { vertices: 0, edges: 0, triangles: 0 };
  /** Faces with more than three sides: a vertex that moves may change their triangles. */
  private polygons = 0;
  /** Whether the page picks in its worker (decided at the last full layout): patches then carry its copies. */
  private pickingInWorker = false;

  /** Every buffer laid out afresh, with room to grow. */
  full(mesh: HalfedgeMesh): RenderBuffers {
    const vertexRoom = mesh.vertexSlots + SPARE;
    const edgeRoom = mesh.edgeSlots + SPARE;
    const positions = new Float32Array(3 * vertexRoom);
    positions.set(mesh.positions.subarray(0, 3 * mesh.vertexSlots));
    const vertices = new Uint32Array(vertexRoom);
    const fallback = liveVertex(mesh);
    for (let v = 0; v < mesh.vertexSlots; v++) vertices[v] = mesh.vDeleted[v] ? fallback : v;
    const edges = new Uint32Array(2 * edgeRoom);
    for (let e = 0; e < mesh.edgeSlots; e++) writeEdge(mesh, e, edges, 2 * e);

    // a face of degree d draws d − 2 triangles: the halfedges inside faces, less two per face
    const { heFace, eDeleted } = mesh;
    let count = -2 * mesh.nFaces;
    for (let h = 0; h < mesh.halfedgeSlots; h++) if (heFace[h] !== -1 && !eDeleted[h >> 1]) count++;
    const triangleRoom = count + 2 * SPARE;
    const triangles = new Uint32Array(3 * triangleRoom);
    const triangleFace = new Int32Array(triangleRoom).fill(-1);
    this.faceStart = new Int32Array(mesh.faceSlots + SPARE);
    this.faceRoom = new Int32Array(mesh.faceSlots + SPARE);
    this.faceCount = new Int32Array(mesh.faceSlots + SPARE);
    this.trianglesUsed = 0;
    this.polygons = 0;
    for (let f = 0; f < mesh.faceSlots; f++) {
      if (mesh.fDeleted[f]) continue;
      this.faceStart[f] = this.trianglesUsed;
      this.faceCount[f] = this.faceRoom[f] = layFace(mesh, f, this.trianglesUsed, triangles, triangleFace);
      this.trianglesUsed += this.faceCount[f];
      if (this.faceCount[f] > 1) this.polygons++;
    }
    this.capacity = { vertices: vertexRoom, edges: edgeRoom, triangles: triangleRoom };
    const used = this.counts(mesh);
    this.pickingInWorker = used.triangles > PICK_IN_WORKER_ABOVE;
    return {
      positions,
      vertices,
      edges,
      triangles,
      triangleFace,
      counts: used,
      planeNormal: planeNormal(mesh),
      bounds: renderBounds(mesh),
      picking: this.pickingInWorker ? { positions: positions.slice(), triangles: triangles.slice(0, 3 * used.triangles) } : null,
    };
  }

  /**
   * The writes that bring the page's buffers from the mesh before `change` to `mesh` (after it),
   * or null when they do not fit the room left, or the change rewrites most of the mesh (lay the
   * mesh out afresh with `full`).
   */
  patch(mesh: HalfedgeMesh, change: ChangeRecord): RenderPatch | null {
    if (mesh.vertexSlots > this.capacity.vertices || mesh.edgeSlots > this.capacity.edges || mesh.faceSlots > this.faceStart.length) return null;
    const written = change.pointers.array.length + change.ranges.reduce((sum, range) => sum + range.new.length, 0);
    if (written > RELAYOUT_SHARE * Math.max(SPARE, mesh.halfedgeSlots)) return null;
    const touched = touchedBy(mesh, change);
    const writes: RenderWrite[] = [];
    if (this.polygons > 0) {
      // a moved corner can change how a polygon splits into triangles: those polygons are drawn
      // again; when many corners moved (a smoothing step, a subdivision's vertex points), every
      // face, in one range
      const onlyMoved = change.pointers.array.length === 0 && touched.vertices.size + touched.edges.size + touched.faces.size === 0;
      if (onlyMoved && movedCount(touched.moved) > EVERY_FACE_ABOVE) {
        // a mesh of quads (a Catmull-Clark level) redraws only the quads whose diagonal changed
        const flipped = this.quadsSplitAnew(mesh, touched.moved);
        if (flipped === null || flipped.length > EVERY_FACE_ABOVE) writes.push(...this.everyFace(mesh));
        else for (const f of flipped) touched.faces.add(f);
      }
      else forEachMoved(touched.moved, (v) => this.polygonsAround(mesh, v, touched.faces));
    }
    const fallback = liveVertex(mesh);

    const positions = positionWrites(mesh, touched.moved, touched.vertices);
    writes.push(...positions);
    for (const v of touched.vertices) writes.push({ buffer: 'vertices', offset: v, data: Uint32Array.of(mesh.vDeleted[v] ? fallback : v) });
    for (const e of touched.edges) {
      const data = new Uint32Array(2);
      writeEdge(mesh, e, data, 0);
      writes.push({ buffer: 'edges', offset: 2 * e, data });
    }
    for (const f of touched.faces) {
      const wasPolygon = this.faceCount[f] > 1;
      const corners = f < mesh.faceSlots && !mesh.fDeleted[f] ? faceTriangles(mesh, f) : new Uint32Array(0);
      const count = corners.length / 3;
      this.polygons += (count > 1 ? 1 : 0) - (wasPolygon ? 1 : 0);
      this.faceCount[f] = count;
      let start = this.faceStart[f];
      if (count > this.faceRoom[f]) {
        // the old range is too small: blank it and move the face to the end
        if (this.faceRoom[f] > 0) writes.push(...blank(start, this.faceRoom[f]));
        if (this.trianglesUsed + count > this.capacity.triangles) return null;
        start = this.faceStart[f] = this.trianglesUsed;
        this.trianglesUsed += count;
        this.faceRoom[f] = count;
      }
      const data = new Uint32Array(3 * this.faceRoom[f]);
      const faces = new Int32Array(this.faceRoom[f]).fill(-1);
      writeTriangles(corners, f, 0, data, faces);
      if (data.length > 0) writes.push({ buffer: 'triangles', offset: 3 * start, data }, { buffer: 'triangleFace', offset: start, data: faces });
    }
    const picking = this.pickingInWorker ? writes.filter((w) => w.buffer === 'positions' || w.buffer === 'triangles').map((w) => ({ ...w, data: w.data.slice() })) : null;
    return { writes, counts: this.counts(mesh), picking, bounds: positions.reduce((sum, w) => sum + w.data.length / 3, 0) > REBOUND_ABOVE ? renderBounds(mesh) : null };
  }

  /**
   * The triangles of every face, each at its range, as one write of the buffers in use: a polygon
   * keeps its number of sides when its corners move, so every range keeps its size.
   */
  private everyFace(mesh: HalfedgeMesh): RenderWrite[] {
    const triangles = new Uint32Array(3 * this.trianglesUsed);
    const triangleFace = new Int32Array(this.trianglesUsed).fill(-1);
    for (let f = 0; f < mesh.faceSlots; f++) if (!mesh.fDeleted[f]) this.faceCount[f] = layFace(mesh, f, this.faceStart[f], triangles, triangleFace);
    return [
      { buffer: 'triangles', offset: 0, data: triangles },
      { buffer: 'triangleFace', offset: 0, data: triangleFace },
    ];
  }

  /**
   * After only vertices moved: the quads that split along the other diagonal now (see
   * `quadSplitCorner`), or null when a face has more than four sides (its triangles may change
   * in more ways: lay every face again). One pass over the faces, where laying them all again
   * sent every triangle to the page.
   */
  private quadsSplitAnew(mesh: HalfedgeMesh, moved: ValueChange[]): number[] | null {
    const { heNext, heVertex, fHalfedge, fDeleted, positions } = mesh;
    const old = positions.slice(0, 3 * mesh.vertexSlots);
    for (const value of moved) {
      if (!value.old) continue;
      if (!value.index) old.set(value.old, 3 * value.start);
      else value.index.forEach((v, i) => old.set(value.old!.subarray(3 * i, 3 * i + 3), 3 * v));
    }
    const flipped: number[] = [];
    for (let f = 0; f < mesh.faceSlots; f++) {
      if (fDeleted[f] || this.faceCount[f] < 2) continue;
      if (this.faceCount[f] > 2) return null;
      const h0 = fHalfedge[f];
      const h1 = heNext[h0];
      const h2 = heNext[h1];
      const a = heVertex[h0];
      const b = heVertex[h1];
      const c = heVertex[h2];
      const d = heVertex[heNext[h2]];
      if (quadSplitCorner(old, a, b, c, d) !== quadSplitCorner(positions, a, b, c, d)) flipped.push(f);
    }
    return flipped;
  }

  /** Adds the faces of more than three sides around vertex `v` to `faces`. */
  private polygonsAround(mesh: HalfedgeMesh, v: number, faces: Set<number>): void {
    const start = mesh.vHalfedge[v];
    if (start < 0) return;
    let h = start;
    let steps = 0;
    do {
      const f = mesh.heFace[h];
      if (f >= 0 && this.faceCount[f] > 1) faces.add(f);
      h = mesh.hePrev[h] ^ 1;
    } while (h !== start && ++steps < mesh.halfedgeSlots);
  }

  private counts(mesh: HalfedgeMesh): RenderBuffers['counts'] {
    return { vertices: mesh.vertexSlots, edges: mesh.edgeSlots, triangles: this.trianglesUsed };
  }
}

/**
 * The vertices, edges and faces whose drawing a change alters, and the position changes that
 * moved vertices (kept as the record has them: a smoothing step's is one range of every vertex,
 * which is never listed id by id).
 */
function touchedBy(mesh: HalfedgeMesh, change: ChangeRecord): { vertices: Set<number>; edges: Set<number>; faces: Set<number>; moved: ValueChange[] } {
  const vertices = new Set<number>();
  const edges = new Set<number>();
  const faces = new Set<number>();
  const { before, after } = change;
  for (let v = before.vertexSlots; v < after.vertexSlots; v++) vertices.add(v);
  for (let e = before.edgeSlots; e < after.edgeSlots; e++) edges.add(e);
  for (let f = before.faceSlots; f < after.faceSlots; f++) faces.add(f);
  forEachPointerWrite(change, (array, id, old, now) => {
    switch (array) {
      case meshArrayIndex.heVertex:
        edges.add(id >> 1);
        if (mesh.heFace[id] >= 0) faces.add(mesh.heFace[id]);
        break;
      case meshArrayIndex.heFace:
        if (old >= 0) faces.add(old);
        if (now >= 0) faces.add(now);
        break;
      case meshArrayIndex.heNext:
        if (mesh.heFace[id] >= 0) faces.add(mesh.heFace[id]);
        break;
      case meshArrayIndex.eDeleted:
        edges.add(id);
        break;
      case meshArrayIndex.vDeleted:
        vertices.add(id);
        break;
      case meshArrayIndex.fDeleted:
      case meshArrayIndex.fHalfedge:
        faces.add(id);
        break;
    }
  });
  const moved = change.values.filter((value) => value.kind === 'vertex' && value.name === 'position');
  return { vertices, edges, faces, moved };
}

function movedCount(moved: ValueChange[]): number {
  return moved.reduce((sum, value) => sum + value.new.length / value.itemSize, 0);
}

function forEachMoved(moved: ValueChange[], visit: (v: number) => void): void {
  for (const value of moved) {
    const count = value.new.length / value.itemSize;
    for (let i = 0; i < count; i++) visit(value.index ? value.index[i] : value.start + i);
  }
}

/**
 * The positions of the moved and the touched vertices: a few one by one; many (a smoothing step)
 * as one range from the first to the last.
 */
function positionWrites(mesh: HalfedgeMesh, moved: ValueChange[], touched: Set<number>): RenderWrite[] {
  const at = (v: number) => ({ buffer: 'positions' as const, offset: 3 * v, data: Float32Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)) });
  if (movedCount(moved) + touched.size <= 64) {
    const writes: RenderWrite[] = [...touched].map(at);
    forEachMoved(moved, (v) => writes.push(at(v)));
    return writes;
  }
  let first = Infinity;
  let last = -1;
  const include = (v: number) => {
    first = Math.min(first, v);
    last = Math.max(last, v);
  };
  touched.forEach(include);
  for (const value of moved) {
    if (value.index) value.index.forEach(include);
    else if (value.new.length > 0) {
      include(value.start);
      include(value.start + value.new.length / value.itemSize - 1);
    }
  }
  if (last < 0) return [];
  return [{ buffer: 'positions', offset: 3 * first, data: new Float32Array(mesh.positions.subarray(3 * first, 3 * last + 3)) }];
}

/** The box and the sphere around the live vertices (none: a point at the origin). */
export function renderBounds(mesh: HalfedgeMesh): RenderBounds {
  const box = boundingBox(mesh);
  if (!box) return { min: [0, 0, 0], max: [0, 0, 0], center: [0, 0, 0], radius: 0 };
  return { ...box, ...boundingSphere(mesh, box)! };
}

function writeEdge(mesh: HalfedgeMesh, e: number, edges: Uint32Array, at: number): void {
  const a = Math.max(0, mesh.heVertex[2 * e]);
  edges[at] = a;
  edges[at + 1] = mesh.eDeleted[e] ? a : mesh.heVertex[2 * e + 1];
}

/** Writes the triangles of face `f` from triangle `t` on; returns how many. */
function layFace(mesh: HalfedgeMesh, f: number, t: number, triangles: Uint32Array, triangleFace: Int32Array): number {
  const h = mesh.faceHalfedge(f);
  if (mesh.next(mesh.next(mesh.next(h))) === h) {
    // a triangle (most faces): its corners as they are, without a list
    triangles[3 * t] = mesh.origin(h);
    triangles[3 * t + 1] = mesh.target(h);
    triangles[3 * t + 2] = mesh.origin(mesh.prev(h));
    triangleFace[t] = f;
    return 1;
  }
  const count = writeFaceTriangles(mesh, f, triangles, t);
  triangleFace.fill(f, t, t + count);
  return count;
}

function writeTriangles(corners: Uint32Array, f: number, first: number, triangles: Uint32Array, triangleFace: Int32Array): void {
  triangles.set(corners, 3 * first);
  triangleFace.fill(f, first, first + corners.length / 3);
}

/** Triangles of no area over a range a face left. */
function blank(start: number, count: number): RenderWrite[] {
  return [
    { buffer: 'triangles', offset: 3 * start, data: new Uint32Array(3 * count) },
    { buffer: 'triangleFace', offset: start, data: new Int32Array(count).fill(-1) },
  ];
}

function liveVertex(mesh: HalfedgeMesh): number {
  for (let v = 0; v < mesh.vertexSlots; v++) if (!mesh.vDeleted[v]) return v;
  return 0;
}

/** The normal of the plane every face lies in (a 2D mesh), or null. */
export function planeNormal(mesh: HalfedgeMesh): [number, number, number] | null {
  let reference: number[] | null = null;
  const n = [0, 0, 0];
  for (let f = 0; f < mesh.faceSlots; f++) {
    if (mesh.fDeleted[f]) continue;
    faceNormal(mesh, f, n);
    if (n[0] === 0 && n[1] === 0 && n[2] === 0) continue;
    if (!reference) reference = [...n];
    else if (Math.abs(reference[0] * n[0] + reference[1] * n[1] + reference[2] * n[2]) < 0.9999) return null;
  }
  return reference as [number, number, number] | null;
}
