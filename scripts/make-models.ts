/**
 * Writes the sample models of the app into public/models/ (and their list, index.json), all made
 * by the project itself from `src/core/shapes.ts`, except the Stanford bunny, which comes from the
 * `bunny` package (public domain). Run with `npm run models`; the output is deterministic, and a
 * test checks that the committed files match it.
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import bunny from 'bunny';
import {
  annulus,
  bowTie,
  cube,
  disk,
  doubleTorus,
  grid,
  inconsistentPair,
  mergeSoups,
  moebiusStrip,
  type PolygonSoup,
  soupFromArrays,
  strip,
  tetrahedron,
  threeFacesOnAnEdge,
  torus,
  uvSphere,
  type WriteFormat,
  writeSoup,
} from '../src/index.js';

export interface SampleModel {
  file: string;
  title: string;
  make: () => PolygonSoup;
  format: WriteFormat;
}

/** Moves a soup by (dx, dy, dz) (to set pieces side by side). */
function moved(soup: PolygonSoup, dx: number, dy: number, dz: number): PolygonSoup {
  const positions = Float64Array.from(soup.positions);
  for (let i = 0; i < positions.length; i += 3) {
    positions[i] += dx;
    positions[i + 1] += dy;
    positions[i + 2] += dz;
  }
  return { ...soup, positions };
}

/** A strip of triangles with every third one listed clockwise. */
function inconsistentStrip(): PolygonSoup {
  const soup = strip(4);
  for (let f = 0; 3 * f < soup.faceIndices.length; f += 3) soup.faceIndices.subarray(3 * f + 1, 3 * f + 3).reverse();
  return soup;
}

export const sampleModels: SampleModel[] = [
  { file: 'disk.off', title: 'Open disk (2D)', make: () => disk(2), format: 'off' },
  { file: 'tetrahedron.off', title: 'Tetrahedron', make: tetrahedron, format: 'off' },
  { file: 'cube.off', title: 'Cube of quads', make: cube, format: 'off' },
  { file: 'grid.off', title: 'Quad grid (2D)', make: () => grid(4, 3, true), format: 'off' },
  { file: 'annulus.off', title: 'Annulus (two boundary loops)', make: () => annulus(10), format: 'off' },
  { file: 'torus.off', title: 'Torus (genus 1)', make: () => torus(16, 8), format: 'off' },
  { file: 'double-torus.off', title: 'Double torus (genus 2)', make: doubleTorus, format: 'off' },
  { file: 'sphere.ply', title: 'Sphere (binary PLY)', make: () => uvSphere(10, 16), format: 'ply-binary' },
  { file: 'moebius.obj', title: 'Möbius strip (non-orientable)', make: () => moebiusStrip(16), format: 'obj' },
  {
    file: 'non-manifold.obj',
    title: 'Non-manifold: pinched vertex and a three-face edge',
    make: () => mergeSoups([bowTie(), moved(threeFacesOnAnEdge(), 0, 2, 0)]),
    format: 'obj',
  },
  {
    file: 'inconsistent.off',
    title: 'Inconsistently oriented faces',
    make: () => mergeSoups([inconsistentStrip(), moved(inconsistentPair(), 0, 2, 0)]),
    format: 'off',
  },
  { file: 'bunny.ply', title: 'Stanford bunny (low resolution)', make: () => soupFromArrays(bunny.positions.flat(), bunny.cells), format: 'ply' },
];

export function modelBytes(model: SampleModel): Uint8Array {
  return writeSoup(model.make(), model.format);
}

export function modelIndex(): string {
  return JSON.stringify(sampleModels.map(({ file, title }) => ({ file, title })), null, 2) + '\n';
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const folder = join(import.meta.dirname, '../public/models');
  mkdirSync(folder, { recursive: true });
  for (const model of sampleModels) writeFileSync(join(folder, model.file), modelBytes(model));
  writeFileSync(join(folder, 'index.json'), modelIndex());
  console.log(`wrote ${sampleModels.length} models to ${folder}`);
}
