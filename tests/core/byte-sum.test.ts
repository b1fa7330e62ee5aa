import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import { byteSum } from '../../src/core/memory.js';
import { buildMesh, tetrahedron } from '../../src/index.js';

describe('byteSum', () => {
  it('sums the first count bytes of any view, aligned or not, of any length and any byte values', () => {
    fc.assert(
      fc.property(fc.uint8Array({ maxLength: 3000 }), fc.nat({ max: 7 }), fc.nat(), (data, offset, cut) => {
        const buffer = new Uint8Array(data.length + offset);
        buffer.set(data, offset);
        const view = buffer.subarray(offset);
        const count = data.length === 0 ? 0 : cut % (data.length + 1);
        let expected = 0;
        for (let i = 0; i < count; i++) expected += view[i];
        expect(byteSum(view, count)).toBe(expected);
      }),
      { seed: 7, numRuns: 300 },
    );
    // past the 128 words a lane holds, every byte 255
    expect(byteSum(new Uint8Array(100_003).fill(255), 100_003)).toBe(255 * 100_003);
  });

  it('is what a mesh recounts its deleted slots with', () => {
    const { mesh } = buildMesh(tetrahedron());
    mesh.vDeleted[3] = 1;
    mesh.eDeleted.fill(1, 2, 5);
    mesh.recountDeleted();
    expect(mesh.nVertices).toBe(mesh.vertexSlots - 1);
    expect(mesh.nEdges).toBe(mesh.edgeSlots - 3);
  });
});
