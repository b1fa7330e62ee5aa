/**
 * glTF files made as exporters make them, with glTF-Transform: vertices split along every seam of
 * normals and texture coordinates (a cube's 24 vertices, a UV sphere's seam column and poles),
 * several nodes with transforms, strips, points, quantized, Draco- and meshopt-compressed.
 */
import { type Document, Logger, type Node, NodeIO, Primitive } from '@gltf-transform/core';
import { EXTMeshoptCompression, KHRDracoMeshCompression, KHRMeshQuantization } from '@gltf-transform/extensions';
import { draco, meshopt, quantize } from '@gltf-transform/functions';
import draco3d from 'draco3dgltf';
import { MeshoptEncoder } from 'meshoptimizer';

/** A cube as exporters write it: 4 vertices per side (its own normal and UVs), 24 in all, 12 triangles. */
export function addCube(document: Document, name: string): Node {
  const positions: number[] = [];
  const normals: number[] = [];
  const uvs: number[] = [];
  const indices: number[] = [];
  const axes = [
    [0, 1, 2],
    [1, 2, 0],
    [2, 0, 1],
  ];
  for (const [a, b, c] of axes) {
    for (const sign of [1, -1]) {
      const base = positions.length / 3;
      for (const [u, v] of [
        [-1, -1],
        [1, -1],
        [1, 1],
        [-1, 1],
      ]) {
        const p = [0, 0, 0];
        p[a] = sign;
        p[b] = u * sign;
        p[c] = v;
        positions.push(...p);
        const n = [0, 0, 0];
        n[a] = sign;
        normals.push(...n);
        uvs.push((u + 1) / 2, (v + 1) / 2);
      }
      indices.push(base, base + 1, base + 2, base, base + 2, base + 3);
    }
  }
  return addMesh(document, name, positions, indices, { normals, uvs });
}

/**
 * A UV sphere as three.js's SphereGeometry makes it: (w + 1) × (h + 1) vertices, the seam column
 * repeated and each pole repeated per slice; triangles at the poles only one per quad.
 * Welded: w (h − 1) + 2 vertices and 2 w (h − 1) triangles.
 */
export function addSphere(document: Document, name: string, w: number, h: number): Node {
  const positions: number[] = [];
  const normals: number[] = [];
  const uvs: number[] = [];
  for (let iy = 0; iy <= h; iy++) {
    for (let ix = 0; ix <= w; ix++) {
      const theta = (iy / h) * Math.PI;
      // the seam column's x and z come from the same angle written once, so the positions match exactly
      const phi = ix === w ? 0 : (ix / w) * 2 * Math.PI;
      const p = iy === 0 ? [0, 1, 0] : iy === h ? [0, -1, 0] : [-Math.cos(phi) * Math.sin(theta), Math.cos(theta), Math.sin(phi) * Math.sin(theta)];
      positions.push(...p);
      normals.push(...p);
      uvs.push(ix / w, 1 - iy / h);
    }
  }
  const at = (ix: number, iy: number) => iy * (w + 1) + ix;
  const indices: number[] = [];
  for (let iy = 0; iy < h; iy++) {
    for (let ix = 0; ix < w; ix++) {
      const [a, b, c, d] = [at(ix + 1, iy), at(ix, iy), at(ix, iy + 1), at(ix + 1, iy + 1)];
      if (iy !== 0) indices.push(a, b, d);
      if (iy !== h - 1) indices.push(b, c, d);
    }
  }
  return addMesh(document, name, positions, indices, { normals, uvs });
}

/** A ribbon of n quads as one triangle strip: 2n + 2 vertices, 2n triangles. */
export function addRibbon(document: Document, name: string, n: number): Node {
  const positions: number[] = [];
  for (let i = 0; i <= n; i++) positions.push(i, 0, 0, i, 1, 0);
  return addMesh(document, name, positions, Array.from({ length: 2 * n + 2 }, (_, i) => i), {}, Primitive.Mode.TRIANGLE_STRIP);
}

export function addMesh(
  document: Document,
  name: string,
  positions: number[],
  indices: number[],
  { normals, uvs }: { normals?: number[]; uvs?: number[] } = {},
  mode: number = Primitive.Mode.TRIANGLES,
): Node {
  const buffer = document.getRoot().listBuffers()[0] ?? document.createBuffer();
  const accessor = (type: 'SCALAR' | 'VEC2' | 'VEC3', array: Float32Array | Uint32Array) => document.createAccessor().setType(type).setArray(array).setBuffer(buffer);
  const primitive = document.createPrimitive().setMode(mode as 4).setAttribute('POSITION', accessor('VEC3', Float32Array.from(positions))).setIndices(accessor('SCALAR', Uint32Array.from(indices)));
  if (normals) primitive.setAttribute('NORMAL', accessor('VEC3', Float32Array.from(normals)));
  if (uvs) primitive.setAttribute('TEXCOORD_0', accessor('VEC2', Float32Array.from(uvs)));
  const node = document.createNode(name).setMesh(document.createMesh(name).addPrimitive(primitive));
  const scene = document.getRoot().getDefaultScene() ?? document.getRoot().setDefaultScene(document.createScene('scene')).getDefaultScene()!;
  scene.addChild(node);
  return node;
}

export async function glbOf(document: Document, compression: 'none' | 'quantized' | 'draco' | 'meshopt' = 'none'): Promise<Uint8Array> {
  const io = new NodeIO().registerExtensions([KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization]);
  document.setLogger(new Logger(Logger.Verbosity.SILENT));
  if (compression === 'quantized') await document.transform(quantize());
  if (compression === 'draco') {
    io.registerDependencies({ 'draco3d.encoder': await draco3d.createEncoderModule() });
    await document.transform(draco({ method: 'edgebreaker' }));
  }
  if (compression === 'meshopt') {
    await MeshoptEncoder.ready;
    io.registerDependencies({ 'meshopt.encoder': MeshoptEncoder });
    await document.transform(meshopt({ encoder: MeshoptEncoder }));
  }
  return io.writeBinary(document);
}
