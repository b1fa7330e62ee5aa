/**
 * The built-in exercises, easiest first: queries that walk the pointers, then the local edits of
 * every halfedge course, then one level of Loop subdivision. Each reference is the library's own
 * function; the fixtures hold the hard cases (boundaries, valence 3, a forbidden collapse, several
 * components).
 */
import { boundaryLoops, vertexAdjacentVertices } from '../circulators.js';
import { canCollapseEdge, collapseEdge } from '../edits/collapse.js';
import { canFlipEdge, flipEdge } from '../edits/flip.js';
import { pokeFace } from '../edits/poke.js';
import { splitEdgeTriangulated } from '../edits/split-edge.js';
import { subdivide } from '../subdivision/index.js';
import type { Exercise, ExerciseInput } from './exercise.js';

/** The input of a fixture that gives one id. */
const id = (input: ExerciseInput | undefined) => input as number;

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
      { name: 'a boundary edge (refused)', shapes: [['disk', 1]], input: 1 },
      { name: 'an edge of a tetrahedron (the other corners are joined: refused)', shapes: [['tetrahedron']], input: 0 },
      { name: 'an edge between quads (refused)', shapes: [['cube']], input: 0 },
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
    ],
    reference: (mesh, e) => splitEdgeTriangulated(mesh, id(e)).vertex,
  },
  {
    id: 'collapse-edge',
    title: 'Collapse an edge',
    kind: 'edit',
    answer: 'vertex',
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
      { name: 'an edge of a bipyramid whose ends share a third neighbour (link condition: refused)', shapes: [['uvSphere', 2, 3]], input: 1 },
      { name: 'an edge of a tetrahedron (refused)', shapes: [['tetrahedron']], input: 0 },
    ],
    reference: (mesh, e) => (canCollapseEdge(mesh, id(e)) ? -1 : collapseEdge(mesh, id(e)).vertex),
  },
  {
    id: 'poke-face',
    title: 'Poke a face',
    kind: 'edit',
    answer: 'vertex',
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
    ],
    reference: (mesh, f) => pokeFace(mesh, id(f)).vertex,
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
];

/** The built-in exercise with this id, or with this as one of its older ids (`poke-face`). */
export function findExercise(id: string): Exercise | undefined {
  return exercises.find((exercise) => exercise.id === id) ?? exercises.find((exercise) => exercise.aliases?.includes(id));
}
