/**
 * The halfedge mesh: every edge is two opposite *halfedges*, and every halfedge knows
 * the halfedge after it (`next`) and before it (`prev`) around the face on its left, the vertex it
 * starts from (`origin`) and that face (`face`).
 *
 * ```
 *            target = origin(next(h))
 *                 ▲ │
 *        next(h) ╱  │
 *               ╱ h │ twin(h)
 *    face(h)   ╱    │
 *             ╱     ▼
 *       prev(h)  origin(h)
 * ```
 *
 * Storage is index-based and struct-of-arrays: elements are integers, relations are `Int32Array`s
 * named owner + relation (`heNext`, `heVertex`, `vHalfedge`, `fHalfedge`), and `-1` is the one
 * "none". Indices carry what can be derived:
 *   - the two halfedges of edge `e` are `2e` and `2e + 1`, so `twin(h) = h ^ 1` and `edge(h) = h >> 1`;
 *   - `target(h) = origin(next(h))`.
 *
 * Conventions (written down once; `validate()` checks every one):
 *   - faces lie on the **left** of their halfedges, which run **counter-clockwise** seen from outside;
 *   - a **boundary halfedge** has `face = -1` but still links `next`/`prev` around its hole, so
 *     every halfedge lies on exactly one closed cycle;
 *   - a boundary vertex's halfedge (`vHalfedge`) is its outgoing boundary halfedge, so "is this
 *     vertex on the boundary?" is one lookup;
 *   - an isolated vertex has `vHalfedge = -1`;
 *   - every vertex has one fan of faces (the mesh is manifold): the builder duplicates pinched
 *     vertices to make it so.
 *
 * Deleted elements stay in their slots, flagged in `vDeleted`, `eDeleted` or `fDeleted`, until
 * `compact()` renumbers the live ones. Algorithms may loop over `0 … slots - 1` without checking
 * the flags when `isCompact` is true (always, right after a build).
 */
import { AttributeSet } from './attributes.js';
import { InvalidInputError, TopologyError } from './errors.js';
import { attributeSetOf, type ElementKind, elementKinds, lengthsByKind, meshArrays, roomByKind, setMeshArray, slotCount } from './mesh-arrays.js';
import { byteSum, type Memory, newArrayLike } from './memory.js';
import { clearedFlags, permuteItems, Scratch } from './permute.js';

export interface MeshCapacity {
  vertices: number;
  edges: number;
  faces: number;
}

/** Old id → new id (-1 for a deleted element), as returned by `compact()` and taken by `renumber()`. */
export interface CompactionMaps {
  vertices: Int32Array;
  edges: Int32Array;
  faces: Int32Array;
}

export class HalfedgeMesh {
  /** Next halfedge around the face (or hole) on the left. */
  heNext!: Int32Array;
  /** Previous halfedge around the face (or hole) on the left. */
  hePrev!: Int32Array;
  /** The vertex a halfedge starts from. */
  heVertex!: Int32Array;
  /** The face on the left, or -1 for a boundary halfedge. */
  heFace!: Int32Array;
  /** One outgoing halfedge per vertex: the boundary one on the boundary, -1 when isolated. */
  vHalfedge!: Int32Array;
  /** One halfedge of each face. */
  fHalfedge!: Int32Array;
  /** 1 where the slot is deleted. */
  vDeleted!: Uint8Array;
  eDeleted!: Uint8Array;
  fDeleted!: Uint8Array;

  /** Vertex, edge and face slots in use, deleted ones included. Halfedge slots are `2 × edgeSlots`. */
  vertexSlots = 0;
  edgeSlots = 0;
  faceSlots = 0;

  private deletedVertices = 0;
  private deletedEdges = 0;
  private deletedFaces = 0;

  readonly vertexAttributes: AttributeSet;
  readonly halfedgeAttributes: AttributeSet;
  readonly edgeAttributes: AttributeSet;
  readonly faceAttributes: AttributeSet;

  constructor(capacity: MeshCapacity = { vertices: 0, edges: 0, faces: 0 }) {
    const { vertices, edges, faces } = capacity;
    const length = lengthsByKind(capacity);
    for (const spec of meshArrays) setMeshArray(this, spec.name, new spec.type(length[spec.owner]));
    this.vertexAttributes = new AttributeSet(vertices);
    this.halfedgeAttributes = new AttributeSet(2 * edges);
    this.edgeAttributes = new AttributeSet(edges);
    this.faceAttributes = new AttributeSet(faces);
    this.vertexAttributes.add('position', 'float64', 3);
  }

