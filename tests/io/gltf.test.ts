// glTF in and out: exporter-made files (seams split, several nodes, strips, points, quantized,
// Draco, meshopt) welded to the real surface with exact counts; round trips .glb → mesh → .glb;
// broken files refused with the accessor or buffer named.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Document, NodeIO, Primitive } from '@gltf-transform/core';
import fc from 'fast-check';
import { afterAll, describe, expect, it } from 'vitest';
import { convert } from '../../src/cli/commands/convert.js';
import { loadMesh, takeReadSettings } from '../../src/cli/io.js';
import { buildMesh, type HalfedgeMesh, meshStats, ParseError, validate } from '../../src/index.js';
import { readMeshAsync, writeMeshAsync } from '../../src/core/io/index.js';
import { weldPositions } from '../../src/core/io/weld.js';
import { addCube, addMesh, addRibbon, addSphere, glbOf } from './gltf-fixtures.js';

async function open(bytes: Uint8Array, resources?: Map<string, Uint8Array<ArrayBuffer>>) {
  const file = await readMeshAsync(bytes, { resources });
  const { mesh, report } = buildMesh(file.soup);
  expect(validate(mesh)).toEqual([]);
  return { file, mesh, report };
}

const counts = (mesh: HalfedgeMesh) => ({ V: mesh.nVertices, E: mesh.nEdges, F: mesh.nFaces, boundaryLoops: boundaryLoops(mesh) });

/** A .glb of the JSON text `json` (padded with spaces to whole words, as the format asks) and the binary chunk `bin`. */
function glbFrom(json: Uint8Array, bin: Uint8Array): Uint8Array {
  const jsonLength = Math.ceil(json.length / 4) * 4;
  const binLength = Math.ceil(bin.length / 4) * 4;
  const bytes = new Uint8Array(20 + jsonLength + 8 + binLength);
  const view = new DataView(bytes.buffer);
  view.setUint32(0, 0x46546c67, true); // 'glTF'
  view.setUint32(4, 2, true);
  view.setUint32(8, bytes.length, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true); // 'JSON'
  bytes.fill(0x20, 20, 20 + jsonLength);
  bytes.set(json, 20);
  view.setUint32(20 + jsonLength, binLength, true);
  view.setUint32(24 + jsonLength, 0x004e4942, true); // 'BIN'
  bytes.set(bin, 28 + jsonLength);
  return bytes;
}

function boundaryLoops(mesh: HalfedgeMesh): number {
  const seen = new Set<number>();
  let loops = 0;
  for (const h of mesh.halfedges()) {
    if (mesh.heFace[h] !== -1 || seen.has(h)) continue;
    loops++;
    let g = h;
    do {
      seen.add(g);
      g = mesh.heNext[g];
    } while (g !== h);
  }
  return loops;
}

function sphereDocument(): Document {
  const document = new Document();
  addSphere(document, 'Globe', 16, 8);
  return document;
}

// 16 × 8 sphere: 16·7 + 2 = 114 vertices, 2·16·7 = 224 triangles, 336 edges, closed
const sphereCounts = { V: 114, E: 336, F: 224, boundaryLoops: 0 };

