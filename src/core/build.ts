/**
 * Building a halfedge mesh from a polygon soup, in time linear in the number of face corners.
 *
 * Each face corner `c` (vertex `corners[c]` of a face) becomes the halfedge from that vertex to the
 * next one of the face. The work is to find, for each such halfedge, its twin: the corner of a
 * neighbouring face that runs along the same edge the other way. The phases:
 *
 *   1. keep the faces a halfedge mesh can hold (drop out-of-range and degenerate ones);
 *   2. pair the corners that share an edge (a counting sort by the edge's lower vertex, then the
 *      few corners of each bucket compared with one another: no hash map, no search of the mesh);
 *   3. when some pair runs the same way, flip faces so neighbours agree (per component, keeping the
 *      majority's orientation); a pair that still disagrees is a non-orientable seam and is cut;
 *   4. edges with three or more faces keep one pair and detach the rest; a face cut or detached
 *      from an edge takes its own copies of the edge's two vertices, and the corners are paired again;
 *   5. number the halfedges (twin pairs in adjacent slots, in order of first appearance) and link
 *      each face's loop;
 *   6. walk the fan of faces around each vertex; a vertex with several fans is duplicated, one copy
 *      per fan, as OpenMesh's importer does;
 *   7. link the boundary halfedges into loops around each hole.
 *
 * Every repair is reported (see `report.ts`) with the ids involved.
 */
import { attributeTypeOf } from './attributes.js';
import { InvalidInputError } from './errors.js';
import { HalfedgeMesh } from './mesh.js';
import { setMeshArray } from './mesh-arrays.js';
import { type BuildReport, ReportBuilder } from './report.js';
import { checkSoupShape, type PolygonSoup } from './soup.js';

export interface BuildOptions {
  /** Called between phases with the fraction done (0…1). */
  onProgress?: (fraction: number) => void;
}

export interface BuildResult {
  mesh: HalfedgeMesh;
  report: BuildReport;
  /** Mesh face → soup face; `null` when every face was kept, so the ids are the same. */
  inputFaceOf: Int32Array | null;
}

/**
 * Builds a halfedge mesh from a polygon soup, repairing what a halfedge mesh cannot hold and
 * reporting each repair. Vertex ids are kept (duplicates of pinched vertices are appended);
 * face ids are kept unless faces had to be dropped (see `inputFaceOf`).
 * @example
 *   const { mesh, report } = buildMesh(soupFromArrays(positions, [[0, 1, 2], [0, 2, 3]]));
 * @throws InvalidInputError when the soup's arrays are not shaped as `PolygonSoup` says.
 */
export function buildMesh(soup: PolygonSoup, options: BuildOptions = {}): BuildResult {
  checkSoupShape(soup);
  const progress = options.onProgress ?? (() => {});
  /** Progress from `from` to `to` as a long loop goes: `tick(i, n)` every `TICK + 1` items. */
  const span = (from: number, to: number) => (i: number, n: number) => progress(from + ((to - from) * i) / n);
  const nInputVertices = soup.positions.length / 3;
  const nInputFaces = soup.faceStarts.length - 1;
  const report = new ReportBuilder();

  // 1. keep the faces a halfedge mesh can hold
  const kept = keepValidFaces(soup, report);
  progress(0.2);

  // 2. pair the corners that share an edge. The pairing works in two numbers a corner, as many as
  // a closed mesh's next and prev pointers, which then take that memory over (see `linkFaces`)
  const entries = new Int32Array(2 * kept.starts[kept.faceCount]);
  let pairing = pairCorners(kept.corners, kept.starts, nInputVertices, entries, span(0.2, 0.4));
  progress(0.4);

  // 3. orient: flip faces until every pair runs opposite ways, or cut where it cannot
  /** Corners whose face leaves their edge, with its own copies of the edge's two vertices. */
  const detached: Detached[] = [];
  if (pairing.sameDirectionPairs > 0) {
    orientFaces(kept, pairing.twin, report);
    pairing = pairCorners(kept.corners, kept.starts, nInputVertices, entries);
    cutSeams(kept, pairing.twin, report, detached);
  }

  // 4. edges with more than two faces: keep one pair, detach the others
  for (const group of pairing.crowded) keepOnePair(group, kept, pairing.twin, report, detached);
  let copyOf: number[] = [];
  if (detached.length > 0) {
    copyOf = detachCorners(kept, detached, nInputVertices, soup.faceIndices);
    // copies only ever take corners out of an edge, so every edge now has one or two corners,
    // and the two of a pair run opposite ways
    pairing = pairCorners(kept.corners, kept.starts, nInputVertices + copyOf.length, entries);
  }
  progress(0.5);

  // 5. number the halfedges and link each face loop (twin becomes each corner's halfedge)
  const mesh = linkFaces(kept, pairing, nInputVertices + copyOf.length, entries, span(0.5, 0.7));
  copyAttributes(soup, kept, mesh, pairing.twin);
  copyOf.forEach((v, i) => mesh.vertexAttributes.copy(nInputVertices + i, v));
  progress(0.7);

  // 6. one fan per vertex: the common case needs no split, and a walk that only checks so
  const faceHalfedges = kept.starts[kept.faceCount];
  if (!walkSingleFans(mesh, faceHalfedges)) splitFans(mesh, report, span(0.7, 0.9));
  progress(0.9);

  // 7. link the boundary loops
  if (mesh.halfedgeSlots > faceHalfedges) linkBoundaries(mesh);
  reportVertices(mesh, nInputVertices, report);
  progress(1);

  return {
    mesh,
    report: report.finish(nInputVertices, nInputFaces),
    inputFaceOf: kept.inputFace?.slice(0, kept.faceCount) ?? null,
  };
}