  // ---------------------------------------------------------------------------------------------
  // Navigation (O(1) each)

  next(h: number): number {
    return this.heNext[h];
  }
  prev(h: number): number {
    return this.hePrev[h];
  }
  twin(h: number): number {
    return h ^ 1;
  }
  edge(h: number): number {
    return h >> 1;
  }
  origin(h: number): number {
    return this.heVertex[h];
  }
  target(h: number): number {
    return this.heVertex[this.heNext[h]];
  }
  face(h: number): number {
    return this.heFace[h];
  }
  /** An outgoing halfedge of `v` (its boundary one if `v` is on the boundary), or -1 if isolated. */
  vertexHalfedge(v: number): number {
    return this.vHalfedge[v];
  }
  faceHalfedge(f: number): number {
    return this.fHalfedge[f];
  }
  edgeHalfedge(e: number): number {
    return 2 * e;
  }

  isBoundaryHalfedge(h: number): boolean {
    return this.heFace[h] === -1;
  }
  isBoundaryEdge(e: number): boolean {
    return this.heFace[2 * e] === -1 || this.heFace[2 * e + 1] === -1;
  }
  isBoundaryVertex(v: number): boolean {
    const h = this.vHalfedge[v];
    return h >= 0 && this.heFace[h] === -1;
  }
  isIsolatedVertex(v: number): boolean {
    return this.vHalfedge[v] === -1;
  }
  /** True when the face touches a hole along one of its edges. */
  isBoundaryFace(f: number): boolean {
    const start = this.fHalfedge[f];
    let h = start;
    let steps = 0;
    do {
      if (this.heFace[h ^ 1] === -1) return true;
      h = this.heNext[h];
      if (++steps > this.halfedgeSlots) throw new TopologyError(`the next cycle of f${f} does not close`);
    } while (h !== start);
    return false;
  }

  /** Number of sides of face `f` (or of the hole that `h` runs around, with `loopLength`). */
  faceDegree(f: number): number {
    return this.loopLength(this.fHalfedge[f]);
  }
  /** Number of halfedges on the `next` cycle through `h`. */
  loopLength(h: number): number {
    let n = 0;
    let g = h;
    do {
      n++;
      g = this.heNext[g];
      if (n > this.halfedgeSlots) throw new TopologyError(`the next cycle from h${h} does not close`);
    } while (g !== h);
    return n;
  }
  /** Number of edges at `v` (0 for an isolated vertex). */
  vertexDegree(v: number): number {
    const start = this.vHalfedge[v];
    if (start < 0) return 0;
    let n = 0;
    let h = start;
    do {
      n++;
      h = this.hePrev[h] ^ 1;
      if (n > this.halfedgeSlots) throw new TopologyError(`the rotation around v${v} does not close`);
    } while (h !== start);
    return n;
  }

  // ---------------------------------------------------------------------------------------------
  // Counts and liveness

  get positions(): Float64Array {
    return this.vertexAttributes.get('position')!.data as Float64Array;
  }
  get halfedgeSlots(): number {
    return 2 * this.edgeSlots;
  }
  get nVertices(): number {
    return this.vertexSlots - this.deletedVertices;
  }
  get nEdges(): number {
    return this.edgeSlots - this.deletedEdges;
  }
  get nHalfedges(): number {
    return 2 * this.nEdges;
  }
  get nFaces(): number {
    return this.faceSlots - this.deletedFaces;
  }
  /** True when no slot is deleted, so `0 … slots - 1` are all live elements. */
  get isCompact(): boolean {
    return this.deletedVertices === 0 && this.deletedEdges === 0 && this.deletedFaces === 0;
  }

  isVertexDeleted(v: number): boolean {
    return this.vDeleted[v] === 1;
  }
  isEdgeDeleted(e: number): boolean {
    return this.eDeleted[e] === 1;
  }
  isHalfedgeDeleted(h: number): boolean {
    return this.eDeleted[h >> 1] === 1;
  }
  isFaceDeleted(f: number): boolean {
    return this.fDeleted[f] === 1;
  }

