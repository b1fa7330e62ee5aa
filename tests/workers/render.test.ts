/**
 * The render layout patched change by change draws what a fresh layout of the mesh draws, also
 * after a face shrank and grew back many times (its range stays, its polygon count must not drift).
 */
import { describe, expect, it } from 'vitest';
import { applyChange, buildMesh, type ChangeRecord, grid, invertChange, noChange, positionsChange, smooth, triangulateFace, uvSphere } from '../../src/index.js';
import { REBOUND_ABOVE, type RenderBounds, type RenderBuffers } from '../../src/workers/protocol.js';
import { RenderLayout } from '../../src/workers/render.js';

/** The triangles the buffers draw, each as its sorted corners and its face. */
function drawnTriangles(render: RenderBuffers): string[] {
  const triangles: string[] = [];
  for (let t = 0; t < render.counts.triangles; t++) {
    if (render.triangleFace[t] === -1) continue;
    const corners = Array.from(render.triangles.subarray(3 * t, 3 * t + 3)).sort((a, b) => a - b);
    triangles.push(`${corners.join(' ')} f${render.triangleFace[t]}`);
  }
  return triangles.sort();
}

describe('the render layout, patched', () => {
  it('redraws a quad made non-convex after another face was triangulated and put back ten times', () => {
    const { mesh } = buildMesh(grid(3, 3, true));
    const layout = new RenderLayout();
    const render = layout.full(mesh);
    const patch = (change: ChangeRecord) => {
      const result = layout.patch(mesh, change);
      expect(result).not.toBeNull();
      for (const { buffer, offset, data } of result!.writes) (render[buffer] as Uint32Array | Int32Array | Float32Array).set(data, offset);
      render.counts = result!.counts;
    };
    const { record } = triangulateFace(mesh, 0);
    patch(record!);
    for (let i = 0; i < 10; i++) {
      applyChange(mesh, record!, 'backward');
      patch(invertChange(record!));
      applyChange(mesh, record!, 'forward');
      patch(record!);
    }
    // corner 1 of the middle quad pushed past the diagonal 0–2: a fan from corner 0 would now cross outside
    const f = 4;
    const loop = [0, 1, 2, 3].map((k) => {
      let h = mesh.fHalfedge[f];
      for (let i = 0; i < k; i++) h = mesh.heNext[h];
      return mesh.heVertex[h];
    });
    const [p0, p1, p2, p3] = loop.map((v) => mesh.position(v));
    const middle = [0, 1, 2].map((k) => (p0[k] + p2[k]) / 2);
    const moved = [0, 1, 2].map((k) => middle[k] + 0.3 * (p3[k] - middle[k]));
    mesh.positions.set(moved, 3 * loop[1]);
    const position = { kind: 'vertex' as const, name: 'position', itemSize: 3, index: Int32Array.of(loop[1]), start: 0, old: Float64Array.from(p1), new: Float64Array.from(moved) };
    patch({ ...noChange(mesh), values: [position] });
    expect(drawnTriangles(render)).toEqual(drawnTriangles(new RenderLayout().full(mesh)));
  });

  it('carries the bounds measured again when it moves many vertices, none when it moves a few', () => {
    const { mesh } = buildMesh(uvSphere(64, 96));
    expect(mesh.vertexSlots).toBeGreaterThan(REBOUND_ABOVE);
    const layout = new RenderLayout();
    const holdsEveryVertex = (bounds: RenderBounds) => {
      for (const v of mesh.vertices()) {
        const p = mesh.position(v);
        expect(Math.hypot(p[0] - bounds.center[0], p[1] - bounds.center[1], p[2] - bounds.center[2])).toBeLessThanOrEqual(bounds.radius * (1 + 1e-12));
        p.forEach((x, k) => expect(x >= bounds.min[k] && x <= bounds.max[k]).toBe(true));
      }
      // the box is the tightest: a vertex on each of its sides
      for (let k = 0; k < 3; k++) {
        expect([...mesh.vertices()].some((v) => mesh.position(v)[k] === bounds.min[k])).toBe(true);
        expect([...mesh.vertices()].some((v) => mesh.position(v)[k] === bounds.max[k])).toBe(true);
      }
    };
    holdsEveryVertex(layout.full(mesh).bounds);

    // smoothing shrinks the sphere: the new bounds are smaller, and still hold every vertex
    const before = mesh.positions.slice(0, 3 * mesh.vertexSlots);
    smooth(mesh, { method: 'laplacian', iterations: 5 });
    const patched = layout.patch(mesh, positionsChange(mesh, before))!;
    expect(patched.bounds).not.toBeNull();
    holdsEveryVertex(patched.bounds!);
    expect(patched.bounds).toEqual(new RenderLayout().full(mesh).bounds);
    expect(patched.bounds!.radius).toBeLessThan(0.999);

    // one vertex moved: the page grows its own sphere
    const old = mesh.positions.slice(0, 3);
    mesh.positions[0] *= 2;
    const position = { kind: 'vertex' as const, name: 'position', itemSize: 3, index: Int32Array.of(0), start: 0, old, new: mesh.positions.slice(0, 3) };
    expect(layout.patch(mesh, { ...noChange(mesh), values: [position] })!.bounds).toBeNull();
  });
});