type IndexArray = Int32Array | Uint32Array;

/** Reports progress through a loop of `n` items at item `i`. */
type Tick = (i: number, n: number) => void;
/** Long loops tick every `TICK + 1` items (a mask: a power of two minus one). */
const TICK = 0x3fff;

/**
 * The faces that survive phase 1, as corner lists (CSR like the soup). When every face survives
 * as it is, these are the soup's own arrays (not copied; never written to).
 */
interface KeptFaces {
  corners: IndexArray;
  starts: IndexArray;
  faceCount: number;
  /** Kept face → soup face, or null when they are the same. */
  inputFace: Int32Array | null;
  /** Kept corner → soup corner, kept only when the soup has corner attributes. */
  cornerSource: Int32Array | null;
}

function inputFaceOf(kept: KeptFaces, f: number): number {
  return kept.inputFace ? kept.inputFace[f] : f;
}

function keepValidFaces(soup: PolygonSoup, report: ReportBuilder): KeptFaces {
  const { faceStarts, faceIndices } = soup;
  const nV = soup.positions.length / 3;
  const nF = faceStarts.length - 1;
  const stamp = new VertexStamp(nV);
  const trackCorners = (soup.cornerAttributes?.length ?? 0) > 0;

  // the common case: every face is already fine, so its lists are copied as they are
  let firstBad = 0;
  while (firstBad < nF && isSimpleFace(faceIndices, faceStarts[firstBad], faceStarts[firstBad + 1], nV, stamp)) {
    firstBad++;
  }
  if (firstBad === nF) {
    return {
      corners: faceIndices,
      starts: faceStarts,
      faceCount: nF,
      inputFace: null,
      cornerSource: trackCorners ? identity(faceIndices.length) : null,
    };
  }

  const corners = new Int32Array(faceIndices.length);
  const cornerSource = trackCorners ? new Int32Array(faceIndices.length) : null;
  const starts = new Int32Array(nF + 1);
  const inputFace = new Int32Array(nF);
  let nc = 0;
  let nk = 0;
  for (let f = 0; f < nF; f++) {
    const s = faceStarts[f];
    const e = faceStarts[f + 1];
    if (f < firstBad || isSimpleFace(faceIndices, s, e, nV, stamp)) {
      for (let i = s; i < e; i++) {
        if (cornerSource) cornerSource[nc] = i;
        corners[nc++] = faceIndices[i];
      }
    } else {
      const kept = repairFace(soup, f, corners, cornerSource, nc, nk, stamp, report);
      if (kept === nc) continue;
      nc = kept;
    }
    inputFace[nk++] = f;
    starts[nk] = nc;
  }
  return {
    corners: corners.subarray(0, nc),
    starts: starts.subarray(0, nk + 1),
    faceCount: nk,
    inputFace,
    cornerSource: cornerSource?.subarray(0, nc) ?? null,
  };
}

