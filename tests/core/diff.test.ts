import { describe, expect, it } from 'vitest';
import { buildMesh, diffPointers, tetrahedron } from '../../src/index.js';

describe('diffPointers', () => {
  it('finds nothing between a mesh and its copy', () => {
    const { mesh } = buildMesh(tetrahedron());
    expect(diffPointers(mesh, mesh.clone())).toEqual({ changes: [], total: 0 });
  });

  it('lists each changed field old → new, and new elements as changes from -1', () => {
    const { mesh } = buildMesh(tetrahedron());
    const after = mesh.clone();
    after.heNext[0] = 7;
    after.fHalfedge[2] = 9;
    const v = after.addVertex(1, 2, 3);
    after.vHalfedge[v] = 5;
    expect(diffPointers(mesh, after).changes).toEqual([
      { element: 'halfedge', id: 0, field: 'next', before: 2, after: 7 },
      { element: 'vertex', id: 4, field: 'halfedge', before: -1, after: 5 },
      { element: 'face', id: 2, field: 'halfedge', before: mesh.fHalfedge[2], after: 9 },
    ]);
  });

  it('counts every change but lists only up to the limit', () => {
    const { mesh } = buildMesh(tetrahedron());
    const after = mesh.clone();
    after.heNext.fill(0);
    const diff = diffPointers(mesh, after, 3);
    expect(diff.changes).toHaveLength(3);
    // 12 halfedges, one of which (h4, closing face 0) already had next = h0
    expect(diff.total).toBe(11);
  });
});
