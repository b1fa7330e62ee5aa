/**
 * A level run straight through with Node's helper thread doing the topology steps gives exactly
 * the mesh the calling thread alone gives, on closed and open meshes, triangles, quads and mixed
 * polygons, with blended, copied and face attributes; and it falls back, or reports the helper's
 * error, as `src/node/helper-thread.ts` says.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { buildMesh, catmullClark, grid, type HalfedgeMesh, type PolygonSoup, subdivide, torus, uvSphere, validate } from '../../src/index.js';
import { type HelperThread, useHelperThread } from '../../src/core/subdivision/helper-thread.js';
import { shareMesh } from '../../src/core/serialize.js';
import { nodeHelperThread } from '../../src/node/helper-thread.js';
import { flower, meshArrays, meshOf, triangulate } from './helpers.js';

// From source the worker first loads the TypeScript loader, which takes a while: wait for it
const helper = nodeHelperThread({ minFaces: 0, startWaitMs: 60_000 });

/** The helper, counting the levels it did and the ones it left to the calling thread. */
function countingHelper(): { helper: HelperThread; helped: number; calledOff: number } {
  const counts = { helped: 0, calledOff: 0 };
  const counting: HelperThread = {
    minFaces: 0,
    start() {
      const run = helper.start();
      return {
        ...run,
        begun() {
          const begun = run.begun();
          if (begun) counts.helped++;
          else counts.calledOff++;
          return begun;
        },
      };
    },
  };
  return Object.assign(counts, { helper: counting });
}

/** A mesh with a blended attribute (normals), a copied one (labels) and a face attribute. */
function withAttributes(soup: PolygonSoup): HalfedgeMesh {
  const mesh = meshOf(soup);
  const normals = mesh.vertexAttributes.add('normal', 'float64', 3).data;
  const labels = mesh.vertexAttributes.add('label', 'int32', 1).data;
  const groups = mesh.faceAttributes.add('group', 'uint16', 1).data;
  for (let v = 0; v < mesh.vertexSlots; v++) {
    normals.set([Math.sin(v), Math.cos(v), v / mesh.vertexSlots], 3 * v);
    labels[v] = 7 * v + 1;
  }
  for (let f = 0; f < mesh.faceSlots; f++) groups[f] = f % 5;
  return mesh;
}

/** Pointers, positions and every other attribute, cut to the live slots. */
function everything(mesh: HalfedgeMesh): Record<string, ArrayLike<number>> {
  const attributes = (set: Iterable<{ name: string; itemSize: number; data: ArrayLike<number> & { subarray(a: number, b: number): ArrayLike<number> } }>, count: number, kind: string) =>
    Object.fromEntries([...set].map(({ name, itemSize, data }) => [`${kind} ${name}`, data.subarray(0, count * itemSize)]));
  return { ...meshArrays(mesh), ...attributes(mesh.vertexAttributes, mesh.vertexSlots, 'vertex'), ...attributes(mesh.faceAttributes, mesh.faceSlots, 'face') };
}

/**
 * Where two meshes' arrays and attributes differ: the first differing entry of each array that
 * does ([] when none). A loop over the typed arrays: a deep comparison of a million entries as
 * plain arrays took most of a minute.
 */
function differences(a: HalfedgeMesh, b: HalfedgeMesh): string[] {
  const [ours, theirs] = [everything(a), everything(b)];
  const found: string[] = [];
  for (const name of new Set([...Object.keys(ours), ...Object.keys(theirs)])) {
    const [x, y] = [ours[name], theirs[name]];
    if (!x || !y || x.length !== y.length) {
      found.push(`${name}: ${x?.length} entries against ${y?.length}`);
      continue;
    }
    for (let i = 0; i < x.length; i++) {
      if (Object.is(x[i], y[i])) continue;
      found.push(`${name}[${i}]: ${x[i]} against ${y[i]}`);
      break;
    }
  }
  return found;
}