/** Marks vertices with the face that last used them, to spot a vertex used twice by one face. */
class VertexStamp {
  private stamp: Int32Array | null = null;
  private current = 0;
  constructor(private readonly nV: number) {}
  /** Starts a new face. */
  next(): void {
    this.current++;
    this.stamp ??= new Int32Array(this.nV);
  }
  /** Stamps v and says whether it was already stamped for this face. */
  seen(v: number): boolean {
    const stamp = this.stamp!;
    if (stamp[v] === this.current) return true;
    stamp[v] = this.current;
    return false;
  }
}

/** In range, at least 3 corners, no vertex twice. */
function isSimpleFace(indices: PolygonSoup['faceIndices'], s: number, e: number, nV: number, stamp: VertexStamp): boolean {
  // triangles and quads, most faces of most files, in a few comparisons each (small enough to be
  // inlined where the faces are checked)
  if (e - s === 3) {
    const a = indices[s];
    const b = indices[s + 1];
    const c = indices[s + 2];
    return a >= 0 && a < nV && b >= 0 && b < nV && c >= 0 && c < nV && a !== b && b !== c && c !== a;
  }
  if (e - s === 4) {
    const a = indices[s];
    const b = indices[s + 1];
    const c = indices[s + 2];
    const d = indices[s + 3];
    const inRange = a >= 0 && a < nV && b >= 0 && b < nV && c >= 0 && c < nV && d >= 0 && d < nV;
    return inRange && a !== b && a !== c && a !== d && b !== c && b !== d && c !== d;
  }
  return isSimplePolygon(indices, s, e, nV, stamp);
}

/** `isSimpleFace` for any number of corners: a stamp per vertex finds one listed twice. */
function isSimplePolygon(indices: PolygonSoup['faceIndices'], s: number, e: number, nV: number, stamp: VertexStamp): boolean {
  if (e - s < 3) return false;
  for (let i = s; i < e; i++) {
    const v = indices[i];
    if (!(v >= 0 && v < nV)) return false;
  }
  stamp.next();
  for (let i = s; i < e; i++) if (stamp.seen(indices[i])) return false;
  return true;
}

/**
 * Face `f` is not simple: drop it (out-of-range index, fewer than 3 distinct vertices, a vertex
 * visited twice) or, when it only repeats a vertex in a row, keep it without the repeat. Writes
 * the kept corners from `nc` on and returns the new corner count (`nc` when dropped).
 */
function repairFace(
  soup: PolygonSoup,
  f: number,
  corners: Int32Array,
  cornerSource: Int32Array | null,
  nc: number,
  keptId: number,
  stamp: VertexStamp,
  report: ReportBuilder,
): number {
  const { faceStarts, faceIndices } = soup;
  const nV = soup.positions.length / 3;
  const listed = Array.from(faceIndices.subarray(faceStarts[f], faceStarts[f + 1]));
  const outOfRange = listed.find((v) => !(v >= 0 && v < nV));
  if (outOfRange !== undefined) {
    report.add('out-of-range-index', {
      message: `face ${f} uses vertex ${outOfRange}, but the vertices are numbered 0..${nV - 1}`,
      inputFaces: [f],
    });
    return nc;
  }
  // drop repeats in a row, the last corner wrapping round to the first
  const first = nc;
  for (let i = faceStarts[f]; i < faceStarts[f + 1]; i++) {
    if (nc > first && corners[nc - 1] === faceIndices[i]) continue;
    if (cornerSource) cornerSource[nc] = i;
    corners[nc++] = faceIndices[i];
  }
  while (nc - first > 1 && corners[nc - 1] === corners[first]) nc--;
  const degree = nc - first;
  let repeated = -1;
  stamp.next();
  for (let c = first; c < nc; c++) if (stamp.seen(corners[c])) repeated = corners[c];
  if (degree < 3 || repeated !== -1) {
    report.add('degenerate-face', {
      message:
        degree < 3
          ? `face ${f} (${listed.join(', ')}) has fewer than 3 distinct vertices`
          : `face ${f} (${listed.join(', ')}) passes through vertex ${repeated} twice`,
      inputFaces: [f],
      inputVertices: [...new Set(listed)],
    });
    return first;
  }
  report.add('collapsed-repeated-vertex', {
    message: `face ${f} (${listed.join(', ')}) kept as (${Array.from(corners.subarray(first, nc)).join(', ')})`,
    inputFaces: [f],
    faces: [keptId],
  });
  return nc;
}

function identity(n: number): Int32Array {
  const ids = new Int32Array(n);
  for (let i = 0; i < n; i++) ids[i] = i;
  return ids;
}

