/**
 * The built-in exercises, easiest first: queries that walk the pointers, the local edits of every
 * halfedge course (flip, split, collapse), the local operations of the halfedge assignment (inset
 * a vertex, extrude, bevel, dissolve, collapse a face, make a hole, weld, triangulate), then one
 * level of Loop, Catmull-Clark and linear subdivision, isotropic remeshing and simplification (the
 * last two graded by the properties of the result: they have no single right answer). Each reference is the library's own function;
 * the fixtures hold the hard cases (boundaries, valence 3, a forbidden collapse, several
 * components), and those of the assignment's operations are hidden: graded by the rule they
 * state, their mesh never shown (see `Fixture.hidden`). A solution that is right for each, written
 * against the mesh API alone, is in `tests/practice/solutions/`.
 */
import { boundaryLoops, vertexAdjacentVertices } from '../circulators.js';
import { canCollapseEdge, collapseEdge } from '../edits/collapse.js';
import { canFlipEdge, flipEdge } from '../edits/flip.js';
import { triangulateMesh } from '../edits/triangulate.js';
import { pokeFace } from '../edits/poke.js';
import { bevelEdge, bevelVertex, canBevelEdge, canBevelVertex } from '../edits/bevel.js';
import { canDissolveEdge, canDissolveVertex, dissolveEdge, dissolveVertex } from '../edits/dissolve.js';
import { canCollapseFace, collapseFace } from '../edits/collapse-face.js';
import { canExtrudeFace, extrudeFace } from '../edits/extrude.js';
import { canMakeBoundary, makeBoundary } from '../edits/make-boundary.js';
import { canWeldEdges, weldEdges } from '../edits/weld.js';
import { splitEdgeTriangulated } from '../edits/split-edge.js';
import { subdivide } from '../subdivision/index.js';
import { remesh } from '../remeshing/index.js';
import { decimate } from '../decimation/index.js';
import type { Exercise, ExerciseInput, Fixture } from './exercise.js';
import type { ResultBounds } from './properties.js';

/** The input of a fixture that gives one id. */
const id = (input: ExerciseInput | undefined) => input as number;
/** The input of a fixture that gives named numbers. */
const named = (input: ExerciseInput | undefined) => input as { readonly [name: string]: number };

/** A hidden fixture: a hard case, shown to the student by its name and rule only. */
const hidden = (name: string, rule: string, fixture: Omit<Fixture, 'name' | 'hidden' | 'rule'>): Fixture => ({ name: `hidden: ${name}`, ...fixture, hidden: true, rule });

/**
 * A pentagon (f0) with its fifth corner v4 in the middle of its bottom side, and under that side a
 * triangle with no area (f1: v0, v1, v4 on one line), whose long side is on the boundary.
 * ```
 *    v3 ─────────────── v2
 *    │                   │
 *    │        f0         │
 *    │                   │
 *    v0 ────── v4 ────── v1     f1 = v0 → v1 → v4: flat, along the bottom
 * ```
 */
/** Two triangles on the same three corners, back to back: closed, every vertex with 2 edges. */
const PILLOW = 'OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n';

/**
 * An L of six corners, listed from v2 (3, 1), where a fan from the first corner folds over (and
 * whose centroid, (4/3, 1), is none of its corners):
 * ```
 *    v5 ──── v4
 *    │        │
 *    │       v3 ─────────── v2
 *    │                       │
 *    v0 ─────────────────── v1
 * ```
 */
const L_HEXAGON = 'OFF\n6 1 0\n0 0 0\n3 0 0\n3 1 0\n1 1 0\n1 2 0\n0 2 0\n6 2 3 4 5 0 1\n';

/** A quad whose four corners lie on the x axis (no area), and a unit square above it. */
const FLAT_QUAD_AND_SQUARE = 'OFF\n8 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n0 1 0\n1 1 0\n1 2 0\n0 2 0\n4 0 1 2 3\n4 4 5 6 7\n';

const SLIVER_UNDER_PENTAGON = 'OFF\n5 2 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n1 0 0\n5 0 4 1 2 3\n3 0 1 4\n';

/** What a remeshing must reach (the library's own result reaches it with room on every fixture: tests/practice/properties.test.ts). */
const REMESH_BOUNDS: ResultBounds = { shareNearTarget: 0.5, maxDistance: 0.04 };

/** What a simplification must reach (the library's own result, as for remeshing). */
const SIMPLIFY_BOUNDS: ResultBounds = { shareOfTargetFaces: 0.9, maxDistance: 0.05 };

const starter = (comment: string, body: string) => `// ${comment}\nexport default function (mesh, input) {\n${body}\n}\n`;

