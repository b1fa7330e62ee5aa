/**
 * The glTF reader fuzzer: `.glb` files the library writes (a cube and a strip, with normals and
 * texture coordinates per corner) and the same as `.gltf` JSON with the buffer inside, mutated as
 * the other readers' files are (`readers.ts`). Each must raise a `ParseError` that says where (a
 * byte offset in a `.glb`, a line and column and JSON path in a `.gltf`), or read into a mesh
 * that is valid, saves and reads back the same (`reload.ts`), and writes as `.glb` and reads back
 * with the same counts. Asynchronous, as the glTF reader is.
 */
import { buildMesh } from '../src/core/build.js';
import { ParseError } from '../src/core/errors.js';
import { readMeshAsync } from '../src/core/io/read.js';
import { writeMeshAsync } from '../src/core/io/write.js';
import type { HalfedgeMesh } from '../src/core/mesh.js';
import { cube, strip } from '../src/core/shapes.js';
import { validate } from '../src/core/validate.js';
import { type CheckOutcome, mutatedSample, refusal, type Sample } from './readers.js';
import { reloadDifference } from './reload.js';
import type { CaseOutcome, FuzzTarget } from './target.js';

/** A `.glb` and a `.gltf` (its buffer a data URI) of each of two small meshes with corner attributes. */
export async function gltfSamples(): Promise<Sample[]> {
  const samples: Sample[] = [];
  for (const [name, soup] of [
    ['cube', cube()],
    ['strip', strip(3)],
  ] as const) {
    const { mesh } = buildMesh(soup);
    const texcoord = mesh.halfedgeAttributes.add('texcoord', 'float32', 2).data;
    const normal = mesh.halfedgeAttributes.add('normal', 'float32', 3).data;
    for (let i = 0; i < texcoord.length; i++) texcoord[i] = (i % 7) / 7;
    for (let i = 0; i < normal.length; i += 3) normal[i + 2] = 1;
    const glb = await writeMeshAsync(mesh, 'glb');
    samples.push({ name: `${name}.glb`, bytes: glb }, { name: `${name}.gltf`, bytes: glbToEmbeddedGltf(glb) });
  }
  return samples;
}

/** The GLB's JSON with its binary chunk as a base64 data URI: a self-contained `.gltf`. */
function glbToEmbeddedGltf(glb: Uint8Array): Uint8Array {
  const view = new DataView(glb.buffer, glb.byteOffset, glb.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(glb.subarray(20, 20 + jsonLength)));
  const binStart = 20 + jsonLength;
  const bin = glb.subarray(binStart + 8, binStart + 8 + view.getUint32(binStart, true));
  json.buffers[0].uri = `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}`;
  return new TextEncoder().encode(JSON.stringify(json, null, 1));
}

const counts = (mesh: HalfedgeMesh) => `V ${mesh.nVertices} E ${mesh.nEdges} F ${mesh.nFaces}`;

/** Reads one mutated glTF file and checks what came of it. */
export async function checkGltf(name: string, bytes: Uint8Array): Promise<CheckOutcome> {
  try {
    const file = await readMeshAsync(bytes, { fileName: name });
    const { mesh } = buildMesh(file.soup);
    const problems = validate(mesh, { limit: 3 });
    if (problems.length > 0) return { kind: 'failure', reason: `built an invalid mesh: ${problems.map((p) => p.message).join('; ')}` };
    const difference = reloadDifference(mesh);
    if (difference) return { kind: 'failure', reason: `accepted, but saved and read back: ${difference}` };
    const again = buildMesh((await readMeshAsync(await writeMeshAsync(mesh, 'glb'))).soup).mesh;
    if (counts(again) !== counts(mesh)) return { kind: 'failure', reason: `written as .glb and read back: ${counts(mesh)} became ${counts(again)}` };
    return { kind: 'accepted' };
  } catch (error) {
    if (error instanceof ParseError) return refusal(error);
    return { kind: 'failure', reason: `threw ${(error as Error)?.stack ?? String(error)}` };
  }
}

/** At most this many bytes of a failing input go into its replay line, as base64. */
const MAX_INPUT_BYTES = 8192;

export function gltfTarget(samples: Promise<Sample[]> = gltfSamples(), check = checkGltf): FuzzTarget<Promise<CaseOutcome>> {
  return {
    name: 'gltf',
    async runCase(seed: number, index: number): Promise<CaseOutcome> {
      const input = mutatedSample(await samples, seed, index);
      const outcome = await check(input.sample, input.bytes);
      if (outcome.kind !== 'failure') return outcome;
      const bytes = input.bytes.length <= MAX_INPUT_BYTES ? ` bytes (base64) ${Buffer.from(input.bytes).toString('base64')}` : ` (${input.bytes.length} bytes)`;
      return { ...outcome, input: `${input.sample}: ${input.steps.join('; ')};${bytes}` };
    },
  };
}