interface Pairing {
  /** The corner across the same edge, or -1. */
  twin: Int32Array;
  /** Corners left without a partner (crowded edges' included, until they are paired again). */
  unpaired: number;
  /** Pairs whose two corners run the same way (the faces disagree on orientation). */
  sameDirectionPairs: number;
  /** Corners of each edge that has three or more, in corner order. */
  crowded: number[][];
}

/** Pairs the corners; `entries` (two numbers a corner) is its working memory. */
function pairCorners(corners: IndexArray, starts: IndexArray, nV: number, entries: Int32Array, tick: Tick = () => {}): Pairing {
  const nF = starts.length - 1;
  const nC = starts[nF];
  // bucket the corners by the lower vertex of their edge (a counting sort): count bucket v's
  // corners at v + 2, sum them up so that v + 1 holds where bucket v starts, then let each corner
  // placed in bucket v move v + 1 on; afterwards bucket v runs from bucketStart[v] to bucketStart[v + 1]
  const bucketStart = new Int32Array(nV + 2);
  for (let f = 0; f < nF; f++) {
    if ((f & TICK) === 0) tick(f, 3 * nF);
    const s = starts[f];
    const e = starts[f + 1];
    for (let c = s; c < e; c++) {
      const a = corners[c];
      const b = corners[c + 1 < e ? c + 1 : s];
      bucketStart[(a < b ? a : b) + 2]++;
    }
  }
  for (let v = 1; v <= nV + 1; v++) bucketStart[v] += bucketStart[v - 1];
  // entries: (corner, upper vertex) pairs, side by side so one cache line holds both; the upper
  // vertex is stored as ~hi (negative) when the corner runs from hi to lo
  for (let f = 0; f < nF; f++) {
    if ((f & TICK) === 0) tick(nF + f, 3 * nF);
    const s = starts[f];
    const e = starts[f + 1];
    for (let c = s; c < e; c++) {
      const a = corners[c];
      const b = corners[c + 1 < e ? c + 1 : s];
      const slot = 2 * bucketStart[(a < b ? a : b) + 1]++;
      entries[slot] = c;
      entries[slot + 1] = a < b ? b : ~a;
    }
  }

  // within a bucket, corners with the same upper vertex share an edge. A bucket holds a handful of
  // corners (about six on a triangle mesh), so each one is compared with those after it, all in the
  // cache; a big bucket (a vertex at the tip of a wide fan) is sorted first, so that the comparing
  // can stop at the first other upper vertex
  const twin = new Int32Array(nC).fill(-1);
  const crowded: number[][] = [];
  let sameDirectionPairs = 0;
  let paired = 0;
  for (let lo = 0; lo < nV; lo++) {
    if ((lo & TICK) === 0) tick(2 * nV + lo, 3 * nV);
    const begin = 2 * bucketStart[lo];
    const end = 2 * bucketStart[lo + 1];
    const sorted = end - begin > 2 * SMALL_BUCKET;
    if (sorted) sortByUpperVertex(entries, begin, end);
    for (let i = begin; i < end; i += 2) {
      const upper = entries[i + 1];
      if (upper === PAIRED) continue;
      const down = ~upper;
      const first = entries[i];
      let partner = -1;
      let partnerUpper = 0;
      let group: number[] | null = null;
      for (let j = i + 2; j < end; j += 2) {
        const other = entries[j + 1];
        if (other !== upper && other !== down) {
          if (sorted) break; // the corners on this edge all came just after i
          continue;
        }
        entries[j + 1] = PAIRED;
        if (partner === -1) {
          partner = entries[j];
          partnerUpper = other;
        } else {
          // a third (or later) corner on this edge: the edge is crowded, and no pair is made yet
          group ??= [first, partner];
          group.push(entries[j]);
        }
      }
      if (group !== null) crowded.push(group);
      else if (partner !== -1) {
        twin[first] = partner;
        twin[partner] = first;
        paired += 2;
        if (upper === partnerUpper) sameDirectionPairs++;
      }
    }
  }
  return { twin, unpaired: nC - paired, sameDirectionPairs, crowded };
}

/** Buckets of up to this many corners are paired by comparing each corner with the ones after it. */
const SMALL_BUCKET = 32;

/** Marks an entry whose corner a corner before it in the bucket has taken (no upper vertex is ~0x7fffffff). */
const PAIRED = -0x80000000;

/**
 * Sorts the (corner, upper vertex) entries between `begin` and `end` by upper vertex; corners on
 * the same edge keep their order.
 */
