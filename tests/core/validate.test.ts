import { describe, expect, it } from 'vitest';
import { bowTie, buildMesh, fan, type HalfedgeMesh, type Invariant, soupFromArrays, tetrahedron, torus, validate } from '../../src/index.js';

const closed = () => buildMesh(tetrahedron()).mesh;
const open = () => buildMesh(fan(3)).mesh;

function invariants(mesh: HalfedgeMesh): Invariant[] {
  return [...new Set(validate(mesh).map((v) => v.invariant))];
}

describe('validate', () => {
  it('finds nothing wrong with a freshly built mesh', () => {
    expect(validate(closed())).toEqual([]);
    expect(validate(open())).toEqual([]);
    expect(validate(buildMesh(torus(5, 4)).mesh)).toEqual([]);
  });

  it('names a next pointer whose prev does not point back', () => {
    const mesh = closed();
    mesh.heNext[0] = 6; // h0 → h6, but prev(h6) is still someone else
    const found = validate(mesh);
    expect(found.map((v) => v.invariant)).toContain('next-prev-inverse');
    expect(found.find((v) => v.invariant === 'next-prev-inverse')!.halfedges).toContain(0);
  });

  it('names a halfedge whose twin starts elsewhere than its target', () => {
    const mesh = closed();
    mesh.heVertex[1] = mesh.heVertex[0]; // twin of h0 now starts where h0 starts
    expect(invariants(mesh)).toContain('twin-origin');
  });

  it('names a face loop that changes face along next', () => {
    const mesh = closed();
    mesh.heFace[2] = 3;
    const found = validate(mesh).filter((v) => v.invariant === 'face-along-next');
    expect(found[0]!.message).toMatch(/h\d+ is in f\d+ but next\(h\d+\) = h\d+ is in f\d+/);
  });

  it('names a face whose halfedge belongs to another face', () => {
    const mesh = closed();
    mesh.fHalfedge[0] = mesh.fHalfedge[1];
    expect(invariants(mesh)).toEqual(['face-halfedge']);
  });

  it('names a vertex whose halfedge does not start at it', () => {
    const mesh = closed();
    mesh.vHalfedge[0] = mesh.vHalfedge[1];
    expect(invariants(mesh)).toEqual(['vertex-halfedge']);
  });

  it('names a boundary vertex whose halfedge is not its boundary halfedge', () => {
    const mesh = open();
    const v = 1;
    mesh.vHalfedge[v] = mesh.hePrev[mesh.vHalfedge[v]] ^ 1; // an interior outgoing halfedge
    expect(invariants(mesh)).toEqual(['boundary-vertex-halfedge']);
  });

  it('names an isolated vertex that halfedges still start from', () => {
    const mesh = closed();
    mesh.vHalfedge[2] = -1;
    expect(invariants(mesh)).toEqual(['isolated-vertex']);
  });

  it('names two edges that join the same two vertices', () => {
    // two separate triangles, the second's first two corners then relabelled as the first's
    const soup = { positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, -1, 0]), faceStarts: new Uint32Array([0, 3, 6]), faceIndices: new Uint32Array([0, 1, 2, 4, 3, 5]) };
    const mesh = buildMesh(soup).mesh;
    expect(validate(mesh)).toEqual([]);
    for (let h = 0; h < mesh.halfedgeSlots; h++) {
      if (mesh.heVertex[h] === 3) mesh.heVertex[h] = 0;
      if (mesh.heVertex[h] === 4) mesh.heVertex[h] = 1;
    }
    mesh.deleteVertex(3);
    mesh.deleteVertex(4);
    const parallel = validate(mesh).filter((v) => v.invariant === 'parallel-edge');
    expect(parallel).toHaveLength(1);
    expect(parallel[0]!.vertices).toEqual([0, 1]);
    expect(parallel[0]!.message).toMatch(/^e\d+ and e\d+ both join v0 and v1/);
  });

  it('names a face that passes through one vertex twice', () => {
    // a pentagon whose corner v3 is relabelled v0: it then runs v0 v1 v2 v0 v4
    const mesh = buildMesh(soupFromArrays([0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 1, 0, 0, 2, 0], [[0, 1, 2, 3, 4]])).mesh;
    expect(validate(mesh)).toEqual([]);
    for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heVertex[h] === 3) mesh.heVertex[h] = 0;
    mesh.vHalfedge[3] = -1;
    mesh.deleteVertex(3);
    const repeats = validate(mesh).filter((v) => v.invariant === 'face-repeats-vertex');
    expect(repeats).toEqual([
      {
        invariant: 'face-repeats-vertex',
        message: 'f0 passes through v0 twice: a mesh file lists a face by its corners and cannot hold that',
        faces: [0],
        vertices: [0],
      },
    ]);
  });

  it('names a vertex with two fans (a pinch)', () => {
    // the builder splits the bow tie's centre into v0 and v5; merge them back by hand
    const mesh = buildMesh(bowTie()).mesh;
    for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heVertex[h] === 5) mesh.heVertex[h] = 0;
    mesh.deleteVertex(5);
    expect(invariants(mesh)).toEqual(['vertex-fan']);
  });

  it('names references to deleted or missing elements instead of crashing', () => {
    const mesh = closed();
    mesh.heNext[3] = 999;
    mesh.heFace[4] = 77;
    mesh.heVertex[5] = -3;
    const found = validate(mesh);
    expect(found.filter((v) => v.invariant === 'reference-in-range').flatMap((v) => v.halfedges)).toEqual([3, 4, 5]);
  });

  it('names an edge with no face on either side', () => {
    const mesh = open();
    const e = mesh.addEdge();
    const [a, b] = [2 * e, 2 * e + 1];
    mesh.heNext[a] = mesh.hePrev[a] = b;
    mesh.heNext[b] = mesh.hePrev[b] = a;
    mesh.heVertex[a] = 0;
    mesh.heVertex[b] = 2;
    expect(invariants(mesh)).toContain('edge-without-face');
  });

  it('names a face of two sides', () => {
    const mesh = open();
    const f = mesh.addFace();
    const e = mesh.addEdge();
    const v = mesh.addVertex(9, 9, 9);
    const w = mesh.addVertex(8, 8, 8);
    const [a, b] = [2 * e, 2 * e + 1];
    mesh.heNext[a] = mesh.hePrev[a] = b;
    mesh.heNext[b] = mesh.hePrev[b] = a;
    mesh.heVertex[a] = v;
    mesh.heVertex[b] = w;
    mesh.heFace[a] = mesh.heFace[b] = f;
    mesh.fHalfedge[f] = a;
    mesh.vHalfedge[v] = a;
    mesh.vHalfedge[w] = b;
    expect(invariants(mesh)).toEqual(['face-degree']);
  });

  it('terminates on a next cycle that never returns, and stops at the limit', () => {
    const mesh = buildMesh(torus(6, 6)).mesh;
    for (let h = 0; h < mesh.halfedgeSlots; h++) mesh.heNext[h] = (h + 2) % mesh.halfedgeSlots;
    expect(validate(mesh, { limit: 5 })).toHaveLength(5);
  });
});