describe('reading glTF', () => {
  it('welds a cube split into 24 vertices back into 8, keeping each corner its normal and UV', async () => {
    const document = new Document();
    addCube(document, 'Box');
    const { file, mesh } = await open(await glbOf(document));
    expect(file.format).toBe('gltf');
    expect(file.counts).toEqual({ vertices: 24, faces: 12 });
    expect(counts(mesh)).toEqual({ V: 8, E: 18, F: 12, boundaryLoops: 0 });
    expect(file.notes[0]).toMatch(/^welded 24 glTF vertices into 8 \(16 joined at equal positions/);
    // every corner's normal is its side's: the three corners at a vertex carry three normals
    const normal = mesh.halfedgeAttributes.get('normal')!;
    for (const h of mesh.halfedges()) {
      if (mesh.heFace[h] === -1) continue;
      const n = Array.from(normal.data.subarray(3 * h, 3 * h + 3));
      const p = mesh.position(mesh.heVertex[h]);
      // the side's normal points along one axis, where the corner's coordinate is ±1 with that sign
      const axis = n.findIndex((x) => x !== 0);
      expect(Math.abs(n[axis])).toBe(1);
      expect(p[axis]).toBe(n[axis]);
    }
  });

  it('closes a UV sphere along its seam and at its poles', async () => {
    const { file, mesh } = await open(await glbOf(sphereDocument()));
    expect(file.counts.vertices).toBe(17 * 9);
    expect(counts(mesh)).toEqual(sphereCounts);
    expect(mesh.halfedgeAttributes.get('texcoord')).toBeDefined();
  });

  for (const compression of ['quantized', 'draco', 'meshopt'] as const) {
    it(`reads a ${compression} sphere to the same counts`, async () => {
      const bytes = await glbOf(sphereDocument(), compression);
      const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + new DataView(bytes.buffer, bytes.byteOffset).getUint32(12, true))));
      const extension = { quantized: 'KHR_mesh_quantization', draco: 'KHR_draco_mesh_compression', meshopt: 'EXT_meshopt_compression' }[compression];
      expect(json.extensionsUsed).toContain(extension);
      const { mesh } = await open(bytes);
      expect(counts(mesh)).toEqual(sphereCounts);
      // positions come back on the unit sphere, up to the quantization
      for (const v of mesh.vertices()) expect(Math.hypot(...mesh.position(v))).toBeCloseTo(1, 2);
    });
  }

  it('places several nodes with their transforms, each a component named in the notes', async () => {
    const document = new Document();
    addCube(document, 'Left').setTranslation([-3, 0, 0]);
    // mirrored: the triangles are turned so the faces still face out
    addCube(document, 'Right').setTranslation([3, 0, 0]).setScale([-1, 2, 1]);
    const { file, mesh } = await open(await glbOf(document));
    expect(counts(mesh)).toEqual({ V: 16, E: 36, F: 24, boundaryLoops: 0 });
    expect(meshStats(mesh).components).toBe(2);
    expect(file.notes).toContain('Left: 8 vertices, 12 triangles (faces 0…11)');
    expect(file.notes).toContain('Right: 8 vertices, 12 triangles (faces 12…23)');
    const xs = [...mesh.vertices()].map((v) => mesh.position(v)[0]).sort((a, b) => a - b);
    expect([xs[0], xs.at(-1)]).toEqual([-4, 4]);
    const ys = [...mesh.vertices()].map((v) => mesh.position(v)[1]);
    expect(Math.max(...ys)).toBe(2);
    // every face faces away from its cube's centre
    for (const f of mesh.faces()) {
      const h = mesh.fHalfedge[f];
      const [a, b, c] = [mesh.heVertex[h], mesh.heVertex[mesh.heNext[h]], mesh.heVertex[mesh.heNext[mesh.heNext[h]]]].map((v) => mesh.position(v));
      const n = cross(sub(b, a), sub(c, a));
      const centre = a[0] < 0 ? [-3, 0, 0] : [3, 0, 0];
      expect(dot(n, sub(a, centre))).toBeGreaterThan(0);
    }
  });

  it('decodes triangle strips and skips points and lines, saying so', async () => {
    const document = new Document();
    addRibbon(document, 'Ribbon', 5);
    addMesh(document, 'Dots', [0, 0, 5, 1, 0, 5], [0, 1], {}, Primitive.Mode.POINTS);
    addMesh(document, 'Wire', [0, 0, 6, 1, 0, 6], [0, 1], {}, Primitive.Mode.LINES);
    const { file, mesh } = await open(await glbOf(document));
    expect(counts(mesh)).toEqual({ V: 12, E: 21, F: 10, boundaryLoops: 1 });
    expect(file.notes).toContain('Dots: a primitive of points was skipped (only triangles make faces)');
    expect(file.notes).toContain('Wire: a primitive of lines was skipped (only triangles make faces)');
  });

  it('reads a .gltf with its .bin given beside it, and one with the data inside', async () => {
    const io = new NodeIO();
    const { json, resources } = await io.writeJSON(sphereDocument(), { basename: 'globe' });
    const text = new TextEncoder().encode(JSON.stringify(json));
    const files = new Map(Object.entries(resources).map(([name, data]) => [name, data as Uint8Array<ArrayBuffer>]));
    expect([...files.keys()]).toEqual(['globe.bin']);
    expect(counts((await open(text, files)).mesh)).toEqual(sphereCounts);
    const inline = { ...json, buffers: json.buffers!.map((b) => ({ ...b, uri: `data:application/octet-stream;base64,${Buffer.from(files.get('globe.bin')!).toString('base64')}` })) };
    expect(counts((await open(new TextEncoder().encode(JSON.stringify(inline)))).mesh)).toEqual(sphereCounts);
    await expect(readMeshAsync(text)).rejects.toThrow(/buffer 0 is the file 'globe\.bin', which was not given/);
  });

  it('refuses a position that is NaN, or that a node takes to infinity, naming where; drops a NaN normal or texture coordinate with a note', async () => {
    const square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];
    const glbOfSquare = (positions: number[], attributes: { normals?: number[]; uvs?: number[] } = {}, scale = 1) => {
      const document = new Document();
      addMesh(document, 'Square', positions, [0, 1, 2, 0, 2, 3], attributes).setScale([scale, 1, 1]);
      return glbOf(document);
    };
    const refusal = async (bytes: Uint8Array) => ((await readMeshAsync(bytes).catch((error: unknown) => error)) as ParseError).message;
    const nan = [...square];
    nan[4] = Number.NaN;
    expect(await refusal(await glbOfSquare(nan))).toMatch(
      /^glTF: byte \d+ \(meshes\[0\]\.primitives\[0\]\.attributes\.POSITION\): Square: vertex 1's position \(item 1\) is NaN, not a number$/,
    );
    expect(await refusal(await glbOfSquare(square.map((x) => x * 1e30), {}, 1e300))).toMatch(
      /^glTF: byte \d+ \(nodes\[0\]\): Square: the node's transform takes vertex 1 \(1\.0\d*e\+30, 0, 0\) of primitive 0 beyond the range of a double$/,
    );
    const normals = [0, 0, 1, Number.NaN, Number.NaN, Number.NaN, 0, 0, 1, 0, 0, 1];
    const uvs = [0, 0, 1, 0, 1, 1, 0, Infinity];
    const { file, mesh } = await open(await glbOfSquare(square, { normals, uvs }));
    expect(file.notes).toEqual(
      expect.arrayContaining([
        expect.stringMatching(/^dropped 1 glTF vertex normal that was NaN or infinite, set to zero; the first is vertex 1 of Square \(primitive 0\), at byte \d+ \(meshes\[0\]\.primitives\[0\]\.attributes\.NORMAL\)$/),
        expect.stringMatching(/^dropped 1 glTF vertex texture coordinate that was NaN or infinite, set to zero; the first is vertex 3 of Square \(primitive 0\)/),
      ]),
    );
    // the corners at (1, 0, 0) have no normal; the others keep theirs
    const normal = mesh.halfedgeAttributes.get('normal')!.data;
    for (const h of mesh.halfedges()) {
      if (mesh.heFace[h] === -1) continue;
      const expected = mesh.position(mesh.heVertex[h]).join() === '1,0,0' ? [0, 0, 0] : [0, 0, 1];
      expect(Array.from(normal.subarray(3 * h, 3 * h + 3))).toEqual(expected);
    }
    expect(counts(mesh)).toEqual({ V: 4, E: 5, F: 2, boundaryLoops: 1 });
  });

  it('refuses a broken file naming the place: the byte of a .glb, the line, column and JSON path of a .gltf', async () => {
    const glb = await glbOf(sphereDocument());
    const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
    const jsonLength = view.getUint32(12, true);
    const json = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength)));
    const withJson = (edit: (json: Record<string, never>) => void) => {
      const copy = structuredClone(json);
      edit(copy);
      return new TextEncoder().encode(JSON.stringify(copy));
    };
    const refusal = async (bytes: Uint8Array, files?: Map<string, Uint8Array<ArrayBuffer>>) => {
      const error = await readMeshAsync(bytes, { resources: files }).then(
        () => null,
        (e: unknown) => e,
      );
      expect(error).toBeInstanceOf(ParseError);
      return (error as ParseError).message;
    };
    // cut short: the header says more than there is
    expect(await refusal(glb.subarray(0, glb.length - 100))).toMatch(/^glTF: byte 8: the header says the file has \d+ bytes; it has \d+/);
    // broken JSON inside a GLB
    const broken = glb.slice();
    broken[20] = 0x5d; // ']' where the JSON's '{' was
    expect(await refusal(broken)).toMatch(/^glTF: byte \d+: broken JSON/);
    // a buffer shorter than its accessors, an index out of range
    const bin = glb.slice(20 + jsonLength + 8);
    const files = new Map([['b.bin', bin.slice(0, 100)]]);
    const short = withJson((j: Record<string, any>) => {
      j.buffers[0].uri = 'b.bin';
      j.buffers[0].byteLength = 100;
    });
    expect(await refusal(short, files)).toMatch(/^glTF: line 1, column \d+ \(bufferViews\[\d+\]\): bufferView \d+ needs bytes \d+…\d+ of buffer 0, which has 100$/);
    const bomb = withJson((j: Record<string, any>) => {
      j.buffers[0].uri = 'b.bin';
      j.accessors[0].count = 2 ** 40;
    });
    expect(await refusal(bomb, new Map([['b.bin', bin]]))).toMatch(/^glTF: line 1, column \d+ \(accessors\[0\]\.count\): accessor 0 claims 1099511627776 elements/);
    const longAccessor = withJson((j: Record<string, any>) => {
      j.buffers[0].uri = 'b.bin';
      j.accessors[0].count += 1;
    });
    expect(await refusal(longAccessor, new Map([['b.bin', bin]]))).toMatch(/^glTF: line 1, column \d+ \(accessors\[0\]\): accessor 0 needs \d+ bytes of bufferView \d+, which has \d+$/);
    // an index past the vertices: the indices are the last accessor the writer made; one of them is set too high
    const indices = json.meshes[0].primitives[0].indices;
    const indexView = json.bufferViews[json.accessors[indices].bufferView];
    const badIndex = bin.slice();
    new DataView(badIndex.buffer).setUint32((indexView.byteOffset ?? 0) + 4 * 7, 5000, true);
    const outOfRange = withJson((j: Record<string, any>) => {
      j.buffers[0].uri = 'b.bin';
    });
    // (the column is the index's accessor number, after `"indices":` in the one line of JSON)
    const column = new TextDecoder().decode(outOfRange).indexOf('"indices":') + '"indices":'.length + 1;
    expect(await refusal(outOfRange, new Map([['b.bin', badIndex]]))).toBe(
      `glTF: line 1, column ${column} (meshes[0].primitives[0].indices): Globe: index 7 of accessor ${indices} is 5000, but the primitive has 153 vertices`,
    );
    // the same in a .glb: the byte offset in the file, past the 20 bytes before the JSON
    const glbJson = withJson(() => {});
    const offset = 20 + new TextDecoder().decode(glbJson).indexOf('"indices":') + '"indices":'.length;
    expect(await refusal(glbFrom(glbJson, badIndex))).toBe(
      `glTF: byte ${offset} (meshes[0].primitives[0].indices): Globe: index 7 of accessor ${indices} is 5000, but the primitive has 153 vertices`,
    );
    expect(await refusal(new TextEncoder().encode('{"asset": {"version": "1.0"}}'))).toMatch(/only glTF 2\.0 is read/);
  });
});