function sortByUpperVertex(entries: Int32Array, begin: number, end: number): void {
  const upperVertex = (slot: number) => (entries[slot + 1] < 0 ? ~entries[slot + 1] : entries[slot + 1]);
  const slots = Array.from({ length: (end - begin) / 2 }, (_, k) => begin + 2 * k);
  slots.sort((p, q) => upperVertex(p) - upperVertex(q) || p - q);
  const sorted = slots.flatMap((slot) => [entries[slot], entries[slot + 1]]);
  entries.set(sorted, begin);
}

/** Face of each corner. */
function cornerFaces(starts: IndexArray): Int32Array {
  const nF = starts.length - 1;
  const faceOf = new Int32Array(starts[nF]);
  for (let f = 0; f < nF; f++) faceOf.fill(f, starts[f], starts[f + 1]);
  return faceOf;
}

/**
 * Chooses, by breadth-first search over faces joined by paired edges, which faces to flip so
 * that neighbours agree; in each component the orientation most faces already have wins.
 * An edge whose faces still disagree when the search meets it again is a non-orientable seam.
 */
function orientFaces(kept: KeptFaces, twin: Int32Array, report: ReportBuilder): void {
  const { starts, faceCount: nF } = kept;
  const corners = (kept.corners = Int32Array.from(kept.corners)); // the soup's own may not be written
  const faceOf = cornerFaces(starts);
  const flip = new Uint8Array(nF);
  const visited = new Uint8Array(nF);
  const queue = new Int32Array(nF);
  let tail = 0;
  for (let seed = 0; seed < nF; seed++) {
    if (visited[seed]) continue;
    const head0 = tail;
    visited[seed] = 1;
    queue[tail++] = seed;
    let flipped = 0;
    for (let head = head0; head < tail; head++) {
      const f = queue[head];
      for (let c = starts[f]; c < starts[f + 1]; c++) {
        const d = twin[c];
        if (d < 0) continue;
        const g = faceOf[d];
        const want = flip[f] ^ (corners[c] === corners[d] ? 1 : 0);
        if (!visited[g]) {
          visited[g] = 1;
          flip[g] = want;
          flipped += want;
          queue[tail++] = g;
        }
      }
    }
    if (2 * flipped > tail - head0) {
      for (let i = head0; i < tail; i++) flip[queue[i]] ^= 1;
    }
  }
  for (let f = 0; f < nF; f++) {
    if (!flip[f]) continue;
    // reverse all but the first corner, so the face still starts at the same vertex
    corners.subarray(starts[f] + 1, starts[f + 1]).reverse();
    kept.cornerSource?.subarray(starts[f] + 1, starts[f + 1]).reverse();
    report.add('reoriented-face', {
      message: `face ${inputFaceOf(kept, f)} flipped`,
      inputFaces: [inputFaceOf(kept, f)],
      faces: [f],
    });
  }
}

/**
 * After orienting, a pair that still runs the same way is a seam of a non-orientable surface:
 * cut it open. Unpairing the two corners alone would leave two boundary edges joining the same
 * two vertices, a slit that no file can hold (a face lists its corners, not its edges: read back,
 * the slit closes again). So the second face leaves the edge with its own copies of both vertices.
 */
function cutSeams(kept: KeptFaces, twin: Int32Array, report: ReportBuilder, detached: Detached[]): void {
  const { corners, starts } = kept;
  for (let c = 0; c < twin.length; c++) {
    const d = twin[c];
    if (d <= c || corners[c] !== corners[d]) continue;
    twin[c] = -1;
    twin[d] = -1;
    report.orientable = false;
    const faces = [faceOfCorner(starts, c), faceOfCorner(starts, d)];
    const [a, b] = cornerEdge(kept, c);
    const incident = {
      message:
        `edge ${a}–${b} between faces ${inputFaceOf(kept, faces[0])} and ${inputFaceOf(kept, faces[1])} was cut open: ` +
        `face ${inputFaceOf(kept, faces[1])} got its own copies of vertices ${a} and ${b}`,
      inputVertices: [a, b],
      inputFaces: faces.map((f) => inputFaceOf(kept, f)),
      faces,
      vertices: [a, b],
    };
    report.add('non-orientable', incident);
    detached.push({ corner: d, incident });
  }
}

/**
 * Of the corners along one edge, pairs the first with the first that runs the other way; the other
 * faces leave the edge, each with its own copies of the edge's two vertices (see `cutSeams` for why
 * unpairing them is not enough).
 */