  *vertices(): Generator<number> {
    for (let v = 0; v < this.vertexSlots; v++) if (this.vDeleted[v] === 0) yield v;
  }
  *edges(): Generator<number> {
    for (let e = 0; e < this.edgeSlots; e++) if (this.eDeleted[e] === 0) yield e;
  }
  *halfedges(): Generator<number> {
    for (let h = 0; h < 2 * this.edgeSlots; h++) if (this.eDeleted[h >> 1] === 0) yield h;
  }
  *faces(): Generator<number> {
    for (let f = 0; f < this.faceSlots; f++) if (this.fDeleted[f] === 0) yield f;
  }

  /** Position of `v` as `[x, y, z]` (written into `out` when given). */
  position(v: number, out: number[] = [0, 0, 0]): number[] {
    const p = this.positions;
    out[0] = p[3 * v];
    out[1] = p[3 * v + 1];
    out[2] = p[3 * v + 2];
    return out;
  }
  setPosition(v: number, x: number, y: number, z: number): void {
    const p = this.positions;
    p[3 * v] = x;
    p[3 * v + 1] = y;
    p[3 * v + 2] = z;
  }

  // ---------------------------------------------------------------------------------------------
  // Growth. New elements come with every relation -1: the caller wires them, then `validate()`.

  /**
   * Makes room for at least this many slots of each kind, without changing any element. The
   * arrays that grow are made anew in `memory`.
   */
  reserve(capacity: Partial<MeshCapacity>, memory?: Memory): void {
    const { vertices = 0, edges = 0, faces = 0 } = capacity;
    const wanted = lengthsByKind({ vertices, edges, faces });
    // decided before any array grows (the capacities are read off the arrays themselves)
    const room = roomByKind(this);
    const grows = (kind: ElementKind) => wanted[kind] > room[kind];
    for (const spec of meshArrays) {
      if (grows(spec.owner)) setMeshArray(this, spec.name, grow(this[spec.name], wanted[spec.owner], slotCount(this, spec.owner), memory));
    }
    for (const kind of elementKinds) {
      if (grows(kind)) attributeSetOf(this, kind).resize(wanted[kind], slotCount(this, kind), memory);
    }
  }

  /** Adds a vertex at (x, y, z), isolated; its other attributes are zero. */
  addVertex(x = 0, y = 0, z = 0): number {
    this.makeRoom({ vertices: this.vertexSlots + 1, edges: 0, faces: 0 });
    const v = this.vertexSlots++;
    this.vHalfedge[v] = -1;
    this.vDeleted[v] = 0;
    this.setPosition(v, x, y, z);
    return v;
  }

  /** Adds an edge; its halfedges are `2e` and `2e + 1`, with every relation -1 and zeroed attributes. */
  addEdge(): number {
    this.makeRoom({ vertices: 0, edges: this.edgeSlots + 1, faces: 0 });
    const e = this.edgeSlots++;
    this.eDeleted[e] = 0;
    for (let h = 2 * e; h < 2 * e + 2; h++) {
      this.heNext[h] = -1;
      this.hePrev[h] = -1;
      this.heVertex[h] = -1;
      this.heFace[h] = -1;
    }
    return e;
  }

  /** Adds a face with no halfedge yet; set `fHalfedge` and the loop's `heFace` next. */
  addFace(): number {
    this.makeRoom({ vertices: 0, edges: 0, faces: this.faceSlots + 1 });
    const f = this.faceSlots++;
    this.fHalfedge[f] = -1;
    this.fDeleted[f] = 0;
    return f;
  }

  /** Marks a vertex deleted. The caller has already unlinked it. */
  deleteVertex(v: number): void {
    if (this.vDeleted[v] === 1) return;
    this.vDeleted[v] = 1;
    this.vHalfedge[v] = -1;
    this.deletedVertices++;
  }
  /** Marks an edge (both halfedges) deleted. The caller has already unlinked it. */
  deleteEdge(e: number): void {
    if (this.eDeleted[e] === 1) return;
    this.eDeleted[e] = 1;
    for (let h = 2 * e; h < 2 * e + 2; h++) {
      this.heNext[h] = this.hePrev[h] = this.heVertex[h] = this.heFace[h] = -1;
    }
    this.deletedEdges++;
  }
  /** Marks a face deleted. The caller has already unlinked it. */
  deleteFace(f: number): void {
    if (this.fDeleted[f] === 1) return;
    this.fDeleted[f] = 1;
    this.fHalfedge[f] = -1;
    this.deletedFaces++;
  }