describe('writing glTF', () => {
  it('round-trips .glb → mesh → .glb with the same V, E, F and corner attributes', async () => {
    const document = new Document();
    addCube(document, 'Box');
    addSphere(document, 'Globe', 12, 6).setTranslation([4, 0, 0]);
    const first = await open(await glbOf(document));
    const written = await writeMeshAsync(first.mesh, 'glb');
    const second = await open(written);
    expect(counts(second.mesh)).toEqual(counts(first.mesh));
    // the same corners in the same order carry the same values (the writer keeps the face order)
    for (const name of ['normal', 'texcoord']) {
      const a = first.mesh.halfedgeAttributes.get(name)!;
      const b = second.mesh.halfedgeAttributes.get(name)!;
      expect(cornerValues(second.mesh, b.data, b.itemSize)).toEqual(cornerValues(first.mesh, a.data, a.itemSize));
    }
    // split again where the corners differ: the cube's 24 vertices and the sphere's seam come back
    // (less the copy at each pole that no triangle of the sphere uses)
    const again = await readMeshAsync(written);
    expect(again.counts.vertices).toBe(first.file.counts.vertices - 2);
  });

  it('writes a mesh of polygons as triangles', async () => {
    const { mesh } = buildMesh({ positions: Float64Array.of(0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 1, 0, 0, 2, 0), faceStarts: Uint32Array.of(0, 5), faceIndices: Uint32Array.of(0, 1, 2, 3, 4) });
    const { mesh: back } = await open(await writeMeshAsync(mesh, 'glb'));
    expect(counts(back)).toEqual({ V: 5, E: 7, F: 3, boundaryLoops: 1 });
  });
});