/** The mesh after `levels` levels, on this thread alone and with the helper; and how often it helped. */
function bothWays(make: () => HalfedgeMesh, scheme: Scheme, levels: number) {
  useHelperThread(null);
  const alone = make();
  subdivide(alone, scheme, levels);
  const counting = countingHelper();
  useHelperThread(counting.helper);
  const helped = make();
  subdivide(helped, scheme, levels);
  useHelperThread(null);
  return { alone, helped, counts: counting };
}

afterAll(() => useHelperThread(null));

/** The schemes a helper takes the topology of: Butterfly's is Loop's, linear subdivision's Catmull-Clark's. */
type Scheme = 'loop' | 'butterfly' | 'catmull-clark' | 'linear';

const fixtures: Array<[string, Scheme, () => HalfedgeMesh]> = [
  ['a closed sphere of triangles', 'loop', () => withAttributes(triangulate(uvSphere(8, 12)))],
  ['an open grid of triangles', 'loop', () => withAttributes(grid(6, 5))],
  ['a closed sphere of triangles', 'butterfly', () => withAttributes(triangulate(uvSphere(8, 12)))],
  ['an open grid of triangles', 'butterfly', () => withAttributes(grid(6, 5))],
  ['a torus of quads', 'catmull-clark', () => withAttributes(torus(10, 8))],
  // 19,200 quads, then 76,800: faces in two chunks and in five, connected by both threads
  ['a torus of quads in several chunks', 'catmull-clark', () => withAttributes(torus(160, 120))],
  ['mixed polygons with a boundary', 'catmull-clark', () => withAttributes(flower())],
  ['a closed sphere of triangles and quads', 'catmull-clark', () => withAttributes(uvSphere(8, 12))],
  ['mixed polygons with a boundary', 'linear', () => withAttributes(flower())],
];

describe.each(fixtures)('on %s, %s straight through', (_, scheme, make) => {
  it('gives with the helper thread exactly what this thread gives alone, two levels, valid', () => {
    const { alone, helped, counts } = bothWays(make, scheme, 2);
    expect(counts.helped).toBe(2);
    expect(helped.heNext.buffer).toBeInstanceOf(SharedArrayBuffer);
    expect(validate(helped)).toEqual([]);
    expect(differences(helped, alone)).toEqual([]);
  }, 120_000);
});

describe('the helper thread', () => {
  it('is left out when an array already had room (it would not be in shared memory): the level runs here, the same', () => {
    const roomy = () => {
      const mesh = withAttributes(torus(10, 8));
      mesh.reserve({ faces: 100 * mesh.faceSlots });
      return mesh;
    };
    const { alone, helped, counts } = bothWays(roomy, 'catmull-clark', 1);
    expect(counts).toMatchObject({ helped: 0, calledOff: 1 });
    expect(validate(helped)).toEqual([]);
    expect(differences(helped, alone)).toEqual([]);
  }, 120_000);

  it('is not started for a level stepped phase by phase, nor for a mesh under its fewest faces', () => {
    let started = 0;
    const start = () => {
      started++;
      return helper.start();
    };
    useHelperThread({ minFaces: 1000, start });
    subdivide(meshOf(torus(10, 8)), 'catmull-clark'); // 80 faces
    for (const _ of catmullClark(meshOf(torus(40, 30)))) {
      // stepped: each phase lists its ids, which the helper's steps do not
    }
    useHelperThread(null);
    expect(started).toBe(0);
  });

  it('is called off when asked whether it has begun before it has a task, and the caller is told to do the steps', () => {
    const run = nodeHelperThread().start();
    expect(run.begun()).toBe(false);
    expect(run.begun()).toBe(false);
    expect(() => run.join()).toThrow('never began');
  });

  it("reports the error a step threw there, as the caller's", () => {
    const run = helper.start();
    const mesh = buildMesh(torus(6, 4)).mesh;
    run.post({ scheme: 'no-such-scheme' as 'loop', oldVertices: mesh.vertexSlots, mesh: shareMesh(mesh) });
    expect(() => run.join()).toThrow("subdivision's helper thread: no topology steps for 'no-such-scheme'");
  }, 120_000);
});