  /**
   * Sizes every array to the slots in use plus `spare` more of each kind: gives back what growth
   * left behind, or keeps a little room so that the next edits do not copy the whole mesh to grow.
   */
  trim(spare = 0): void {
    const room = lengthsByKind({ vertices: spare, edges: spare, faces: spare });
    for (const spec of meshArrays) {
      const array = this[spec.name];
      const slots = slotCount(this, spec.owner);
      if (array.length !== slots + room[spec.owner]) setMeshArray(this, spec.name, grow(array, slots + room[spec.owner], slots));
    }
    for (const kind of elementKinds) {
      const slots = slotCount(this, kind);
      attributeSetOf(this, kind).resize(slots + room[kind], slots);
    }
  }

  /** Makes room for this many slots of each kind, growing by half again when it must grow (so growth is rare). */
  makeRoom(capacity: MeshCapacity): void {
    // the common case, on every element added: everything fits already
    if (capacity.vertices <= this.vHalfedge.length && capacity.edges <= this.eDeleted.length && capacity.faces <= this.fHalfedge.length) return;
    const room = (wanted: number, now: number) => (wanted <= now ? 0 : Math.max(wanted, nextCapacity(now)));
    this.reserve({
      vertices: room(capacity.vertices, this.vHalfedge.length),
      edges: room(capacity.edges, this.eDeleted.length),
      faces: room(capacity.faces, this.fHalfedge.length),
    });
  }

  /** Recounts the deleted slots from the flags (after the arrays were replaced wholesale). */
  recountDeleted(): void {
    this.deletedVertices = byteSum(this.vDeleted, this.vertexSlots);
    this.deletedEdges = byteSum(this.eDeleted, this.edgeSlots);
    this.deletedFaces = byteSum(this.fDeleted, this.faceSlots);
  }

  /**
   * Removes deleted slots, renumbering the live elements in their current order, and shrinks the
   * arrays to fit. Returns old → new id maps (-1 for the deleted) so callers can follow selections.
   */
  compact(): CompactionMaps {
    const maps: CompactionMaps = {
      vertices: liveMap(this.vertexSlots, (v) => this.vDeleted[v] === 0),
      edges: liveMap(this.edgeSlots, (e) => this.eDeleted[e] === 0),
      faces: liveMap(this.faceSlots, (f) => this.fDeleted[f] === 0),
    };
    this.applyRenumbering(maps);
    return maps;
  }

  /**
   * Gives every live element the new id its map says (old id → new id), dropping the deleted
   * ones (-1), and shrinks the arrays to fit: `compact()` keeps the order, `spatialOrder` makes one.
   * The maps must send the live elements of each kind onto 0 … (live count − 1), once each.
   * @throws InvalidInputError naming the first element whose new id is missing, out of range or
   *   taken twice, or a map of the wrong length (nothing is changed).
   */
  renumber(maps: CompactionMaps): void {
    checkRenumbering(maps.vertices, this.vertexSlots, this.nVertices, this.vDeleted, 'v');
    checkRenumbering(maps.edges, this.edgeSlots, this.nEdges, this.eDeleted, 'e');
    checkRenumbering(maps.faces, this.faceSlots, this.nFaces, this.fDeleted, 'f');
    this.applyRenumbering(maps);
  }

  /** `renumber` without the check, for maps made right by construction (`compact`). */
  private applyRenumbering(maps: CompactionMaps): void {
    const edge = maps.edges;
    const halfedge = new Int32Array(2 * this.edgeSlots);
    for (let e = 0; e < this.edgeSlots; e++) {
      const ne = edge[e];
      halfedge[2 * e] = ne < 0 ? -1 : 2 * ne;
      halfedge[2 * e + 1] = ne < 0 ? -1 : 2 * ne + 1;
    }
    const byKind: Record<ElementKind, Int32Array> = { vertex: maps.vertices, halfedge, edge, face: maps.faces };
    const live: Record<ElementKind, number> = { vertex: this.nVertices, halfedge: 2 * this.nEdges, edge: this.nEdges, face: this.nFaces };
    const scratch = new Scratch();
    for (const spec of meshArrays) {
      const old = this[spec.name];
      const count = live[spec.owner];
      const next = spec.refers ? permuteItems(old, 1, byKind[spec.owner], count, scratch, byKind[spec.refers]) : clearedFlags(old, count);
      setMeshArray(this, spec.name, next);
    }
    for (const kind of elementKinds) attributeSetOf(this, kind).permute(byKind[kind], live[kind], scratch);
    this.vertexSlots = live.vertex;
    this.edgeSlots = live.edge;
    this.faceSlots = live.face;
    this.deletedVertices = this.deletedEdges = this.deletedFaces = 0;
  }