describe('the command line', () => {
  const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-gltf-'));
  afterAll(() => rmSync(dir, { recursive: true, force: true }));

  it('converts a .gltf, its buffer read from beside it, to .glb and back to the same counts', async () => {
    const { json, resources } = await new NodeIO().writeJSON(sphereDocument(), { basename: 'globe' });
    writeFileSync(join(dir, 'globe.gltf'), JSON.stringify(json));
    writeFileSync(join(dir, 'globe.bin'), resources['globe.bin']!);
    expect(await convert.run([join(dir, 'globe.gltf'), join(dir, 'globe.glb')])).toBe(0);
    expect(counts((await loadMesh(join(dir, 'globe.glb'))).mesh)).toEqual(sphereCounts);
  });

  it('reads no buffer from outside the folder of the .gltf, and says which buffer is missing', async () => {
    mkdirSync(join(dir, 'inner'));
    writeFileSync(join(dir, 'secret.bin'), new Uint8Array(16));
    writeFileSync(join(dir, 'inner', 'evil.gltf'), JSON.stringify({ asset: { version: '2.0' }, buffers: [{ uri: '%2e%2e/secret.bin', byteLength: 16 }] }));
    // a UsageError: the command line prints it on one line and exits with status 2
    await expect(convert.run([join(dir, 'inner', 'evil.gltf'), join(dir, 'out.glb')])).rejects.toThrow(
      /evil\.gltf: glTF: line 1, column \d+ \(buffers\[0\]\.uri\): buffer 0 is the file '%2e%2e\/secret\.bin', which was not given/,
    );
  });
});