function keepOnePair(group: number[], kept: KeptFaces, twin: Int32Array, report: ReportBuilder, detached: Detached[]): void {
  const { corners, starts } = kept;
  const first = group[0];
  const partner = group.find((c) => corners[c] !== corners[first]);
  if (partner !== undefined) {
    twin[first] = partner;
    twin[partner] = first;
  }
  const leaving = group.filter((c) => c !== first && c !== partner);
  const faces = group.map((c) => faceOfCorner(starts, c));
  const staying = [first, partner ?? first].map((c) => faceOfCorner(starts, c));
  const [a, b] = cornerEdge(kept, first);
  const names = (list: number[]) => list.map((f) => inputFaceOf(kept, f)).join(', ');
  const incident = {
    message:
      `edge ${a}–${b} is shared by ${faces.length} faces (${names(faces)}): ` +
      (partner === undefined ? `${names(staying.slice(0, 1))} keeps it, ` : `${names(staying)} stay joined, `) +
      `${names(leaving.map((c) => faceOfCorner(starts, c)))} detached with their own copies of vertices ${a} and ${b}`,
    inputVertices: [a, b],
    inputFaces: faces.map((f) => inputFaceOf(kept, f)),
    faces,
    vertices: [a, b],
  };
  report.add('non-manifold-edge', incident);
  for (const corner of leaving) detached.push({ corner, incident });
}

/** A corner whose face leaves its edge, and the repair incident that says so (its copies are added to it). */
interface Detached {
  corner: number;
  incident: { vertices: number[] };
}

/**
 * Gives the face of each detached corner its own copies of the corner's edge's two vertices,
 * numbered from `nV` on (one copy per face and vertex, however many of its edges leave). The face
 * thereby also lets go of its other edges at those vertices, which is what a file would say of it.
 * Returns the vertex each copy copies. Only repairs come here: the corners are copied first when
 * they are still the soup's own, which is never written to.
 */
function detachCorners(kept: KeptFaces, detached: Detached[], nV: number, soupCorners: IndexArray): number[] {
  if (kept.corners === soupCorners) kept.corners = Int32Array.from(kept.corners);
  const { corners, starts } = kept;
  const copyOf: number[] = [];
  for (const { corner: c, incident } of detached) {
    const f = faceOfCorner(starts, c);
    const next = c + 1 < starts[f + 1] ? c + 1 : starts[f];
    for (const corner of [c, next]) {
      if (corners[corner] >= nV) continue; // this face already has its copy of the vertex
      copyOf.push(corners[corner]);
      corners[corner] = nV + copyOf.length - 1;
      incident.vertices.push(corners[corner]);
    }
  }
  return copyOf;
}