  /** A deep copy, attributes included, with no spare capacity. */
  clone(): HalfedgeMesh {
    const copy = Object.create(HalfedgeMesh.prototype) as HalfedgeMesh;
    Object.assign(copy, {
      vertexSlots: this.vertexSlots,
      edgeSlots: this.edgeSlots,
      faceSlots: this.faceSlots,
      deletedVertices: this.deletedVertices,
      deletedEdges: this.deletedEdges,
      deletedFaces: this.deletedFaces,
    });
    for (const spec of meshArrays) setMeshArray(copy, spec.name, this[spec.name].slice(0, slotCount(this, spec.owner)));
    const sets = Object.fromEntries(
      elementKinds.map((kind) => [`${kind}Attributes`, attributeSetOf(this, kind).clone(slotCount(this, kind), slotCount(this, kind))]),
    );
    Object.assign(copy, sets);
    return copy;
  }

  /**
   * A mesh over this one's arrays as they are now, nothing copied. When this mesh then grows
   * into new arrays, the view keeps the old ones: a level reads the mesh it started from there
   * while its new arrays are being rewired. The attribute sets are this mesh's own.
   */
  view(): HalfedgeMesh {
    return Object.assign(Object.create(HalfedgeMesh.prototype) as HalfedgeMesh, this);
  }

  /**
   * The slot and deletion counts as they are, or sets them (a recorded change being applied or
   * undone: the arrays must already hold that many slots).
   */
  get slotState(): SlotState {
    const { vertexSlots, edgeSlots, faceSlots, deletedVertices, deletedEdges, deletedFaces } = this;
    return { vertexSlots, edgeSlots, faceSlots, deletedVertices, deletedEdges, deletedFaces };
  }
  set slotState(state: SlotState) {
    Object.assign(this, state);
  }
}

/** How many slots of each kind are in use, and how many of them are deleted. */
export interface SlotState {
  vertexSlots: number;
  edgeSlots: number;
  faceSlots: number;
  deletedVertices: number;
  deletedEdges: number;
  deletedFaces: number;
}

function nextCapacity(used: number): number {
  return Math.max(8, Math.ceil(used * 1.5));
}

function grow<T extends Int32Array | Uint8Array>(array: T, capacity: number, used: number, memory?: Memory): T {
  if (capacity > 0x7fffffff) throw new InvalidInputError(`a mesh cannot hold ${capacity} elements of one kind`);
  const next = newArrayLike(array, capacity, memory);
  next.set(array.subarray(0, used));
  return next;
}

/** Throws unless `map` gives each live slot (`deleted[i]` 0) its own new id in 0 … live − 1, and each deleted one -1. */
function checkRenumbering(map: Int32Array, slots: number, live: number, deleted: Uint8Array, prefix: string): void {
  if (map.length !== slots) throw new InvalidInputError(`renumber: the map of ${prefix} ids has ${map.length} entries for ${slots} slots`);
  const taken = new Uint8Array(live);
  for (let i = 0; i < slots; i++) {
    const j = map[i];
    if (deleted[i]) {
      if (j !== -1) throw new InvalidInputError(`renumber: ${prefix}${i} is deleted, so its new id must be -1, not ${j}`);
    } else if (!(j >= 0 && j < live)) {
      throw new InvalidInputError(`renumber: ${prefix}${i}'s new id ${j} is not in 0…${live - 1}`);
    } else if (taken[j]++) {
      throw new InvalidInputError(`renumber: ${prefix}${i}'s new id ${j} is taken twice`);
    }
  }
}

function liveMap(slots: number, isLive: (i: number) => boolean): Int32Array {
  const map = new Int32Array(slots);
  let next = 0;
  for (let i = 0; i < slots; i++) map[i] = isLive(i) ? next++ : -1;
  return map;
}
