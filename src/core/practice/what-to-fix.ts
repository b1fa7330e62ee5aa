/**
 * What to fix, when a solution's mesh is not the reference's: the first pointer the reference
 * sets, in the order it wrote them, that the solution leaves pointing elsewhere, said with the
 * solution's own write of it (or why it has none):
 *
 * ```
 *   the reference sets v6's halfedge to h23; your code never writes v6's halfedge, and
 *   deleteEdge(e10) at line 62 removed the one it had
 *   the reference sets h8's next to h3; your code sets it to h5: next(h8) = h5 at line 30
 *   the reference sets v2's halfedge to h28, your h27 (v2 → v7); your code never writes …
 * ```
 *
 * Then, if the reference's pointers all agree, the first the solution wrote that the reference
 * left as it was. Only pointers of elements the fixture had are compared, each where the element
 * is the same piece of the mesh in both (`Places`): the ids of new elements may differ, and a
 * solution may reuse another old element than the reference for a new piece (keep the other half
 * of a split edge), which is no mistake. What a pointer names is found in the solution's mesh by
 * where it is, so a new element is named by the solution's own id.
 */
import { faceHalfedges, vertexOutgoingHalfedges } from '../circulators.js';
import { meshArrayIndex, meshArrays, slotCount } from '../mesh-arrays.js';
import type { HalfedgeMesh } from '../mesh.js';
import { loopCorners, nearestVertexIn, sameSpotTolerance } from './compare.js';
import { describeWrite, pointerArrayOf, type PointerWriteField, type PracticeWrite } from './writes.js';

/** What the reference left, and the fields it wrote (`16 · index + array`) in the order it wrote them. */
export interface ReferenceEdit {
  mesh: HalfedgeMesh;
  order: readonly number[];
}

/** The kinds of element a pointer belongs to or names. */
type Kind = 'vertex' | 'halfedge' | 'face';

/**
 * The sentence above, for the first pointer the reference sets that `yours` (the fixture `before`
 * after the solution's `writes`) leaves otherwise; null when every pointer compared agrees.
 */
export function whatToFix(before: HalfedgeMesh, yours: HalfedgeMesh, writes: readonly PracticeWrite[], reference: ReferenceEdit): string | null {
  const places = new Places(before, yours, reference.mesh);
  const setByReference = fieldsSetBy(before, reference);
  const compared = (key: number): { field: string; said: string; now: number; kind: Kind; last: PracticeWrite | null } | null => {
    const { array, index } = fieldOf(key);
    const spec = meshArrays[array];
    // a pointer array's owner and the kind it names are never an edge
    const [owner, kind] = [spec.owner as Kind, spec.refers as Kind];
    if (index >= slotCount(before, owner) || !places.same(owner, index)) return null;
    const value = reference.mesh[spec.name][index];
    const wanted = value === -1 ? -1 : places.inYours(kind, value);
    const now = yours[spec.name][index];
    const handle = (spec.name === 'vHalfedge' || spec.name === 'fHalfedge') && value !== -1 ? places.handles(spec.name, index) : null;
    if (handle ? handle.choices.has(now) || handle.choices.size === 0 : wanted === null || now === wanted) return null;
    // the reference's own id where the solution's mesh has another at that place, or none
    const named = wanted === value ? nameOf(kind, value) : wanted === null ? `${nameOf(kind, value)} of its mesh` : `${nameOf(kind, value)}, your ${nameOf(kind, wanted)}${places.describe(kind, wanted)}`;
    const last = lastWriteOf(writes, spec.name, index);
    return { field: `${nameOf(owner, index)}'s ${spec.field}`, said: `${named}${handle?.rule ?? ''}`, now, kind, last };
  };
  const yourWrite = (now: string, last: PracticeWrite) => `your code sets it to ${now}: ${describeWrite(last)}${at(last.line)}`;

  for (const key of setByReference) {
    const found = compared(key);
    if (!found) continue;
    const { field, said, now, kind, last } = found;
    const sets = `the reference sets ${field} to ${said}`;
    if (last) return `${sets}; ${yourWrite(nameOf(kind, now), last)}`;
    const removal = now === -1 ? null : removalOf(writes, kind, now);
    if (removal) return `${sets}; your code never writes ${field}, and ${describeWrite(removal)}${at(removal.line)} removed the one it had`;
    return `${sets}; your code never writes ${field}, which is still ${nameOf(kind, now)}`;
  }
  const setKeys = new Set(setByReference);
  for (const key of new Set(writeOrderOf(writes, before))) {
    const found = setKeys.has(key) ? null : compared(key);
    if (found) return `the reference leaves ${found.field} as it was, ${found.said}; ${yourWrite(nameOf(found.kind, found.now), found.last!)}`;
  }
  return null;
}

