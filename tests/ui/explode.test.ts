import { describe, expect, it } from 'vitest';
import { boundingSphere, buildMesh, cutMesh, type HalfedgeMesh, meshFingerprint, mergeSoups, type PolygonSoup, tetrahedron, torus } from '../../src/index.js';
import { cutPlaneOnShow, EXPLODE_SHARE, explodedMesh, explodedRender, explodeOffsets } from '../../src/ui/explode.js';
import { RenderLayout, renderBounds } from '../../src/workers/render.js';

/** A soup moved by (dx, dy, dz). */
function moved(soup: PolygonSoup, dx: number, dy: number, dz: number): PolygonSoup {
  const positions = Float64Array.from(soup.positions, (x, i) => x + [dx, dy, dz][i % 3]);
  return { ...soup, positions };
}

/** Vertex v's offset (a zero the sign of the normal made −0 reads as 0: the same offset). */
function offsetOf(offsets: Float64Array, v: number): number[] {
  return [0, 1, 2].map((k) => offsets[3 * v + k] + 0);
}

/** The torus cut across its ring by the plane y = −0.05, keeping both sides: two bent tubes, capped. */
function cutTorus(): HalfedgeMesh {
  const { mesh } = buildMesh(torus(8, 4));
  cutMesh(mesh, [0, 2, 0, 0.1], { keep: 'both' });
  return mesh;
}

describe('explodeOffsets', () => {
  it('moves two tetrahedra apart along the line between their centres, by a fifth of the bounding radius', () => {
    const { mesh } = buildMesh(mergeSoups([tetrahedron(), moved(tetrahedron(), 4, 0, 0)]));
    const explosion = explodeOffsets(mesh, null)!;
    // the whole box is x ∈ [−1, 5], centred at (2, 0, 0); its farthest corners are √11 away
    const distance = EXPLODE_SHARE * Math.sqrt(11);
    expect(explosion.distance).toBe(distance);
    for (let v = 0; v < 4; v++) expect(offsetOf(explosion.offsets, v)).toEqual([-distance, 0, 0]);
    for (let v = 4; v < 8; v++) expect(offsetOf(explosion.offsets, v)).toEqual([distance, 0, 0]);
  });

  it('leaves a part at the centre of the whole where it is', () => {
    const { mesh } = buildMesh(mergeSoups([moved(tetrahedron(), -4, 0, 0), tetrahedron(), moved(tetrahedron(), 4, 0, 0)]));
    const { offsets, distance } = explodeOffsets(mesh, null)!;
    expect([0, 4, 8].map((v) => offsetOf(offsets, v))).toEqual([
      [-distance, 0, 0],
      [0, 0, 0],
      [distance, 0, 0],
    ]);
  });

  it('moves the two halves of a cut torus along the plane normal: the half above up, the half below down', () => {
    const mesh = cutTorus();
    const { offsets, distance } = explodeOffsets(mesh, [0, 2, 0, 0.1])!;
    expect(distance).toBe(EXPLODE_SHARE * boundingSphere(mesh)!.radius);
    const p = mesh.positions;
    let above = 0;
    let below = 0;
    for (const v of mesh.vertices()) {
      // a vertex off the plane is in the half on its side; one on it (a cap's) in either
      const upper = offsets[3 * v + 1] > 0;
      expect(offsetOf(offsets, v)).toEqual([0, upper ? distance : -distance, 0]);
      if (p[3 * v + 1] > -0.05 + 1e-9) expect(upper).toBe(true);
      if (p[3 * v + 1] < -0.05 - 1e-9) expect(upper).toBe(false);
      if (upper) above++;
      else below++;
    }
    expect(above).toBeGreaterThan(0);
    expect(below).toBeGreaterThan(0);
  });

  it('has nothing to pull apart in a mesh of one part', () => {
    expect(explodeOffsets(buildMesh(torus(8, 4)).mesh, null)).toBeNull();
    expect(explodeOffsets(buildMesh(torus(8, 4)).mesh, [0, 1, 0, 0])).toBeNull();
  });

  it('leaves an isolated vertex where it is', () => {
    const { mesh } = buildMesh(mergeSoups([tetrahedron(), moved(tetrahedron(), 4, 0, 0)]));
    const lone = mesh.addVertex(9, 9, 9);
    expect(offsetOf(explodeOffsets(mesh, null)!.offsets, lone)).toEqual([0, 0, 0]);
  });
});

describe('the exploded mesh and render buffers', () => {
  it('draw every vertex at its position plus its offset, and leave the mesh itself as it was', () => {
    const mesh = cutTorus();
    const before = meshFingerprint(mesh);
    const explosion = explodeOffsets(mesh, [0, 2, 0, 0.1])!;
    const drawn = explodedMesh(mesh, explosion);
    const render = new RenderLayout().full(mesh);
    const drawnRender = explodedRender(render, explosion, drawn);
    for (const v of mesh.vertices()) {
      const expected = mesh.position(v).map((x, k) => x + explosion.offsets[3 * v + k]);
      expect(drawn.position(v)).toEqual(expected);
      // the render positions are single precision: moved from the rounded position, and rounded again
      const expected32 = mesh.position(v).map((x, k) => Math.fround(Math.fround(x) + explosion.offsets[3 * v + k]));
      expect([...drawnRender.positions.subarray(3 * v, 3 * v + 3)]).toEqual(expected32);
    }
    // the same pointers and counts: the drawn mesh reads the mesh's own arrays
    expect(drawn.heNext).toBe(mesh.heNext);
    expect(drawn.nFaces).toBe(mesh.nFaces);
    expect(drawnRender.triangles).toBe(render.triangles);
    // the bounds are those of the parts where they moved to: every moved vertex inside the box and the sphere
    expect(drawnRender.bounds).toEqual(renderBounds(drawn));
    for (const v of drawn.vertices()) {
      const p = drawn.position(v);
      expect(Math.hypot(...p.map((x, k) => x - drawnRender.bounds.center[k]))).toBeLessThanOrEqual(drawnRender.bounds.radius * (1 + 1e-12));
      p.forEach((x, k) => expect(x >= drawnRender.bounds.min[k] && x <= drawnRender.bounds.max[k]).toBe(true));
    }
    expect(drawnRender.bounds.radius).toBeGreaterThan(render.bounds.radius);
    expect(meshFingerprint(mesh)).toBe(before);
    expect(render.positions[1]).toBe(Math.fround(mesh.positions[1]));
  });
});

describe('cutPlaneOnShow', () => {
  const open = { label: 'open torus.off', vertices: 0, faces: 0, source: { kind: 'open' as const, name: 'torus.off', sample: 'torus.off' } };
  const cut = (keep?: 'both' | 'above') => ({ label: 'plane cut', vertices: 0, faces: 0, source: { kind: 'operation' as const, request: { kind: 'cut' as const, plane: [0, 1, 0, 0] as [number, number, number, number], keep } } });

  it('is the plane of a cut that kept both sides, while the view is at it', () => {
    expect(cutPlaneOnShow({ items: [open, cut('both')], index: 1 })).toEqual([0, 1, 0, 0]);
    expect(cutPlaneOnShow({ items: [open, cut()], index: 1 })).toEqual([0, 1, 0, 0]);
  });

  it('is null for a cut that kept one side, and once the view has gone back before the cut', () => {
    expect(cutPlaneOnShow({ items: [open, cut('above')], index: 1 })).toBeNull();
    expect(cutPlaneOnShow({ items: [open, cut('both')], index: 0 })).toBeNull();
  });
});
