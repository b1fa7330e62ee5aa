import { describe, expect, it } from 'vitest';
import {
  annulus,
  boundaryLoops,
  buildMesh,
  disk,
  doubleTorus,
  faceAdjacentFaces,
  faceHalfedges,
  faceVertices,
  type HalfedgeMesh,
  loopHalfedges,
  moebiusStrip,
  strip,
  torus,
  uvSphere,
  vertexAdjacentFaces,
  vertexAdjacentVertices,
  vertexIncomingHalfedges,
  vertexOutgoingHalfedges,
} from '../../src/index.js';

const meshes: Array<[string, HalfedgeMesh]> = [
  ['sphere', buildMesh(uvSphere(5, 7)).mesh],
  ['torus', buildMesh(torus(6, 5)).mesh],
  ['double torus', buildMesh(doubleTorus()).mesh],
  ['disk', buildMesh(disk(3)).mesh],
  ['annulus', buildMesh(annulus(9)).mesh],
  ['Möbius strip', buildMesh(moebiusStrip(8)).mesh],
];

/** The halfedges leaving v, found by scanning every halfedge (the oracle). */
function outgoingByScan(mesh: HalfedgeMesh, v: number): number[] {
  const result: number[] = [];
  for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heVertex[h] === v) result.push(h);
  return result;
}

describe.each(meshes)('circulators on the %s agree with the raw pointer walk', (_, mesh) => {
  it('faceHalfedges follows next from the face halfedge, and every halfedge names the face', () => {
    for (let f = 0; f < mesh.faceSlots; f++) {
      const walked: number[] = [];
      let h = mesh.fHalfedge[f];
      do {
        walked.push(h);
        h = mesh.heNext[h];
      } while (h !== mesh.fHalfedge[f]);
      expect([...faceHalfedges(mesh, f)]).toEqual(walked);
      expect([...faceVertices(mesh, f)]).toEqual(walked.map((g) => mesh.heVertex[g]));
      expect([...faceAdjacentFaces(mesh, f)]).toEqual(walked.map((g) => mesh.heFace[g ^ 1]));
      for (const g of walked) expect(mesh.heFace[g]).toBe(f);
    }
  });

  it('faceHalfedges walked backwards with prev gives the same loop reversed', () => {
    for (let f = 0; f < mesh.faceSlots; f++) {
      const backwards: number[] = [];
      let h = mesh.fHalfedge[f];
      do {
        backwards.push(h);
        h = mesh.hePrev[h];
      } while (h !== mesh.fHalfedge[f]);
      const forwards = [...faceHalfedges(mesh, f)];
      expect([forwards[0], ...forwards.slice(1).reverse()]).toEqual(backwards);
    }
  });

  it('vertexOutgoingHalfedges visits every halfedge leaving the vertex exactly once', () => {
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const rotated = [...vertexOutgoingHalfedges(mesh, v)];
      expect(rotated[0]).toBe(mesh.vHalfedge[v]);
      expect([...rotated].sort((a, b) => a - b)).toEqual(outgoingByScan(mesh, v));
    }
  });

  it('rotating counter-clockwise (twin of prev) is rotating clockwise (next of twin) in reverse', () => {
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const ccw = [...vertexOutgoingHalfedges(mesh, v)];
      const cw: number[] = [];
      let h = mesh.vHalfedge[v];
      do {
        cw.push(h);
        h = mesh.heNext[h ^ 1];
      } while (h !== mesh.vHalfedge[v]);
      expect([ccw[0], ...ccw.slice(1).reverse()]).toEqual(cw);
    }
  });

  it('incoming halfedges, neighbours and faces come from the outgoing ones', () => {
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const out = [...vertexOutgoingHalfedges(mesh, v)];
      expect([...vertexIncomingHalfedges(mesh, v)]).toEqual(out.map((h) => h ^ 1));
      for (const h of vertexIncomingHalfedges(mesh, v)) expect(mesh.target(h)).toBe(v);
      expect([...vertexAdjacentVertices(mesh, v)]).toEqual(out.map((h) => mesh.target(h)));
      expect([...vertexAdjacentFaces(mesh, v)]).toEqual(out.map((h) => mesh.heFace[h]).filter((f) => f !== -1));
    }
  });

  it('boundaryLoops yields one halfedge per hole, and the holes hold every boundary halfedge', () => {
    const loops = [...boundaryLoops(mesh)];
    const inLoops = loops.flatMap((h) => [...loopHalfedges(mesh, h)]);
    const boundary = [];
    for (let h = 0; h < mesh.halfedgeSlots; h++) if (mesh.heFace[h] === -1) boundary.push(h);
    expect([...inLoops].sort((a, b) => a - b)).toEqual(boundary);
    expect(new Set(inLoops).size).toBe(inLoops.length);
  });
});

describe('circulator order', () => {
  it('goes counter-clockwise around an interior vertex of a planar mesh', () => {
    const { mesh } = buildMesh(disk(2));
    const angle = (w: number) => Math.atan2(mesh.positions[3 * w + 1], mesh.positions[3 * w]);
    // vertex 0 is the centre: its neighbours' angles increase (mod 2π) as we rotate
    const angles = [...vertexAdjacentVertices(mesh, 0)].map(angle);
    let turns = 0;
    for (let i = 0; i < angles.length; i++) {
      const step = (angles[(i + 1) % angles.length] - angles[i] + 2 * Math.PI) % (2 * Math.PI);
      expect(step).toBeGreaterThan(0);
      expect(step).toBeLessThan(Math.PI);
      turns += step;
    }
    expect(turns).toBeCloseTo(2 * Math.PI);
  });

  it('starts at the boundary halfedge of a boundary vertex, then sweeps the fan', () => {
    const { mesh } = buildMesh(strip(3));
    for (let v = 0; v < mesh.vertexSlots; v++) {
      const faces = [...vertexOutgoingHalfedges(mesh, v)].map((h) => mesh.heFace[h]);
      expect(faces[0]).toBe(-1);
      expect(faces.slice(1)).not.toContain(-1);
    }
  });

  it('stops with an error instead of looping forever on a broken mesh', () => {
    const { mesh } = buildMesh(uvSphere(4, 5));
    // make vertex 0's rotation skip its start: point a prev at a halfedge of another vertex
    const h = mesh.vHalfedge[0];
    mesh.hePrev[h] = mesh.heNext[mesh.heNext[h]] ^ 1;
    expect(() => [...vertexOutgoingHalfedges(mesh, 0)]).toThrow(/does not close/);
  });
});
