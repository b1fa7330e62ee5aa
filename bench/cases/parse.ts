/**
 * Parsing mesh files into a polygon soup, beside three.js's PLYLoader parsing the same PLY bytes.
 *
 * The files are a closed latitude–longitude sphere written by our own writers, with coordinates
 * as such files usually hold them: float32 properties in PLY, about six decimals in OFF and OBJ
 * (what exporters printing "%f" or "%g" write).
 */
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import type { BenchCase } from '../harness.js';
import type { PolygonSoup } from '../../src/index.js';
import { type WriteFormat, writeSoup } from '../../src/core/io/index.js';
import { readMesh } from '../library.js';
import { sphereFaceCount, sphereWithFaces } from './sphere.js';

type Positions = PolygonSoup['positions'];

const formats: Array<{ name: string; format: WriteFormat; positions: (p: Positions) => Positions }> = [
  { name: 'parse-ply-binary', format: 'ply-binary', positions: (p) => Float32Array.from(p) },
  { name: 'parse-ply-ascii', format: 'ply', positions: (p) => Float32Array.from(p) },
  { name: 'parse-off-ascii', format: 'off', positions: sixDecimals },
  { name: 'parse-obj', format: 'obj', positions: sixDecimals },
];

function sixDecimals(positions: Positions): Float64Array {
  return Float64Array.from(positions, (x) => Math.round(x * 1e6) / 1e6);
}

export function parseCases(sizes: number[]): BenchCase[] {
  return sizes.flatMap((size) => {
    const faces = sphereFaceCount(size);
    return formats.map(({ name, format, positions }): BenchCase => {
      let bytes: Uint8Array = new Uint8Array(0);
      let buffer = new ArrayBuffer(0);
      const bench: BenchCase = {
        case: name,
        size: faces,
        repeat: size >= 1e6 ? 5 : 9,
        prepare() {
          const sphere = sphereWithFaces(size);
          bytes = writeSoup({ ...sphere, positions: positions(sphere.positions) }, format);
          buffer = bytes.slice().buffer;
        },
        run: () => readMesh(bytes),
      };
      if (format.startsWith('ply')) bench.peer = { name: 'three PLYLoader', run: () => new PLYLoader().parse(buffer) };
      return bench;
    });
  });
}
