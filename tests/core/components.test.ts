import { describe, expect, it } from 'vitest';
import { buildMesh, componentRoots, cutMesh, mergeSoups, tetrahedron, torus } from '../../src/index.js';

describe('componentRoots', () => {
  it('names each of two tetrahedra by its lowest vertex', () => {
    const { mesh } = buildMesh(mergeSoups([tetrahedron(), tetrahedron()]));
    expect([...componentRoots(mesh)]).toEqual([0, 0, 0, 0, 4, 4, 4, 4]);
  });

  it('finds one part in a torus, and two after a plane cut across its ring keeps both sides', () => {
    const { mesh } = buildMesh(torus(8, 4));
    expect(new Set(componentRoots(mesh))).toEqual(new Set([0]));
    cutMesh(mesh, [0, 1, 0, 0.05], { keep: 'both' });
    const roots = componentRoots(mesh);
    const parts = new Set([...mesh.vertices()].map((v) => roots[v]));
    expect(parts.size).toBe(2);
    // every edge joins two vertices of one part
    for (const e of mesh.edges()) expect(roots[mesh.origin(2 * e)]).toBe(roots[mesh.origin(2 * e + 1)]);
  });

  it('leaves an isolated vertex its own root', () => {
    const { mesh } = buildMesh(tetrahedron());
    const v = mesh.addVertex(5, 5, 5);
    expect(componentRoots(mesh)[v]).toBe(v);
    expect([...componentRoots(mesh)].slice(0, 4)).toEqual([0, 0, 0, 0]);
  });
});
