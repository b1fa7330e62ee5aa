import { describe, expect, it } from 'vitest';
import { buildMesh, deserializeMesh, diffPointers, meshBuffers, serializeMesh, torus, validate } from '../../src/index.js';

describe('serializeMesh / deserializeMesh', () => {
  it('round-trips connectivity, deleted slots and attributes', () => {
    const { mesh } = buildMesh(torus(5, 4));
    mesh.vertexAttributes.add('color', 'uint8', 3).data.fill(200);
    mesh.faceAttributes.add('label', 'int32', 1, 'copy').data.fill(3);
    mesh.deleteVertex(mesh.addVertex(9, 9, 9));
    const copy = deserializeMesh(serializeMesh(mesh));
    expect(diffPointers(mesh, copy).total).toBe(0);
    expect(copy.nVertices).toBe(mesh.nVertices);
    expect(copy.isCompact).toBe(false);
    expect(Array.from(copy.positions)).toEqual(Array.from(mesh.positions.subarray(0, 3 * mesh.vertexSlots)));
    expect(copy.vertexAttributes.get('color')!.data[5]).toBe(200);
    expect(copy.faceAttributes.get('label')!.interpolation).toBe('copy');
    expect(validate(copy)).toEqual([]);
  });

  it('copies, so the original mesh stays usable, and lists every buffer for transfer', () => {
    const { mesh } = buildMesh(torus(3, 3));
    const serialized = serializeMesh(mesh);
    const buffers = meshBuffers(serialized);
    expect(buffers).toContain(serialized.heNext.buffer);
    expect(buffers).toContain(serialized.attributes.vertex[0]!.data.buffer);
    expect(new Set(buffers).size).toBe(buffers.length);
    structuredClone(serialized, { transfer: buffers });
    expect(serialized.heNext.byteLength).toBe(0);
    expect(validate(mesh)).toEqual([]);
  });

  it('refuses arrays whose lengths disagree', () => {
    const serialized = serializeMesh(buildMesh(torus(3, 3)).mesh);
    serialized.hePrev = serialized.hePrev.subarray(1);
    expect(() => deserializeMesh(serialized)).toThrow(/hePrev has 35 entries, 36 expected/);
  });
});