/** The array (its place in `meshArrays`) and the element of a field numbered `16 · index + array`. */
function fieldOf(key: number): { array: number; index: number } {
  const array = key % 16;
  return { array, index: (key - array) / 16 };
}

/**
 * The pointers a traced solution wrote, `16 · index + array`, in order: a reference solution's
 * steps, as `inWriteOrder` lists an edit's. With `before`, only those of elements it had.
 */
export function writeOrderOf(writes: readonly PracticeWrite[], before?: HalfedgeMesh): number[] {
  const keys: number[] = [];
  for (const write of writes) {
    const array = pointerArrayOf[write.field as PointerWriteField];
    if (array === undefined) continue;
    const spec = meshArrays[meshArrayIndex[array]];
    if (!before || write.index < slotCount(before, spec.owner)) keys.push(16 * write.index + meshArrayIndex[array]);
  }
  return keys;
}

/**
 * The pointers the reference wrote, each once, in the order it first wrote them; then any it
 * changed without its writes being followed (an operation that writes its arrays in bulk), by
 * element, as a record lists them.
 */
function fieldsSetBy(before: HalfedgeMesh, reference: ReferenceEdit): number[] {
  const { mesh } = reference;
  const keys = new Set(reference.order.filter((key) => meshArrays[key % 16].refers !== null));
  for (const spec of meshArrays) {
    if (spec.refers === null) continue;
    const array = meshArrayIndex[spec.name];
    for (let index = 0; index < slotCount(before, spec.owner); index++) {
      if (mesh[spec.name][index] !== before[spec.name][index]) keys.add(16 * index + array);
    }
  }
  return [...keys];
}

/**
 * Where the reference's elements are in the solution's mesh. `same`: an element of the fixture
 * stands for the same piece of the mesh in both, so its pointers can be compared: a vertex still
 * there; a halfedge with one end at least where the reference has it (both ends elsewhere is
 * another halfedge, not a wrong one); a face named by most of the halfedges round it in the
 * reference (its own handle may be the pointer that is wrong). `inYours`: the element of the
 * solution's mesh at the place of one of the reference's, by id where that id is at that place,
 * else found there (a vertex by its position, a halfedge by its ends, a face by its halfedges).
 */
class Places {
  private readonly tolerance: number;
  /** What `inYours` found so far, by kind: a found element, or -2 for none (-1 is not an element). */
  private readonly found = { vertex: new Map<number, number>(), halfedge: new Map<number, number>(), face: new Map<number, number>() };
  private vertexAt: ((p: number[]) => number) | null = null;
  /** Your halfedges by the vertices they join, `from · vertexSlots + to`. */
  private halfedgeJoining: Map<number, number> | null = null;

  constructor(
    private readonly before: HalfedgeMesh,
    private readonly yours: HalfedgeMesh,
    private readonly reference: HalfedgeMesh,
  ) {
    this.tolerance = sameSpotTolerance(reference);
  }

  same(kind: Kind, id: number): boolean {
    const { yours, reference } = this;
    if (!live(yours, kind, id) || !live(reference, kind, id)) return false;
    if (kind === 'vertex') return true;
    if (kind === 'halfedge') return this.inYours('vertex', reference.heVertex[id]) === yours.heVertex[id] || this.inYours('vertex', reference.heVertex[id ^ 1]) === yours.heVertex[id ^ 1];
    return this.inYours('face', id) === id;
  }

  /** The solution's element at the place of the reference's `id`, or null when it has none there. */
  inYours(kind: Kind, id: number): number | null {
    const known = this.found[kind].get(id);
    if (known !== undefined) return known === -2 ? null : known;
    const mine = live(this.reference, kind, id) ? (kind === 'vertex' ? this.vertexFor(id) : kind === 'halfedge' ? this.halfedgeAt(id) : this.faceAt(id)) : null;
    this.found[kind].set(id, mine ?? -2);
    return mine;
  }

  /** A vertex of the fixture stays itself while it lives; any other is found by its position. */
  private vertexFor(id: number): number | null {
    if (id < this.before.vertexSlots && live(this.yours, 'vertex', id)) return id;
    this.vertexAt ??= nearestVertexIn(this.yours, this.tolerance);
    const v = this.vertexAt(this.reference.position(id));
    return v === -1 ? null : v;
  }