export const exercises: Exercise[] = [
  {
    id: 'vertex-degree',
    title: 'Degree of a vertex',
    kind: 'query',
    answer: 'exact',
    task: [
      'Return the number of edges at vertex `input`.',
      'Start from vertexHalfedge(v) and turn around v: the next outgoing halfedge is twin(prev(h)). Stop when you are back where you started.',
    ],
    hints: [
      'An outgoing halfedge h leaves v; prev(h) arrives at v, so twin(prev(h)) leaves v again, one edge further counter-clockwise.',
      'On the boundary this still works: a boundary halfedge has a prev too, around the hole.',
      'Count with a do … while loop, so the first halfedge is counted before the test.',
    ],
    starter: starter('input: a vertex id. Return how many edges meet there.', '  const start = mesh.vertexHalfedge(input);\n  let count = 0;\n  // turn around the vertex here\n  return count;'),
    fixtures: [
      { name: 'a corner of a tetrahedron (valence 3)', shapes: [['tetrahedron']], input: 0 },
      { name: 'the centre of a disk (valence 6)', shapes: [['disk', 2]], input: 0 },
      { name: 'a vertex on the boundary of a disk', shapes: [['disk', 2]], input: 8 },
      { name: 'a corner of a grid (on the boundary)', shapes: [['grid', 2, 2]], input: 0 },
    ],
    reference: (mesh, v) => mesh.vertexDegree(id(v)),
  },
  {
    id: 'face-degree',
    title: 'Sides of a face',
    kind: 'query',
    answer: 'exact',
    task: ['Return the number of sides of face `input`: follow next from faceHalfedge(f) until you are back.'],
    hints: ['Every halfedge of a face has that face on its left, and next goes once around it.', 'Faces need not be triangles: the cube has quads.'],
    starter: starter('input: a face id. Return how many sides it has.', '  let sides = 0;\n  return sides;'),
    fixtures: [
      { name: 'a triangle of a tetrahedron', shapes: [['tetrahedron']], input: 1 },
      { name: 'a quad of a cube', shapes: [['cube']], input: 0 },
      { name: 'a quad of a ring with two holes', shapes: [['annulus', 5]], input: 3 },
    ],
    reference: (mesh, f) => mesh.faceDegree(id(f)),
  },
  {
    id: 'one-ring',
    title: 'One-ring of a vertex',
    kind: 'query',
    answer: 'cycle',
    task: [
      'Return the ids of the vertices joined to vertex `input` by an edge, in counter-clockwise order (start anywhere).',
      'For an outgoing halfedge h, the neighbour is target(h).',
    ],
    hints: ['Turn around the vertex as for its degree, and collect target(h) of each outgoing halfedge.', 'twin(prev(h)) turns counter-clockwise; twin(h) then next turns the other way.'],
    starter: starter('input: a vertex id. Return its neighbours, counter-clockwise.', '  const ring = [];\n  return ring;'),
    fixtures: [
      { name: 'a corner of a tetrahedron', shapes: [['tetrahedron']], input: 2 },
      { name: 'the centre of a disk', shapes: [['disk', 1]], input: 0 },
      { name: 'a vertex on the boundary', shapes: [['grid', 2, 2]], input: 1 },
    ],
    reference: (mesh, v) => [...vertexAdjacentVertices(mesh, id(v))],
  },
  {
    id: 'is-boundary-vertex',
    title: 'Is a vertex on the boundary?',
    kind: 'query',
    answer: 'exact',
    task: ['Return true when vertex `input` lies on the boundary: some halfedge around it has no face (face(h) is -1).'],
    hints: ['Look at every outgoing halfedge, not only the first: do not rely on which one vertexHalfedge gives.', 'isBoundary(h) is face(h) === -1.'],
    starter: starter('input: a vertex id. Return true if it is on the boundary.', '  return false;'),
    fixtures: [
      { name: 'a vertex of a closed tetrahedron', shapes: [['tetrahedron']], input: 1 },
      { name: 'the centre of a disk', shapes: [['disk', 2]], input: 0 },
      { name: 'a vertex on the rim of a disk', shapes: [['disk', 2]], input: 12 },
      { name: 'a corner of a grid', shapes: [['grid', 2, 2]], input: 8 },
    ],
    reference: (mesh, v) => mesh.isBoundaryVertex(id(v)),
  },
  {
    id: 'boundary-loops',
    title: 'Count the holes',
    kind: 'query',
    answer: 'exact',
    task: ['Return the number of boundary loops: cycles of halfedges with no face. Each hole is one loop, however many edges it has.'],
    hints: ['Go through every halfedge; when you meet a boundary halfedge not seen yet, walk its loop with next and mark each one.', 'Keep the marks in a Set or an array indexed by halfedge id.'],
    starter: starter('no input. Return how many holes the mesh has.', '  let loops = 0;\n  return loops;'),
    fixtures: [
      { name: 'a closed tetrahedron', shapes: [['tetrahedron']] },
      { name: 'a disk', shapes: [['disk', 2]] },
      { name: 'a ring (two holes)', shapes: [['annulus', 6]] },
      { name: 'two components: a disk and a ring', shapes: [['disk', 1], ['annulus', 5]] },
    ],
    reference: (mesh) => [...boundaryLoops(mesh)].length,
  },
  {
    id: 'euler-characteristic',
    title: 'Euler characteristic',
    kind: 'query',
    answer: 'exact',
    task: ['Return V − E + F for the whole mesh.'],
    hints: ['vertexCount(), edgeCount() and faceCount() count the live elements.', 'A sphere has 2, a torus 0, a disk 1; components add up.'],
    starter: starter('no input. Return V - E + F.', '  return 0;'),
    fixtures: [
      { name: 'a tetrahedron', shapes: [['tetrahedron']] },
      { name: 'a torus', shapes: [['torus', 6, 4]] },
      { name: 'a disk', shapes: [['disk', 2]] },
      { name: 'two tetrahedra', shapes: [['tetrahedron'], ['tetrahedron']] },
    ],
    reference: (mesh) => mesh.nVertices - mesh.nEdges + mesh.nFaces,
  },
  {
    id: 'flip-edge',
    title: 'Flip an edge',
    kind: 'edit',
    answer: 'exact',
    refusal: false,
    task: [
      'Turn edge `input` between two triangles so that it joins their other two corners; return true.',
      'Return false and change nothing when the flip does not apply: a boundary edge, a face that is not a triangle, or the two other corners already joined by an edge.',
      'Reuse the edge and both faces. Every next (setNext also sets prev), origin and face around the two triangles must be right, and so must the halfedge of every vertex and face involved.',
    ],
    hints: [
      'Name everything first: h = edgeHalfedge(e), t = twin(h), the other halfedges of both triangles, the four corners and both faces. Then write.',
      'After the flip, h runs from the corner opposite t to the corner opposite h.',
      'The two ends of the old edge lose an outgoing halfedge: make their vertexHalfedge one they still have. A face whose halfedge moved to the other face needs a new one too.',
      'To check that the new edge does not exist yet, turn around one of its ends and look at the targets.',
    ],
    starter: starter('input: an edge id. Flip it and return true, or return false when it cannot be flipped.', '  const h = mesh.edgeHalfedge(input);\n  const t = mesh.twin(h);\n  return false;'),
    fixtures: [
      { name: 'an edge inside a disk', shapes: [['disk', 2]], input: 10 },
      { name: 'an edge at the centre of a disk (valence 6)', shapes: [['disk', 1]], input: 0 },
      { name: 'a boundary edge (refused)', shapes: [['disk', 1]], input: 1, rule: 'A boundary edge has one triangle, and a flip needs two: return false and change nothing.' },
      { name: 'an edge of a tetrahedron, whose other corners are joined (refused)', shapes: [['tetrahedron']], input: 0, rule: 'The new edge would repeat one that is there: return false and change nothing.' },
      { name: 'an edge between quads (refused)', shapes: [['cube']], input: 0, rule: 'A flip turns an edge between two triangles: return false and change nothing.' },
      hidden('an inner edge whose ends are both on the boundary', 'An edge between two triangles is flipped wherever its ends are, the boundary included.', { shapes: [['grid', 2, 2]], input: 7 }),
      hidden('an edge of the second of two components', 'Ids are not positions: the edge can be anywhere, and nothing else moves.', { shapes: [['tetrahedron'], ['disk', 1]], input: 6 }),
      hidden('two triangles back to back (refused)', 'When both triangles have the same three corners, the flip would join a vertex to itself: return false and change nothing.', { off: PILLOW, input: 0 }),
    ],
    reference: (mesh, e) => !canFlipEdge(mesh, id(e)) && (flipEdge(mesh, id(e)), true),
  },
  {
    id: 'split-edge',
    title: 'Split an edge',
    kind: 'edit',
    answer: 'vertex',
    task: [
      'Put a new vertex at the midpoint of edge `input`, and split each triangle beside the edge in two by joining the new vertex to its opposite corner. Return the new vertex.',
      'On the boundary there is one triangle to split; the hole gains a side.',
    ],
    hints: [
      'A split makes one vertex, and on an interior edge three edges and two faces (one of each fewer on the boundary).',
      'Split the edge first (a → m → b, the faces now have four sides), then cut each face in two from m to its opposite corner.',
      'The new vertex is on the boundary when the edge was: its vertexHalfedge must then be its outgoing boundary halfedge.',
    ],
    starter: starter('input: an edge id. Split it at its midpoint; return the new vertex.', '  const h = mesh.edgeHalfedge(input);\n  const [a, b] = [mesh.position(mesh.origin(h)), mesh.position(mesh.target(h))];\n  const m = mesh.newVertex([(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2]);\n  return m;'),
    fixtures: [
      { name: 'an edge inside a disk', shapes: [['disk', 2]], input: 10 },
      { name: 'an edge on the boundary', shapes: [['disk', 1]], input: 1 },
      { name: 'an edge of a tetrahedron (valence 3 corners)', shapes: [['tetrahedron']], input: 2 },
      hidden('an inner edge whose ends are both on the boundary', 'The new vertex is inside when the edge is, even where both ends are on the boundary.', { shapes: [['grid', 2, 2]], input: 7 }),
      hidden('the boundary side of a corner triangle', "On the boundary the hole gains a side, also where the triangle's other corner has only two edges.", { shapes: [['grid', 2, 2]], input: 5 }),
      hidden('an edge of the second of two components', 'Ids are not positions: the edge can be anywhere, and nothing else moves.', { shapes: [['tetrahedron'], ['disk', 1]], input: 6 }),
    ],
    reference: (mesh, e) => splitEdgeTriangulated(mesh, id(e)).vertex,
  },
  {
    id: 'collapse-edge',
    title: 'Collapse an edge',
    kind: 'edit',
    answer: 'vertex',
    refusal: -1,
    task: [
      'Shrink edge `input` of a triangle mesh to one vertex at its midpoint; the triangles beside it disappear. Return the vertex that remains.',
      'Return -1 and change nothing when the collapse would break the mesh: the two ends share a neighbour that is not across a triangle of the edge (the link condition), the edge belongs to a tetrahedron, or both ends are on the boundary but the edge is not.',
    ],
    hints: [
      'Keep origin(h) and delete target(h): every halfedge that started at the deleted vertex must start at the kept one.',
      'Each triangle beside the edge loses a side, so two of its edges become one: keep one, delete the other, and mend the twins by relinking next and prev.',
      'The link condition: collect the neighbours of both ends; the only ones they may share are the corners across the two triangles.',
      'Afterwards the kept vertex, the corners across, and any face that lost its halfedge need a valid halfedge each.',
    ],
    starter: starter('input: an edge id. Collapse it; return the surviving vertex, or -1.', '  return -1;'),
    fixtures: [
      { name: 'an edge inside a disk', shapes: [['disk', 2]], input: 10 },
      { name: 'an edge at the centre of a disk', shapes: [['disk', 2]], input: 0 },
      { name: 'an edge on the boundary', shapes: [['disk', 2]], input: 20 },
      { name: 'an edge of a bipyramid whose ends share a third neighbour, against the link condition (refused)', shapes: [['uvSphere', 2, 3]], input: 1, rule: 'Ends that share a neighbour not across the edge would join two edges into one: return -1 and change nothing.' },
      { name: 'an edge of a tetrahedron (refused)', shapes: [['tetrahedron']], input: 0, rule: 'A tetrahedron has no edge to spare: return -1 and change nothing.' },
      hidden('the boundary side of a corner triangle', 'A boundary edge whose triangle has a second boundary side collapses too: the triangle goes, and the hole loses a side.', { shapes: [['grid', 2, 2]], input: 5 }),
      hidden('an inner edge whose ends are both on the boundary (refused)', 'An inner edge joining two boundary vertices would pinch the surface into a figure 8: return -1 and change nothing.', { shapes: [['grid', 2, 2]], input: 7 }),
      hidden('a lone triangle (refused)', 'A triangle with no other face cannot lose a side: return -1 and change nothing.', { shapes: [['singleTriangle']], input: 0 }),
    ],
    reference: (mesh, e) => (canCollapseEdge(mesh, id(e)) ? -1 : collapseEdge(mesh, id(e)).vertex),
  },
  {
    id: 'inset-vertex',
    aliases: ['poke-face'],
    title: 'Inset a vertex (poke a face)',
    kind: 'edit',
    answer: 'vertex',
    refusal: -1,
    task: ['Put a new vertex at the centroid of face `input` (the average of its corners) and join it to every corner, so a face of k sides becomes k triangles. Return the new vertex.'],
    hints: [
      'A face of k sides gains one vertex, k edges and k − 1 faces (it keeps its own id as one of the triangles).',
      'Around the face, each old halfedge gets a new triangle: old halfedge, then corner → m, then m → corner.',
    ],
    starter: starter('input: a face id. Poke it; return the new vertex.', '  return -1;'),
    fixtures: [
      { name: 'a triangle of a tetrahedron', shapes: [['tetrahedron']], input: 0 },
      { name: 'a quad of a cube', shapes: [['cube']], input: 2 },
      { name: 'a triangle on the boundary of a disk', shapes: [['disk', 1]], input: 3 },
      hidden('a lone triangle', 'A face with the hole all around is poked like any other: every side keeps its boundary twin.', { shapes: [['singleTriangle']], input: 0 }),
      hidden('a pentagon with a corner on a straight side', 'A face of any number of sides becomes that many triangles, whatever its shape.', { off: SLIVER_UNDER_PENTAGON, input: 0 }),
      hidden('a quad at the corner of a grid', 'A face along the boundary is poked too: its boundary sides stay on the hole.', { shapes: [['grid', 2, 2, 1]], input: 0 }),
    ],
    reference: (mesh, f) => pokeFace(mesh, id(f)).vertex,
  },
  {
    id: 'extrude-face',
    title: 'Extrude a face',
    kind: 'edit',
    answer: 'face',
    refusal: -1,
    task: [
      'The input is `{ face, offset, inset }`. Surround face `face` with a ring of quads, one on each of its sides, and move the face: each corner v gets a new copy u, and face `face` now runs round the copies. Return `face`.',
      'Where the copies go: u = (1 − inset)·v + inset·c + offset·n, where c is the centroid of the face (the average of its corners) and n its unit normal (see the hints). So inset 0.5 moves each corner half way to the centre, and offset 0.5 pulls the face out by 0.5.',
      'Each quad runs v_i → v_i+1 → u_i+1 → u_i, on the old side i, which stays where it is with its twin (so the face across it, or the hole, is not touched). A face of k sides gains k vertices, 2k edges and k faces.',
      'Return -1 and change nothing when the extrusion does not apply: an inset outside 0 … 1, or an offset other than 0 on a face with no area (it has no normal to move along).',
    ],
    hints: [
      "The unit normal: add up the cross products p_i × p_i+1 of each side's two corners (Newell's formula; half the sum is the vector area), then divide by its length. Compute every position before you write anything.",
      'Make k new vertices, k rim edges (u_i → u_i+1, in the face), k rung edges (v_i → u_i) and k quads first, then set every origin, next and face.',
      'Quad i uses four halfedges: the old side i, the rung at v_i+1 going up, the twin of rim i (u_i+1 → u_i) and the rung at v_i coming down.',
      'The old corners keep their vertexHalfedge (their old halfedges still leave them); each new corner needs one, and the face needs one of its rims.',
    ],
    starter: starter('input: { face, offset, inset }. Extrude the face; return it, or -1.', '  const { face, offset, inset } = input;\n  return -1;'),
    fixtures: [
      { name: 'a quad of a cube, pulled out by 0.5', shapes: [['cube']], input: { face: 1, offset: 0.5, inset: 0 } },
      { name: 'a triangle of a tetrahedron, inset 0.25 and pushed in by 0.2', shapes: [['tetrahedron']], input: { face: 0, offset: -0.2, inset: 0.25 } },
      { name: 'a triangle inside a disk, inset 0.5 (offset 0)', shapes: [['disk', 2]], input: { face: 0, offset: 0, inset: 0.5 } },
      hidden('a triangle at the corner of a grid', 'A face along the boundary is extruded too: the quads on its boundary sides border the hole.', { shapes: [['grid', 2, 2]], input: { face: 0, offset: 0.3, inset: 0.2 } }),
      hidden('a lone triangle', 'A face with the hole all around is extruded like any other.', { shapes: [['singleTriangle']], input: { face: 0, offset: 0.5, inset: 0.1 } }),
      hidden('a pentagon with a corner on a straight side', 'A face of any number of sides gets one quad per side.', { off: SLIVER_UNDER_PENTAGON, input: { face: 0, offset: 0.4, inset: 0.3 } }),
      hidden('an inset of 1.5 (refused)', 'An inset outside 0 … 1 is refused: return -1 and change nothing.', { shapes: [['cube']], input: { face: 2, offset: 0.1, inset: 1.5 } }),
      hidden('a face with no area, pulled out by 0.3 (refused)', 'A face with no area has no normal: with an offset other than 0 it is refused (return -1 and change nothing).', { off: SLIVER_UNDER_PENTAGON, input: { face: 1, offset: 0.3, inset: 0 } }),
    ],
    reference: (mesh, input) => {
      const { face, offset, inset } = named(input);
      return canExtrudeFace(mesh, face, { offset, inset }) ? -1 : extrudeFace(mesh, face, { offset, inset }).face;
    },
  },
  {
    id: 'bevel-vertex',
    title: 'Bevel a vertex',
    kind: 'edit',
    answer: 'face',
    refusal: -1,
    task: [
      'The input is `{ vertex, amount }`. Replace vertex `vertex` by a new face with one corner on each of its edges: a vertex with d edges becomes a face of d sides. Return the new face.',
      'Each corner goes `amount` of the way from the vertex along its edge: the corner on the edge to neighbour x is at (1 − amount)·v + amount·x. The vertex itself becomes one of the corners (moved there), the others are new: d − 1 vertices, d edges and one face more.',
      'Each face around the vertex gains one side (between its two new corners), and the new face gets the other halfedge of each of those sides. On the boundary, the gap of the hole gains the side instead of a face, so the new face borders the hole.',
      'Return -1 and change nothing when the bevel does not apply: a vertex with fewer than 3 edges, or an amount outside 0 … 1.',
    ],
    hints: [
      'List the outgoing halfedges (spokes) counter-clockwise first: h, then twin(prev(h)), … Spoke j keeps its edge; it now leaves corner j.',
      'Between spoke j and spoke j + 1 lies one face (or the hole). Its loop went … → prev(spoke j) → spoke j → …, through v; now it goes prev(spoke j) → new side → spoke j, where the new side runs from corner j + 1 to corner j.',
      'Read every prev and face you need before the first write: the loops change under you.',
      "Every corner needs a vertexHalfedge: its spoke. On the boundary, the corner just after the hole's gap must leave along the new side on the hole instead.",
    ],
    starter: starter('input: { vertex, amount }. Bevel the vertex; return the new face, or -1.', '  const { vertex, amount } = input;\n  return -1;'),
    fixtures: [
      { name: 'a corner of a cube, amount 0.25', shapes: [['cube']], input: { vertex: 0, amount: 0.25 } },
      { name: 'the centre of a disk (6 edges), amount 0.5', shapes: [['disk', 1]], input: { vertex: 0, amount: 0.5 } },
      { name: 'a corner of a tetrahedron, amount 0.3', shapes: [['tetrahedron']], input: { vertex: 1, amount: 0.3 } },
      hidden('a vertex on the boundary (4 edges)', 'A vertex on the boundary is bevelled too: the new face borders the hole along one side.', { shapes: [['disk', 2]], input: { vertex: 7, amount: 0.3 } }),
      hidden('a vertex on the boundary with two faces', 'A boundary vertex with 3 edges becomes a triangle on the hole.', { shapes: [['disk', 1]], input: { vertex: 2, amount: 0.4 } }),
      hidden('a corner of a grid of quads, with 2 edges (refused)', 'A vertex with fewer than 3 edges is refused (the face would have fewer than 3 sides): return -1 and change nothing.', { shapes: [['grid', 2, 2, 1]], input: { vertex: 0, amount: 0.3 } }),
      hidden('an amount of 1.5 (refused)', 'An amount outside 0 … 1 is refused: return -1 and change nothing.', { shapes: [['cube']], input: { vertex: 3, amount: 1.5 } }),
    ],
    reference: (mesh, input) => {
      const { vertex, amount } = named(input);
      return canBevelVertex(mesh, vertex, amount) ? -1 : bevelVertex(mesh, vertex, { amount }).face;
    },
  },
  {
    id: 'bevel-edge',
    title: 'Bevel an edge',
    kind: 'edit',
    answer: 'face',
    refusal: -1,
    task: [
      'The input is `{ edge, amount }`. Replace edge `edge`, between two faces, by a new face with one corner on every other edge leaving either of its ends. If its ends have m and n edges, the new face has m + n − 2 sides. Return the new face.',
      'Each corner goes `amount` of the way from its end along its edge: (1 − amount)·a + amount·x for the edge from end a to neighbour x. The two ends become two of the corners (moved there); the rest are new.',
      'Every face around either end, other than the two beside the edge, gains one side between its two new corners (on the boundary, the hole gains it). The two faces beside the edge keep a side each toward the new face: the edge itself on one side, a new edge on the other.',
      'Return -1 and change nothing when the bevel does not apply: an edge on the boundary, an edge whose ends have fewer than 5 edges between them (the face would have fewer than 3 sides), or an amount outside 0 … 1.',
    ],
    hints: [
      'Work out both ends like a vertex bevel, one fan each: the spokes of end a are its outgoing halfedges counter-clockwise after h = edgeHalfedge(e), and those of end b after twin(h). There are no new sides across the two faces of the edge.',
      'Read every prev, next, face and position you need before the first write.',
      'Where twin(h) was, in its face, a new edge now runs from b to the last corner of a; twin(h) itself moves into the new face and leaves the last corner of b. h stays in its face.',
      'The new face goes: twin(h), the sides of a, the twin of the new edge, the sides of b.',
    ],
    starter: starter('input: { edge, amount }. Bevel the edge; return the new face, or -1.', '  const { edge, amount } = input;\n  return -1;'),
    fixtures: [
      { name: 'an edge inside a disk, amount 0.25', shapes: [['disk', 2]], input: { edge: 0, amount: 0.25 } },
      { name: 'an edge of a cube, amount 0.3', shapes: [['cube']], input: { edge: 0, amount: 0.3 } },
      { name: 'an edge of a tetrahedron, amount 0.2', shapes: [['tetrahedron']], input: { edge: 3, amount: 0.2 } },
      hidden('an edge from the centre of a disk to its rim', 'An edge between two faces with an end on the boundary is bevelled too: the new face borders the hole at that end.', { shapes: [['disk', 1]], input: { edge: 0, amount: 0.3 } }),
      hidden('an edge across a strip (both ends on the boundary)', 'An edge between two faces with both ends on the boundary is bevelled too: the new face borders the hole at each end.', { shapes: [['strip', 3]], input: { edge: 1, amount: 0.25 } }),
      hidden('an edge on the boundary (refused)', 'An edge on the boundary is refused (a bevel puts a face between two faces): return -1 and change nothing.', { shapes: [['disk', 1]], input: { edge: 1, amount: 0.3 } }),
      hidden('an edge of a pillow of two triangles (refused)', 'An edge whose ends have fewer than 5 edges between them is refused (the new face would have fewer than 3 sides): return -1 and change nothing.', { off: PILLOW, input: { edge: 0, amount: 0.3 } }),
      hidden('an amount of -0.5 (refused)', 'An amount outside 0 … 1 is refused: return -1 and change nothing.', { shapes: [['cube']], input: { edge: 4, amount: -0.5 } }),
    ],
    reference: (mesh, input) => {
      const { edge, amount } = named(input);
      return canBevelEdge(mesh, edge, amount) ? -1 : bevelEdge(mesh, edge, { amount }).face;
    },
  },
  {
    id: 'dissolve-edge',
    title: 'Dissolve an edge',
    kind: 'edit',
    answer: 'exact',
    refusal: false,
    task: [
      'Erase edge `input`: the two faces beside it become one face. Return true.',
      'On the boundary, an edge has one face: that face becomes part of the hole instead (its halfedges lose their face). Any other edge of that face that also lay along the hole would then have the hole on both sides: it goes too, and so does a corner left with no edge.',
      'Return false and change nothing when the dissolve does not apply: two faces that share a corner besides the ends of the edge (the merged face would pass through it twice), and on the boundary, a face that cannot become a hole (one that touches the boundary only at a corner, or a face with the hole all around).',
    ],
    hints: [
      'Between two faces: give every halfedge of the second face the first face, then link prev(h) to next(twin(h)) and prev(twin(h)) to next(h). Delete the edge and the second face.',
      "The two ends of the edge, and the face you keep, may have had one of the edge's halfedges as their halfedge: give them another.",
      "On the boundary, the face's halfedges keep their next and prev: they become a hole's loop. A corner that was inside the mesh is now on the boundary, so its halfedge must be the one of those that leaves it.",
      'An edge with the hole on both sides: splice it out of the loops by relinking the halfedges around its two ends.',
    ],
    starter: starter('input: an edge id. Dissolve it and return true, or return false.', '  const h = mesh.edgeHalfedge(input);\n  return false;'),
    fixtures: [
      { name: 'an edge between two triangles inside a disk', shapes: [['disk', 2]], input: 10 },
      { name: 'an edge of a cube (two quads become a hexagon)', shapes: [['cube']], input: 0 },
      { name: 'an edge inside a grid of quads', shapes: [['grid', 3, 3, 1]], input: 5 },
      hidden('an edge on the boundary of a disk', 'An edge on the boundary is dissolved by making its face part of the hole.', { shapes: [['disk', 1]], input: 1 }),
      hidden('an edge on the boundary at the end of a strip', 'When the face joins the hole, its other edges along the hole go too (the hole on both sides), and so does a corner left with no edge.', { shapes: [['strip', 3]], input: 4 }),
      hidden('an edge whose faces share another corner (refused)', 'Two faces that share a corner besides the ends of the edge are not merged: return false and change nothing.', { off: SLIVER_UNDER_PENTAGON, input: 0 }),
      hidden('an edge on the boundary whose face touches the hole at a corner (refused)', 'A face that would touch the hole at a corner only (a pinch) does not become a hole: return false and change nothing.', { shapes: [['strip', 3]], input: 0 }),
      hidden('an edge of a lone triangle (refused)', 'A face with the hole all around does not become a hole (nothing would be left of it): return false and change nothing.', { shapes: [['singleTriangle']], input: 0 }),
    ],
    reference: (mesh, e) => !canDissolveEdge(mesh, id(e)) && (dissolveEdge(mesh, id(e)), true),
  },
  {
    id: 'dissolve-vertex',
    title: 'Dissolve a vertex',
    kind: 'edit',
    answer: 'face',
    refusal: -1,
    task: [
      'Remove vertex `input` and all its edges: the faces around it merge into one face. Return the merged face.',
      'The merged face runs round what is left of the faces: for each face around the vertex, its sides away from the vertex, one face after the other.',
      'On the boundary, the faces do not merge with the hole: the faces around the vertex merge, and a new edge between its two neighbours along the boundary closes the merged face (the hole now runs along that edge).',
      'Return -1 and change nothing when the dissolve does not apply: the merged face would pass through a vertex twice, or have fewer than 3 sides; on the boundary, a vertex with one face (nothing to merge), or one whose two neighbours along the boundary are already joined by an edge.',
    ],
    hints: [
      'List the outgoing halfedges x counter-clockwise. The face of x, face(x), keeps the path from next(x) round to prev(prev(x)): link the end of each path to the start of the next one.',
      'Before writing, walk those paths and collect their corners: a corner met twice means the merged face would pass through it twice.',
      'Keep one face (the first), give every halfedge of the paths that face, and delete the others, the edges at the vertex, and the vertex.',
      'On the boundary, start from the boundary halfedge: the hole runs a → v → b. The new edge has halfedge b → a in the merged face and a → b on the hole, between the hole halfedges before a and after b.',
      'A neighbour whose halfedge ran to the vertex needs another; so does the kept face if its halfedge was one of the edges that go.',
    ],
    starter: starter('input: a vertex id. Dissolve it; return the merged face, or -1.', '  const start = mesh.vertexHalfedge(input);\n  return -1;'),
    fixtures: [
      { name: 'the centre of a disk (six triangles become a hexagon)', shapes: [['disk', 1]], input: 0 },
      { name: 'a corner of a cube (three quads become a hexagon)', shapes: [['cube']], input: 0 },
      { name: 'a vertex inside a grid of quads', shapes: [['grid', 3, 3, 1]], input: 5 },
      hidden('a vertex on the boundary of a disk', 'A vertex on the boundary does not merge its faces with the hole: a new edge between its two neighbours along the boundary closes the merged face.', { shapes: [['disk', 2]], input: 7 }),
      hidden('a corner of a tetrahedron', 'Dissolving a corner of a tetrahedron leaves two triangles on the same three corners, back to back: a valid closed mesh.', { shapes: [['tetrahedron']], input: 0 }),
      hidden('a corner of a grid in one face (refused)', 'A boundary vertex with one face has nothing to merge: return -1 and change nothing.', { shapes: [['grid', 2, 2]], input: 2 }),
      hidden('a boundary vertex whose neighbours are already joined (refused)', 'When the two neighbours along the boundary are already joined, the closing edge would be a second edge between them: return -1 and change nothing.', { shapes: [['annulus', 3]], input: 0 }),
      hidden('a vertex whose faces share another corner (refused)', 'The merged face must not pass through a vertex twice: return -1 and change nothing.', { off: SLIVER_UNDER_PENTAGON, input: 0 }),
      hidden('a vertex of a pillow of two triangles (refused)', 'A merged face needs 3 sides: return -1 and change nothing.', { off: PILLOW, input: 0 }),
    ],
    reference: (mesh, v) => (canDissolveVertex(mesh, id(v)) ? -1 : dissolveVertex(mesh, id(v)).face),
  },
  {
    id: 'collapse-face',
    title: 'Collapse a face',
    kind: 'edit',
    answer: 'vertex',
    refusal: -1,
    task: [
      'Shrink face `input` to one vertex at its centroid (the average of its corners): its corners merge into that vertex, and its edges and the face itself disappear. Return the vertex that remains.',
      'Each face across a side of the face loses that side. A triangle across a side disappears, and its two other edges, which now join the same two vertices, become one edge. A face of four or more sides keeps the rest.',
      'Return -1 and change nothing when the collapse would break the mesh: a face across several sides left with fewer than 3; an edge between two corners that is not a side (it would become a loop); a vertex joined to two corners other than across a triangle beside the face (the link condition); a face, or the hole, that would meet the new vertex at two places; triangles on every side meeting at one vertex (a tetrahedron); a single edge, or two triangles on the same three corners, left around the new vertex; a face on its own.',
    ],
    hints: [
      'Keep corner 0 as the new vertex: every other halfedge that left a corner now leaves it. Move it to the centroid.',
      "Check everything before the first write: list the halfedges leaving each corner between the face's two edges there (its spokes), counter-clockwise; around the new vertex they come corner after corner.",
      'Across side i, the loop of the face beyond runs … → prev(t) → t → next(t) → …, with t = twin(side i): link prev(t) to next(t) and t is out.',
      'Across a triangle, link its halfedge from corner i to the third corner into the place of the one from corner i + 1 (the edge that goes).',
      "Afterwards the new vertex needs a halfedge (its boundary one if it has one), and a face whose halfedge went needs another.",
    ],
    starter: starter('input: a face id. Collapse it; return the vertex that remains, or -1.', '  return -1;'),
    fixtures: [
      { name: 'a triangle inside a disk', shapes: [['disk', 2]], input: 0 },
      { name: 'a quad of a cube', shapes: [['cube']], input: 0 },
      { name: 'a quad inside a grid of quads', shapes: [['grid', 3, 3, 1]], input: 4 },
      hidden('a quad at the corner of a grid', 'A face along the boundary is collapsed too: the hole loses the sides it shared with the face.', { shapes: [['grid', 2, 2, 1]], input: 0 }),
      hidden('a triangle of a small disk, with a side on the rim', 'A face with a side on the boundary and triangles beside it is collapsed too.', { shapes: [['disk', 1]], input: 0 }),
      hidden('a face of a tetrahedron (refused)', 'When the triangles on every side meet at one vertex, only an edge would be left: return -1 and change nothing.', { shapes: [['tetrahedron']], input: 0 }),
      hidden('a triangle whose corners touch the boundary at two places (refused)', 'A face that meets the hole at two places would pinch the surface: return -1 and change nothing.', { shapes: [['grid', 2, 2]], input: 3 }),
      hidden('a triangle of a sphere whose corners share a neighbour (refused)', 'A vertex joined to two corners, other than across a triangle beside the face, would be joined to the new vertex twice (the link condition): return -1 and change nothing.', { shapes: [['uvSphere', 3, 3]], input: 1 }),
      hidden('a lone triangle (refused)', 'A face on its own has nothing to collapse into: return -1 and change nothing.', { shapes: [['singleTriangle']], input: 0 }),
    ],
    reference: (mesh, f) => (canCollapseFace(mesh, id(f)) ? -1 : collapseFace(mesh, id(f)).vertex),
  },
  {
    id: 'make-boundary',
    title: 'Make a face a hole',
    kind: 'edit',
    answer: 'exact',
    refusal: false,
    task: [
      'Turn face `input` into a hole: its halfedges lose their face (face -1) and keep their next and prev, so they run round the hole. Return true.',
      'Where the face lay along a hole, the edges between them now have the hole on both sides: they go, and the two holes become one (or, where the face touched the hole along separate stretches, the hole splits). A corner left with no edge goes too.',
      "Return false and change nothing when the face cannot become a hole: a corner already on the boundary where neither of the face's edges is (the two holes would meet at that vertex only, a pinch), or a face with the hole all around it (nothing would be left).",
    ],
    hints: [
      'Before writing, note for each side whether its twin is on the boundary, and for each corner whether it is on the boundary.',
      "A corner that was inside the mesh is now on the boundary: its halfedge must be its outgoing boundary halfedge, the face's side that leaves it.",
      'An edge with the hole on both sides, halfedge g and its twin: link prev(g) to next(twin(g)) and prev(twin(g)) to next(g), then delete the edge. If one end had no other edge, the loop turns back there: skip it and delete that vertex.',
    ],
    starter: starter('input: a face id. Make it a hole and return true, or return false.', '  return false;'),
    fixtures: [
      { name: 'a triangle inside a disk', shapes: [['disk', 2]], input: 0 },
      { name: 'a quad of a cube', shapes: [['cube']], input: 0 },
      { name: 'a quad inside a grid of quads', shapes: [['grid', 3, 3, 1]], input: 4 },
      hidden('a triangle on the rim of a disk', 'A face along the hole joins it: the edge between them, with the hole on both sides now, goes.', { shapes: [['disk', 2]], input: 6 }),
      hidden('a triangle in the middle of a strip', 'A face that touches the hole along two separate stretches splits it into two loops.', { shapes: [['strip', 3]], input: 1 }),
      hidden('the triangle at a corner of a grid', 'A corner that only this face had is left with no edge: it goes too.', { shapes: [['grid', 2, 2]], input: 2 }),
      hidden('a triangle touching the rim at a corner (refused)', 'A corner already on the boundary where neither edge of the face is would pinch the surface: return false and change nothing.', { shapes: [['disk', 2]], input: 8 }),
      hidden('a lone triangle (refused)', 'A face with the hole all around would leave nothing: return false and change nothing.', { shapes: [['singleTriangle']], input: 0 }),
    ],
    reference: (mesh, f) => !canMakeBoundary(mesh, id(f)) && (makeBoundary(mesh, id(f)), true),
  },
  {
    id: 'weld-edges',
    title: 'Weld two boundary edges',
    kind: 'edit',
    answer: 'exact',
    refusal: false,
    task: [
      'The input is `[e1, e2]`, two edges on the boundary. Glue them into one edge with a face on each side, and return true.',
      "Which ends meet follows the faces' orientation: with h1 (a1 → b1) and h2 (a2 → b2) the boundary halfedges of the two edges, b2 merges into a1 and a2 into b1, each pair at its midpoint. e1 stays, and h1 takes the place of twin(h2) in its face; e2 and the merged-away vertices go.",
      'Where the two edges follow one another along the hole (they share an end, a "zip"), only their other ends merge, and the shared vertex is no longer on the boundary.',
      'Return false and change nothing when the weld does not apply: an edge that is not on the boundary, the same edge twice, two ends that would merge that are already joined by an edge or are corners of one face, and a merge that would join two vertices by two edges.',
    ],
    hints: [
      'Check each pair that merges (a1 with b2, b1 with a2; skip a pair that is already one vertex): look at the halfedges leaving both, for an edge between them, a face they share, and neighbours they would then share.',
      "Every halfedge that left b2 (other than e2's) now leaves a1, and every one that left a2 now leaves b1.",
      'The hole: link prev(h2) to next(h1), and prev(h1) to next(h2), except at a zip, where the hole closes.',
      'Each merged vertex still on the boundary needs its outgoing boundary halfedge as its halfedge.',
    ],
    starter: starter('input: [e1, e2], two boundary edges. Weld them and return true, or return false.', '  const [e1, e2] = input;\n  return false;'),
    fixtures: [
      { name: 'two triangles side by side', shapes: [['singleTriangle'], ['singleTriangle']], input: [1, 5] },
      { name: 'two squares side by side', shapes: [['grid', 1, 1, 1], ['grid', 1, 1, 1]], input: [1, 7] },
      { name: 'a triangle onto the rim of a disk', shapes: [['disk', 1], ['singleTriangle']], input: [11, 14] },
      hidden('the two ends of a strip (it becomes a ring)', 'Two edges of one hole, apart, are welded too: the hole splits into two loops.', { shapes: [['strip', 3]], input: [4, 10] }),
      hidden('the two straight sides of a fan (a zip)', 'Two edges that follow one another along the hole are zipped: only their other ends merge, and the shared vertex leaves the boundary.', { shapes: [['fan', 4, 4.5]], input: [0, 8] }),
      hidden('two sides of one triangle (refused)', 'Two ends already joined by an edge cannot merge (the edge would become a loop): return false and change nothing.', { shapes: [['singleTriangle']], input: [0, 1] }),
      hidden('an edge inside a disk (refused)', 'Only boundary edges can be welded: return false and change nothing.', { shapes: [['disk', 1]], input: [0, 1] }),
      hidden('a weld that would double an edge (refused)', 'A weld that would join two vertices by two edges is refused: return false and change nothing.', { shapes: [['strip', 3]], input: [3, 10] }),
      hidden('the same edge twice (refused)', 'A weld joins two different edges: return false and change nothing.', { shapes: [['disk', 1]], input: [1, 1] }),
    ],
    reference: (mesh, input) => {
      const [e1, e2] = input as readonly number[];
      return !canWeldEdges(mesh, e1, e2) && (weldEdges(mesh, e1, e2), true);
    },
  },
  {
    id: 'triangulate',
    title: 'Triangulate the mesh',
    kind: 'edit',
    answer: 'none',
    compare: 'triangulation',
    task: [
      'Cut every face of more than three sides into triangles, in place, by adding diagonals: edges inside the face between two of its corners. A face of k sides becomes k − 2 triangles, with k − 3 new edges. Return nothing.',
      'Any diagonals are right, as long as every triangle lies inside its face: none may fold over (turn the other way round than the face) or have no area, and no diagonal may join two vertices that an edge already joins.',
      'A face that cannot be cut so (its corners all on one line: it has no area) is left as it is.',
    ],
    hints: [
      'A fan from one corner (joining it to every other corner) is right for a convex face. For the others, cut off an "ear": a corner that turns the way the face turns, with no other corner inside its triangle; repeat on what is left.',
      "To see which way a corner turns, lay the face flat: the normal n is the sum of the cross products of consecutive corners (Newell); a corner turns the face's way when (b − a) × (c − b) points along n.",
      'Give every new triangle its three halfedges: old sides where it has them, and new edges for the diagonals (one edge for the two triangles on either side). The face keeps its id as one of the triangles; every corner keeps its halfedge.',
      'List the faces first: the triangles you make are faces too, and need no visit.',
    ],
    starter: starter('no input. Cut every face of more than three sides into triangles.', '  for (const f of mesh.faces()) {\n    // cut f here\n  }'),
    fixtures: [
      { name: 'a cube (six quads)', shapes: [['cube']] },
      { name: 'a grid of quads', shapes: [['grid', 2, 2, 1]] },
      { name: 'a ring of quads and a tetrahedron', shapes: [['annulus', 5], ['tetrahedron']] },
      hidden('an L-shaped hexagon', 'A face that is not convex must be cut along diagonals inside it: no triangle may fold over.', { off: L_HEXAGON }),
      hidden('a pentagon with a corner on a straight side, over a flat triangle', 'No triangle may have no area (three corners on a line), and no diagonal may double an edge that is already there.', { off: SLIVER_UNDER_PENTAGON }),
      hidden('a quad with its corners on one line, beside a square', 'A face with no area cannot be cut into triangles: leave it as it is.', { off: FLAT_QUAD_AND_SQUARE }),
      hidden('a torus of quads', 'Every face of more than three sides is cut, whatever the shape of the mesh.', { shapes: [['torus', 4, 3]] }),
    ],
    reference: (mesh) => {
      triangulateMesh(mesh);
    },
  },
  {
    id: 'loop-subdivision',
    title: 'Loop subdivision',
    kind: 'edit',
    answer: 'none',
    task: [
      'Apply one level of Loop subdivision to the triangle mesh, in place: every triangle becomes four, and every vertex moves.',
      'New edge points: 3/8 of each end and 1/8 of the two opposite corners (on the boundary, the midpoint). Old vertices of valence n: (1 − nβ) of themselves plus β of each neighbour, β = (1/n)(5/8 − (3/8 + ¼ cos(2π/n))²); on the boundary 3/4 of themselves and 1/8 of their two boundary neighbours, except a corner of valence 2, which stays where it is.',
    ],
    hints: [
      'Compute every new position from the old mesh first, and only then change the connectivity.',
      'Split every old edge (your split-edge without its face cuts), then cut each hexagon into four triangles by joining its three new vertices.',
      'Remember which vertices are new: they are the ones with ids from the old vertexCount() on.',
    ],
    starter: starter('no input. Subdivide the mesh once, in place.', '  const oldVertices = mesh.vertices();\n  const oldEdges = mesh.edges();\n'),
    fixtures: [
      { name: 'a tetrahedron (valence 3)', shapes: [['tetrahedron']] },
      { name: 'a disk (boundary)', shapes: [['disk', 1]] },
      { name: 'two components', shapes: [['tetrahedron'], ['fan', 3]] },
    ],
    reference: (mesh) => subdivide(mesh, 'loop', 1),
  },
  {
    id: 'catmull-clark',
    title: 'Catmull-Clark subdivision',
    kind: 'edit',
    answer: 'none',
    task: [
      'Apply one level of Catmull-Clark subdivision to the mesh, in place: every face of n sides becomes n quads, and every old vertex moves. Faces may have any number of sides.',
      'New points: a face point at the centroid of each face (the average of its corners); an edge point on each edge at the average of its two ends and the two face points beside it (on the boundary, the midpoint of the edge). Each quad joins a face point, an edge point, an old corner and the next edge point.',
      'Old vertices, with n edges: (F + 2R + (n − 3)·P) / n, where P is the vertex, F the average of the n face points around it and R the average of the midpoints of its n edges. On the boundary, 3/4 of itself and 1/8 of each of its two neighbours along the boundary, except a corner with 2 edges, which stays where it is.',
    ],
    hints: [
      'Compute every new position from the old mesh first (face points, edge points, old vertices), and only then change the connectivity.',
      'Split every old edge at its edge point (your split-edge, without cutting the faces): every face now has twice as many sides, old corners and edge points taking turns.',
      'Then, in each face, add its face point and join it to each edge point of the face: n new edges, and n quads (the face keeps its id as one of them).',
      'Remember the lists of old vertices, edges and faces before you start: the ones you make need no visit.',
    ],
    starter: starter('no input. Subdivide the mesh once, in place.', '  const oldVertices = mesh.vertices();\n  const oldEdges = mesh.edges();\n  const oldFaces = mesh.faces();\n'),
    fixtures: [
      { name: 'a cube', shapes: [['cube']] },
      { name: 'a tetrahedron (triangles)', shapes: [['tetrahedron']] },
      { name: 'a torus of quads', shapes: [['torus', 4, 3]] },
      hidden('a grid of quads', 'On the boundary, edge points are midpoints and vertices follow the boundary (3/4 of themselves, 1/8 of each boundary neighbour); a corner with 2 edges stays.', { shapes: [['grid', 2, 2, 1]] }),
      hidden('a disk of triangles', 'The boundary rules hold for triangles too, and an interior vertex with 6 edges moves by the same formula as any other.', { shapes: [['disk', 1]] }),
      hidden('an L-shaped hexagon alone', 'A face of any number of sides becomes that many quads around its face point.', { off: L_HEXAGON }),
      hidden('two components: a cube and a fan', 'Every component is subdivided.', { shapes: [['cube'], ['fan', 3]] }),
    ],
    reference: (mesh) => subdivide(mesh, 'catmull-clark', 1),
  },
  {
    id: 'linear-subdivision',
    title: 'Linear subdivision',
    kind: 'edit',
    answer: 'none',
    task: [
      "Apply one level of linear subdivision to the mesh, in place: Catmull-Clark's connectivity (every face of n sides becomes n quads) with the simplest positions. Faces may have any number of sides.",
      'New points: a face point at the centroid of each face (the average of its corners) and an edge point at the midpoint of each edge. Each quad joins a face point, an edge point, an old corner and the next edge point. The old vertices stay where they are.',
    ],
    hints: [
      'Compute the face points from the old mesh first, then change the connectivity.',
      'Split every old edge at its midpoint (your split-edge, without cutting the faces): every face now has twice as many sides, old corners and edge points taking turns.',
      'Then, in each face, add its face point and join it to each edge point of the face: n new edges, and n quads (the face keeps its id as one of them).',
    ],
    starter: starter('no input. Subdivide the mesh once, in place.', '  const oldEdges = mesh.edges();\n  const oldFaces = mesh.faces();\n'),
    fixtures: [
      { name: 'a cube', shapes: [['cube']] },
      { name: 'a tetrahedron (triangles)', shapes: [['tetrahedron']] },
      { name: 'a grid of quads', shapes: [['grid', 2, 2, 1]] },
      hidden('an L-shaped hexagon alone', 'A face of any number of sides becomes that many quads around its face point.', { off: L_HEXAGON }),
      hidden('two components: a cube and a fan', 'Every component is subdivided.', { shapes: [['cube'], ['fan', 3]] }),
    ],
    reference: (mesh) => subdivide(mesh, 'linear', 1),
  },
  {
    id: 'isotropic-remesh',
    title: 'Isotropic remeshing',
    kind: 'edit',
    answer: 'none',
    compare: 'properties',
    bounds: REMESH_BOUNDS,
    task: [
      'Remesh the triangle mesh in place so that its edges are all about `input.targetEdgeLength` long and its triangles nearly equilateral, in `input.iterations` rounds of four steps (Botsch & Kobbelt):',
      '1. split every edge longer than 4/3 of the target at its midpoint; 2. collapse every edge shorter than 4/5 of it, unless the collapse would break the mesh or make an edge longer than 4/3 of the target; 3. flip every edge whose flip brings the valences of its four corners closer to 6 (4 on the boundary); 4. move each vertex part of the way toward the centroid of its neighbours, within its tangent plane.',
      `There is no single right answer, so your result is checked for what remeshing promises: a valid mesh of triangles with the input's topology, at least ${REMESH_BOUNDS.shareNearTarget! * 100} % of its edges within 4/5 … 4/3 of the target, and every point within ${REMESH_BOUNDS.maxDistance * 100} % of the input's size of the input surface (and the input within that of yours). The boundary stays where it is.`,
    ],
    hints: [
      'Reuse your split, collapse and flip. Before each step, list the edges to visit; an edge an earlier operation of the step deleted is skipped (check it still exists before you use it).',
      'Collapse only where it is safe: the link condition (the ends share no neighbour but the corners across the edge), not both ends on the boundary unless the edge is, and no edge of the result longer than 4/3 of the target.',
      'Flip when the sum of |valence − 6| over the four corners goes down (|valence − 4| for a boundary vertex), never a boundary edge.',
      'Tangential smoothing: the move toward the centroid minus its part along the vertex normal. Leave boundary vertices where they are.',
    ],
    starter: starter('input: { targetEdgeLength, iterations }. Remesh the mesh in place.', '  const L = input.targetEdgeLength;\n  for (let i = 0; i < input.iterations; i++) {\n    // split, collapse, flip, smooth\n  }'),
    fixtures: [
      { name: 'a sphere, to edges as long as it has', shapes: [['uvSphere', 12, 8]], input: { targetEdgeLength: 0.46, iterations: 3 } },
      { name: 'a disk, to shorter edges', shapes: [['disk', 4]], input: { targetEdgeLength: 0.2, iterations: 3 } },
      { name: 'a grid, to longer edges', shapes: [['grid', 6, 6]], input: { targetEdgeLength: 0.28, iterations: 3 } },
      hidden('a sphere, to much shorter edges', 'Edges far longer than the target are split until they are near it: every edge longer than 4/3 of it, again in each round.', { shapes: [['uvSphere', 8, 6]], input: { targetEdgeLength: 0.3, iterations: 3 } }),
      hidden('a fan', 'The boundary is kept: boundary vertices stay on the boundary, and the hole keeps its one loop.', { shapes: [['fan', 6]], input: { targetEdgeLength: 0.3, iterations: 3 } }),
      hidden('two components: a sphere and a disk', 'Every component is remeshed, none is joined to another, and none is lost.', { shapes: [['uvSphere', 12, 8], ['disk', 3]], input: { targetEdgeLength: 0.4, iterations: 3 } }),
    ],
    reference: (mesh, input) => remesh(mesh, named(input)),
  },
  {
    id: 'simplify',
    title: 'Simplification',
    kind: 'edit',
    answer: 'none',
    compare: 'properties',
    bounds: SIMPLIFY_BOUNDS,
    task: [
      'Simplify the triangle mesh in place until it has at most `input.faces` faces, by collapsing edges, cheapest first (Garland & Heckbert): each vertex carries a quadric, the sum of the squared distances to the planes of its triangles; an edge costs the quadric error of the point its collapse leaves, and that point is where the error is least.',
      `There is no single right answer, so your result is checked for what simplification promises: a valid mesh of triangles with the input's topology, from ${SIMPLIFY_BOUNDS.shareOfTargetFaces! * 100} % of \`input.faces\` up to that many faces, and every point within ${SIMPLIFY_BOUNDS.maxDistance * 100} % of the input's size of the input surface (and the input within that of yours).`,
    ],
    hints: [
      'Reuse your collapse, with its refusals: a collapse that breaks the link condition is skipped, and the next cheapest edge is tried.',
      'A quadric is a symmetric 4 × 4 matrix (10 numbers): for a plane n·x + d = 0 it is [n, d][n, d]ᵀ, weighted by the triangle\'s area. A vertex\'s quadric is the sum of its triangles\'; a collapsed edge\'s, the sum of its two ends\'.',
      'Where the 3 × 3 part of the quadric cannot be inverted (a flat neighbourhood), put the point at the edge\'s midpoint.',
      'After a collapse, the edges around the kept vertex get new costs: recompute them (a priority queue with stale entries skipped works, and so does a plain search for the cheapest edge on a small mesh).',
    ],
    starter: starter('input: { faces }. Collapse edges until the mesh has at most that many faces.', '  while (mesh.faceCount() > input.faces) {\n    // find the cheapest edge that can collapse, and collapse it\n    break;\n  }'),
    fixtures: [
      { name: 'a sphere, to a quarter of its faces', shapes: [['uvSphere', 12, 8]], input: { faces: 44 } },
      { name: 'a disk, to a quarter of its faces', shapes: [['disk', 4]], input: { faces: 24 } },
      { name: 'a grid, to a quarter of its faces', shapes: [['grid', 6, 6]], input: { faces: 18 } },
      hidden('a tetrahedron beside a sphere', 'A collapse that would break the mesh is never made: the tetrahedron cannot lose an edge, so the faces come off the sphere.', { shapes: [['tetrahedron'], ['uvSphere', 10, 6]], input: { faces: 28 } }),
      hidden('two disks', 'Boundaries are kept: a boundary vertex stays on the boundary, and every component stays.', { shapes: [['disk', 3], ['disk', 3]], input: { faces: 20 } }),
    ],
    reference: (mesh, input) => {
      decimate(mesh, { targetFaces: named(input).faces });
    },
  },
];

/** The built-in exercise with this id, or with this as one of its older ids (`poke-face`). */
export function findExercise(id: string): Exercise | undefined {
  return exercises.find((exercise) => exercise.id === id) ?? exercises.find((exercise) => exercise.aliases?.includes(id));
}
