/**
 * Seams: the edges where a file split its vertices. Counted on meshes whose seams are known from
 * how they were made, and on two triangles where one corner value decides.
 */
import { Document } from '@gltf-transform/core';
import { describe, expect, it } from 'vitest';
import { readMeshAsync } from '../src/core/io/index.js';
import { buildMesh, type HalfedgeMesh, seamEdges } from '../src/index.js';
import { addCube, addSphere, glbOf } from './io/gltf-fixtures.js';

async function meshOf(document: Document): Promise<HalfedgeMesh> {
  return buildMesh((await readMeshAsync(await glbOf(document))).soup).mesh;
}

/** Two triangles on the edge 0–2 of the square 0 1 2 3, with a texture coordinate per corner. */
function square(texcoords: number[]): HalfedgeMesh {
  return buildMesh({
    positions: Float64Array.of(0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0),
    faceStarts: Uint32Array.of(0, 3, 6),
    faceIndices: Uint32Array.of(0, 1, 2, 0, 2, 3),
    cornerAttributes: [{ name: 'texcoord', itemSize: 2, data: Float32Array.from(texcoords) }],
  }).mesh;
}

/** The edge between vertices a and b. */
function edgeBetween(mesh: HalfedgeMesh, a: number, b: number): number {
  for (const h of mesh.halfedges()) if (mesh.heVertex[h] === a && mesh.heVertex[mesh.heNext[h]] === b) return h >> 1;
  throw new Error(`no edge v${a}–v${b}`);
}

describe('seamEdges', () => {
  it('finds none on a mesh without corner values', () => {
    const mesh = square([0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1]);
    mesh.halfedgeAttributes.remove('texcoord');
    expect(Array.from(seamEdges(mesh))).toEqual([]);
  });

  it('finds the shared edge exactly when a corner at one of its ends differs across it', () => {
    // corners in face order: (0 1 2) then (0 2 3); v0 and v2 are shared
    const same = [0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1];
    expect(Array.from(seamEdges(square(same)))).toEqual([]);
    for (const corner of [3, 4]) {
      // the second face's corner at v0 (3) or at v2 (4) moves: the shared edge is a seam, no other
      const moved = same.slice();
      moved[2 * corner] += 0.5;
      const mesh = square(moved);
      expect(Array.from(seamEdges(mesh))).toEqual([edgeBetween(mesh, 0, 2)]);
    }
    // a corner at v3, which only one face has, makes no seam
    const lone = same.slice();
    lone[2 * 5] += 0.5;
    expect(Array.from(seamEdges(square(lone)))).toEqual([]);
  });

  it('finds a cube’s 12 edges, where its sides’ normals meet, and not the diagonals inside a side', async () => {
    const document = new Document();
    addCube(document, 'Box');
    const mesh = await meshOf(document);
    const seams = Array.from(seamEdges(mesh));
    expect(seams).toHaveLength(12);
    for (const e of seams) {
      // a cube edge's ends differ in one coordinate; a diagonal's in two
      const [p, q] = [mesh.position(mesh.heVertex[2 * e]), mesh.position(mesh.heVertex[2 * e + 1])];
      expect([0, 1, 2].filter((i) => p[i] !== q[i])).toHaveLength(1);
    }
  });

  it('finds a UV sphere’s seam meridian and every edge at its poles (each pole is split per slice)', async () => {
    const [w, h] = [16, 8];
    const document = new Document();
    addSphere(document, 'Globe', w, h);
    const mesh = await meshOf(document);
    // w edges at each pole, and the seam meridian's h − 2 edges between them
    expect(seamEdges(mesh)).toHaveLength(2 * w + (h - 2));
  });
});