describe('--weld-tolerance', () => {
  it('is taken from anywhere in the arguments, with its value apart or after =', () => {
    expect(takeReadSettings(['in.glb', '--weld-tolerance', '0.01', 'out.glb', '--format', 'glb'])).toEqual({
      settings: { weldTolerance: 0.01 },
      rest: ['in.glb', 'out.glb', '--format', 'glb'],
    });
    expect(takeReadSettings(['--weld-tolerance=1e-6', 'in.stl'])).toEqual({ settings: { weldTolerance: 1e-6 }, rest: ['in.stl'] });
    expect(takeReadSettings(['in.off'])).toEqual({ settings: {}, rest: ['in.off'] });
  });

  it('refuses what is not a distance of 0 or more, quoting it', () => {
    expect(() => takeReadSettings(['--weld-tolerance', '-1'])).toThrow("--weld-tolerance takes a distance of 0 or more, not '-1'");
    expect(() => takeReadSettings(['--weld-tolerance=abc'])).toThrow("not 'abc'");
    expect(() => takeReadSettings(['--weld-tolerance=Infinity'])).toThrow("not 'Infinity'");
    expect(() => takeReadSettings(['in.glb', '--weld-tolerance'])).toThrow('not nothing');
  });

  it('closes a cube whose sides were written a hair apart', async () => {
    const document = new Document();
    addCube(document, 'Box');
    const position = document.getRoot().listMeshes()[0]!.listPrimitives()[0]!.getAttribute('POSITION')!;
    // every other side's four corners moved by 1e-5: at equal positions only, the sides come apart
    const moved = Float32Array.from(position.getArray()! as Float32Array, (x, i) => (Math.floor(i / 12) % 2 ? x + 1e-5 : x));
    position.setArray(moved);
    const dir = mkdtempSync(join(tmpdir(), 'halfedge-lab-weld-'));
    try {
      writeFileSync(join(dir, 'box.glb'), await glbOf(document));
      // at equal positions only: a corner with moved and unmoved sides around it (6 of the 8) stays two vertices
      expect(counts((await loadMesh(join(dir, 'box.glb'))).mesh).V).toBe(14);
      const { mesh } = await loadMesh(join(dir, 'box.glb'), { weldTolerance: 1e-4 });
      expect(validate(mesh)).toEqual([]);
      expect(counts(mesh)).toEqual({ V: 8, E: 18, F: 12, boundaryLoops: 0 });
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});

describe('welding', () => {
  it('joins exactly equal positions (and -0 with 0), or those within a tolerance', () => {
    expect(Array.from(weldPositions([0, 0, 0, 1, 0, 0, -0, 0, 0, 1, 0, 0]).remap)).toEqual([0, 1, 0, 1]);
    const near = [0, 0, 0, 1e-7, 0, 0, 1, 0, 0];
    expect(Array.from(weldPositions(near).remap)).toEqual([0, 1, 2]);
    expect(Array.from(weldPositions(near, 1e-6).remap)).toEqual([0, 0, 1]);
  });

  it('within a tolerance, joins each vertex to one within it, and starts a new one only when none is', () => {
    fc.assert(
      fc.property(
        fc.array(fc.tuple(fc.integer({ min: -20, max: 20 }), fc.integer({ min: -20, max: 20 }), fc.integer({ min: -20, max: 20 })), { maxLength: 60 }),
        fc.constantFrom(0.5, 1, 1.5, 3),
        (points, tolerance) => {
          const positions = points.flat().map((x) => x / 4);
          const { remap, positions: welded } = weldPositions(positions, tolerance);
          const distance = (i: number, w: number) => Math.hypot(...[0, 1, 2].map((k) => positions[3 * i + k] - welded[3 * w + k]));
          let made = 0;
          remap.forEach((w, i) => {
            expect(distance(i, w)).toBeLessThanOrEqual(tolerance);
            if (w === made) {
              // a new vertex: at this point's position, and no earlier vertex was within reach
              for (let earlier = 0; earlier < made; earlier++) expect(distance(i, earlier)).toBeGreaterThan(tolerance);
              made++;
            } else expect(w).toBeLessThan(made);
          });
          expect(welded.length).toBe(3 * made);
        },
      ),
      { seed: 19, numRuns: 300 },
    );
  });

  it('stays linear on a tolerance far below the coordinates’ precision, and on NaN positions', () => {
    const count = 100_000;
    const spread = Float64Array.from({ length: 3 * count }, (_, i) => 1e12 + i);
    // cells of 1e-300 would all be one: widened, each point keeps its own
    expect(weldPositions(spread, 1e-300).positions.length).toBe(3 * count);
    const nan = new Float64Array(3 * count).fill(Number.NaN);
    expect(weldPositions(nan, 1).positions.length).toBe(3 * count);
  });
});

function cornerValues(mesh: HalfedgeMesh, data: ArrayLike<number>, size: number): number[][] {
  const values: number[][] = [];
  for (const f of mesh.faces()) {
    let h = mesh.fHalfedge[f];
    for (let i = 0; i < 3; i++, h = mesh.heNext[h]) values.push(Array.from({ length: size }, (_, k) => data[size * h + k]));
  }
  return values;
}

const sub = (a: number[], b: number[]) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: number[], b: number[]) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