function faceOfCorner(starts: IndexArray, c: number): number {
  // the last face whose start is at or before c (binary search: only rare repairs call this)
  let lo = 0;
  let hi = starts.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >>> 1;
    if (starts[mid] <= c) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/** The two vertices of the edge that corner `c` starts. */
function cornerEdge(kept: KeptFaces, c: number): [number, number] {
  const f = faceOfCorner(kept.starts, c);
  const next = c + 1 < kept.starts[f + 1] ? c + 1 : kept.starts[f];
  return [kept.corners[c], kept.corners[next]];
}

/**
 * Numbers the halfedges and links each face loop, in one pass over the corners. A corner's
 * halfedge and its twin's take the two slots of one edge, in order of first appearance, so face
 * 0's halfedges are h0, h2, h4, … To spare a second array of corner size, `twin` is overwritten
 * as the pass goes: afterwards `twin[c]` is the halfedge of corner c.
 */
function linkFaces(kept: KeptFaces, { twin, unpaired }: Pairing, nV: number, entries: Int32Array, tick: Tick = () => {}): HalfedgeMesh {
  const { corners, starts, faceCount: nF } = kept;
  const nC = starts[nF];
  const nE = (nC + unpaired) / 2;
  if (nE > 0x3fffffff) throw new InvalidInputError(`${nE} edges are more than one mesh can hold`);

  const mesh = new HalfedgeMesh({ vertices: nV, edges: nE, faces: nF });
  if (unpaired === 0) {
    // closed: a halfedge per corner, so the pairing's memory holds next and prev exactly (the
    // arrays the mesh was made with are never touched, and cost no memory)
    setMeshArray(mesh, 'heNext', entries.subarray(0, nC));
    setMeshArray(mesh, 'hePrev', entries.subarray(nC));
  }
  mesh.vertexSlots = nV;
  mesh.edgeSlots = nE;
  mesh.faceSlots = nF;
  const { heNext, hePrev, heVertex, heFace, fHalfedge } = mesh;
  let edges = 0;
  for (let f = 0; f < nF; f++) {
    if ((f & TICK) === 0) tick(f, nF);
    const s = starts[f];
    const e = starts[f + 1];
    let first = -1;
    let prev = -1;
    for (let c = s; c < e; c++) {
      const d = twin[c];
      // d > c or none: c comes first on its edge and opens it; d < c: d opened it, and twin[d]
      // already holds d's halfedge
      const h = d < c && d >= 0 ? twin[d] ^ 1 : 2 * edges++;
      if (d === -1) {
        // the other halfedge of the edge is on the boundary: no face, and no next until phase 7
        heFace[h ^ 1] = -1;
        heNext[h ^ 1] = -1;
      }
      twin[c] = h;
      heVertex[h] = corners[c];
      heFace[h] = f;
      if (prev === -1) first = h;
      else {
        hePrev[h] = prev;
        heNext[prev] = h;
      }
      prev = h;
    }
    hePrev[first] = prev;
    heNext[prev] = first;
    fHalfedge[f] = first;
  }
  return mesh;
}

function copyAttributes(soup: PolygonSoup, kept: KeptFaces, mesh: HalfedgeMesh, halfedgeOf: Int32Array): void {
  const faceOf = (f: number) => inputFaceOf(kept, f);
  mesh.positions.set(soup.positions);
  for (const { name, itemSize, data, interpolation } of soup.vertexAttributes ?? []) {
    mesh.vertexAttributes.add(name, attributeTypeOf(data), itemSize, interpolation).data.set(data);
  }
  for (const { name, itemSize, data, interpolation } of soup.faceAttributes ?? []) {
    const target = mesh.faceAttributes.add(name, attributeTypeOf(data), itemSize, interpolation).data;
    for (let f = 0; f < kept.faceCount; f++) {
      const src = faceOf(f);
      // item by item: a view of the source for each element would cost more than the copy
      for (let k = 0; k < itemSize; k++) target[f * itemSize + k] = data[src * itemSize + k];
    }
  }
  for (const { name, itemSize, data, interpolation } of soup.cornerAttributes ?? []) {
    const target = mesh.halfedgeAttributes.add(name, attributeTypeOf(data), itemSize, interpolation).data;
    for (let c = 0; c < halfedgeOf.length; c++) {
      const src = kept.cornerSource![c];
      const h = halfedgeOf[c];
      for (let k = 0; k < itemSize; k++) target[h * itemSize + k] = data[src * itemSize + k];
    }
  }
}

/**
 * Walks the fan of faces around each vertex. The first fan found keeps the vertex; every further
 * fan of the same vertex gets a copy (same position and attributes), so each vertex ends up with
 * exactly one fan. Sets each vertex's halfedge (its outgoing boundary halfedge on an open fan) and
 * the origin of each boundary halfedge.
 */
function splitFans(mesh: HalfedgeMesh, report: ReportBuilder, tick: Tick = () => {}): void {
  const { heNext, hePrev, heVertex, heFace } = mesh;
  const nH = mesh.halfedgeSlots;
  mesh.vHalfedge.fill(-1);
  // a copy added for a pinched vertex may reallocate the vertex arrays: never keep them across one
  let vHalfedge = mesh.vHalfedge;
  const visited = new Uint8Array(nH);
  const copies = new Map<number, number[]>();
  for (let h = 0; h < nH; h++) {
    if ((h & TICK) === 0) tick(h, nH);
    if (heFace[h] === -1 || visited[h]) continue;
    const v = heVertex[h];
    let w = v;
    if (vHalfedge[v] !== -1) {
      w = mesh.addVertex();
      mesh.vertexAttributes.copy(w, v);
      vHalfedge = mesh.vHalfedge;
      let list = copies.get(v);
      if (!list) copies.set(v, (list = []));
      list.push(w);
    }
    // rotate clockwise (next of twin) from h, claiming the fan's halfedges for w, until it closes
    // or meets the boundary: one walk round a vertex inside the surface
    let x = h;
    let open = false;
    for (let steps = 0; ; steps++) {
      visited[x] = 1;
      if (w !== v) heVertex[x] = w;
      const t = x ^ 1;
      if (heFace[t] === -1) {
        open = true;
        break;
      }
      x = heNext[t];
      if (x === h) break;
      if (steps > nH) throw new Error(`buildMesh: the fan around vertex ${v} does not close`);
    }
    if (!open) {
      vHalfedge[w] = heNext[h ^ 1];
      continue;
    }
    // an open fan: rotate counter-clockwise (twin of prev) from h to its first halfedge, claiming the rest
    let first = h;
    for (let steps = 0; ; steps++) {
      const t = hePrev[first] ^ 1;
      if (heFace[t] === -1) break;
      first = t;
      visited[first] = 1;
      if (w !== v) heVertex[first] = w;
      if (steps > nH) throw new Error(`buildMesh: the fan around vertex ${v} does not close`);
    }
    const boundaryOut = hePrev[first] ^ 1;
    heVertex[boundaryOut] = w;
    vHalfedge[w] = boundaryOut;
  }
  for (const [v, list] of copies) {
    report.add('non-manifold-vertex', {
      message: `vertex ${v} joined ${list.length + 1} fans of faces: copies ${list.join(', ')} added`,
      inputVertices: [v],
      vertices: [v, ...list],
    });
  }
}

/**
 * The common case of phase 6: no vertex has a second fan, so none is split. Walks the fan of each
 * vertex from the first halfedge leaving it, as `splitFans` does, but the fans of vertices met
 * before are skipped without a mark per halfedge. Fans never share a halfedge, so the walks cover
 * all `faceHalfedges` exactly when every vertex has one fan; otherwise returns false, and
 * `splitFans` must set everything again. One array read a step, where `splitFans` reads three: the boundary
 * halfedges have a next of -1 (see `linkFaces`).
 */
function walkSingleFans(mesh: HalfedgeMesh, faceHalfedges: number): boolean {
  const { heNext, hePrev, heVertex, vHalfedge } = mesh;
  const nH = mesh.halfedgeSlots;
  vHalfedge.fill(-1);
  let walked = 0;
  for (let h = 0; h < nH; h++) {
    const v = heVertex[h];
    if (vHalfedge[v] !== -1 || heNext[h] === -1) continue;
    // clockwise (next of twin) from h, until the fan closes or meets the boundary
    let n = heNext[h ^ 1];
    walked++;
    while (n !== h && n !== -1) {
      if (++walked > faceHalfedges) return false;
      n = heNext[n ^ 1];
    }
    if (n === h) {
      vHalfedge[v] = heNext[h ^ 1];
      continue;
    }
    // open: counter-clockwise (twin of prev) from h to the boundary halfedge leaving v
    let out = hePrev[h] ^ 1;
    while (heNext[out] !== -1) {
      if (++walked > faceHalfedges) return false;
      out = hePrev[out] ^ 1;
    }
    heVertex[out] = v;
    vHalfedge[v] = out;
  }
  return walked === faceHalfedges;
}

/**
 * Each boundary halfedge b runs opposite a face corner c; the boundary halfedge after b leaves the
 * vertex c starts from, and that vertex's halfedge is exactly its outgoing boundary halfedge.
 */
function linkBoundaries(mesh: HalfedgeMesh): void {
  const { heNext, hePrev, heVertex, heFace, vHalfedge } = mesh;
  const nH = mesh.halfedgeSlots;
  for (let b = 0; b < nH; b++) {
    if (heFace[b] !== -1) continue;
    const after = vHalfedge[heVertex[b ^ 1]];
    heNext[b] = after;
    hePrev[after] = b;
  }
}

function reportVertices(mesh: HalfedgeMesh, nInputVertices: number, report: ReportBuilder): void {
  const { vHalfedge, positions } = mesh;
  for (let v = 0; v < nInputVertices; v++) {
    if (vHalfedge[v] === -1) {
      report.add('isolated-vertex', { message: `vertex ${v} is in no face`, inputVertices: [v], vertices: [v] });
    }
    // each coordinate on its own: a sum of finite ones can overflow (1e308 + 1e308)
    if (!(Number.isFinite(positions[3 * v]) && Number.isFinite(positions[3 * v + 1]) && Number.isFinite(positions[3 * v + 2]))) {
      report.add('non-finite-position', {
        message: `vertex ${v} is at (${positions[3 * v]}, ${positions[3 * v + 1]}, ${positions[3 * v + 2]})`,
        inputVertices: [v],
        vertices: [v],
      });
    }
  }
}