  /** The halfedge joining the same places, the one of the same id first. */
  private halfedgeAt(id: number): number | null {
    const { yours, reference } = this;
    const [from, to] = [this.inYours('vertex', reference.heVertex[id]), this.inYours('vertex', reference.heVertex[id ^ 1])];
    if (from === null || to === null) return null;
    if (live(yours, 'halfedge', id) && yours.heVertex[id] === from && yours.heVertex[id ^ 1] === to) return id;
    const n = yours.vertexSlots;
    if (!this.halfedgeJoining) {
      this.halfedgeJoining = new Map();
      for (const h of yours.halfedges()) {
        const key = yours.heVertex[h] * n + yours.heVertex[h ^ 1];
        if (!this.halfedgeJoining.has(key)) this.halfedgeJoining.set(key, h);
      }
    }
    return this.halfedgeJoining.get(from * n + to) ?? null;
  }

  /** Where an element `inYours` found is, in the solution's mesh: ` (v2 → v7)`, ` (at (0.5, 0, 0))`, ` (v2 → v7 → v5)`, or nothing for a face without a live halfedge. */
  describe(kind: Kind, id: number): string {
    const { yours } = this;
    if (kind === 'vertex') return ` (at (${yours.position(id).map((x) => Math.round(x * 1e4) / 1e4).join(', ')}))`;
    if (kind === 'halfedge') return ` (v${yours.heVertex[id]} → v${yours.heVertex[id ^ 1]})`;
    const start = yours.fHalfedge[id];
    return live(yours, 'halfedge', start) ? ` (${loopCorners(yours, start).map((v) => `v${v}`).join(' → ')})` : '';
  }

  /**
   * A vertex's or a face's halfedge, which the convention leaves open: the solution's halfedges that
   * would do as well as the reference's (leaving the vertex, and on the boundary where the
   * reference's is; round the face), and the rule in words.
   */
  handles(array: 'vHalfedge' | 'fHalfedge', id: number): { choices: Set<number>; rule: string } {
    const { reference } = this;
    const mine = (halfedges: number[]) => new Set(halfedges.map((h) => this.inYours('halfedge', h)).filter((h) => h !== null));
    if (array === 'fHalfedge') return { choices: mine([...faceHalfedges(reference, id)]), rule: ` (or any other halfedge of f${id})` };
    const boundary = reference.heFace[reference.vHalfedge[id]] === -1;
    const leaving = [...vertexOutgoingHalfedges(reference, id)].filter((h) => !boundary || reference.heFace[h] === -1);
    return { choices: mine(leaving), rule: ` (or any other ${boundary ? 'boundary ' : ''}halfedge leaving v${id})` };
  }

  /** The solution's face that more than half the halfedges round the reference's face `f` are in, or null. */
  private faceAt(f: number): number | null {
    const { yours, reference } = this;
    const counts = new Map<number, number>();
    let sides = 0;
    const start = reference.fHalfedge[f];
    let h = start;
    // the reference is valid, so its cycle closes; bounded all the same
    do {
      sides++;
      const mine = this.inYours('halfedge', h);
      if (mine !== null && yours.heFace[mine] !== -1) counts.set(yours.heFace[mine], (counts.get(yours.heFace[mine]) ?? 0) + 1);
      h = reference.heNext[h];
    } while (h !== start && sides <= reference.halfedgeSlots);
    for (const [face, count] of counts) if (2 * count > sides) return face;
    return null;
  }
}

function live(mesh: HalfedgeMesh, kind: Kind, id: number): boolean {
  if (!(id >= 0 && id < slotCount(mesh, kind))) return false;
  return kind === 'vertex' ? mesh.vDeleted[id] === 0 : kind === 'face' ? mesh.fDeleted[id] === 0 : mesh.eDeleted[id >> 1] === 0;
}

/** The solution's last write to `array[index]`, or null. */
function lastWriteOf(writes: readonly PracticeWrite[], array: string, index: number): PracticeWrite | null {
  for (let i = writes.length - 1; i >= 0; i--) {
    const write = writes[i];
    if (write.index === index && pointerArrayOf[write.field as PointerWriteField] === array) return write;
  }
  return null;
}

/** The solution's write that deleted element `id` of a kind (a halfedge goes with its edge), or null. */
function removalOf(writes: readonly PracticeWrite[], kind: Kind, id: number): PracticeWrite | null {
  const [field, index] = kind === 'vertex' ? ['deleteVertex', id] : kind === 'face' ? ['deleteFace', id] : ['deleteEdge', id >> 1];
  return writes.find((write) => write.field === field && write.index === index) ?? null;
}

function nameOf(kind: Kind, id: number): string {
  if (id === -1) return '-1';
  return `${kind === 'vertex' ? 'v' : kind === 'face' ? 'f' : 'h'}${id}`;
}

function at(line: number | null): string {
  return line === null ? '' : ` at line ${line}`;
}
