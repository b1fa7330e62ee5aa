/** What the Export panel says a glTF export makes of a mesh's polygons (glTF holds only triangles). */
import { expect, it } from 'vitest';
import { gltfTriangulation } from '../../src/ui/panels/export.js';

it('counts each face of n sides as n − 2 triangles, naming quads as quads', () => {
  expect(gltfTriangulation({ 4: 128 })).toBe('glTF holds only triangles: the 128 quads become 256 triangles. The other formats keep the faces as they are.');
  expect(gltfTriangulation({ 3: 10, 4: 1 })).toMatch(/: the quad becomes 2 triangles\./);
  expect(gltfTriangulation({ 3: 4, 4: 2, 6: 1 })).toMatch(/: the 3 polygons become 8 triangles\./);
});

it('says nothing of a mesh of triangles, or of none', () => {
  expect(gltfTriangulation({ 3: 20 })).toBeNull();
  expect(gltfTriangulation({})).toBeNull();
});
