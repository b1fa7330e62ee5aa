import { describe, expect, it } from 'vitest';
import {
  annulus,
  buildMesh,
  canFlipEdge,
  cube,
  disk,
  diffPointers,
  faceVertices,
  flipEdge,
  meshStats,
  ParseError,
  type PolygonSoup,
  seededRandom,
  serializeMesh,
  soupFromArrays,
  subdivide,
  tetrahedron,
  TopologyError,
  torus,
  uvSphere,
  validateChange,
  vertexAdjacentVertices,
  writeSoup,
} from '../../src/index.js';
import { loadFile } from '../../src/workers/load.js';
import { PageCopy } from '../../src/workers/page-copy.js';
import { PICK_IN_WORKER_ABOVE, transferables } from '../../src/workers/protocol.js';
import { RenderLayout } from '../../src/workers/render.js';
import { EditingSession } from '../../src/workers/session.js';
import { meshContents } from '../core/contents.js';
import { type PageSession, pageSession, randomEdit } from './page-session.js';

async function sessionWith(bytes: Uint8Array, name: string): Promise<PageSession & { adopt: EditingSession['adopt']; setProgressListener: EditingSession['setProgressListener']; exportMesh: EditingSession['exportMesh']; historyBytes: () => number }> {
  const session = new EditingSession();
  session.adopt(await loadFile(bytes, name));
  const page = pageSession(session);
  return {
    ...page,
    adopt: (...args) => session.adopt(...args),
    setProgressListener: (listener) => session.setProgressListener(listener),
    exportMesh: (format) => session.exportMesh(format),
    historyBytes: () => session.historyBytes(),
  };
}

const cubeFile = () => writeSoup(cube(), 'off');

/** A session on `shape` and a page copy that has taken its first snapshot. */
async function sessionAndPage(shape: PolygonSoup): Promise<{ session: EditingSession; page: PageCopy }> {
  const session = new EditingSession();
  session.adopt(await loadFile(writeSoup(shape, 'off'), 'model.off'));
  const page = new PageCopy();
  page.take(session.snapshot());
  return { session, page };
}

describe('EditingSession', () => {
  it('opens a file into the first history entry and snapshots it', async () => {
    const snapshot = (await sessionWith(cubeFile(), 'cube.off')).snapshot();
    expect(snapshot.stats.faces).toBe(6);
    expect(snapshot.problems).toEqual([]);
    expect(snapshot.file?.name).toBe('cube.off');
    expect(snapshot.history).toEqual({
      items: [{ label: 'open cube.off', vertices: 8, faces: 6, source: { kind: 'open', name: 'cube.off', sample: null } }],
      index: 0,
    });
    // quads are drawn as two triangles each, remembering their face
    expect(snapshot.render.counts.triangles).toBe(6 * 2);
    expect(Array.from(snapshot.render.triangleFace.subarray(0, 4))).toEqual([0, 0, 1, 1]);
  });

  it('steps Loop subdivision phase by phase, valid after each, then adds it to the history', async () => {
    const session = await sessionWith(writeSoup(tetrahedron(), 'off'), 'tet.off');
    let snapshot = session.start({ kind: 'subdivide', scheme: 'loop' });
    expect(snapshot.stepping).toEqual({ label: 'Loop subdivision', phases: 0, total: 4 });
    const names: string[] = [];
    for (let i = 0; i < 4; i++) {
      snapshot = session.step();
      expect(snapshot.problems).toEqual([]);
      names.push(snapshot.phase!.name);
    }
    // the last announced phase finishes the operation: no empty step after it
    expect(snapshot.stepping).toBeNull();
    expect(snapshot.history.index).toBe(1);
    // with the request as run (its level counted), for a link to replay
    expect(snapshot.history.items[1]).toEqual({
      label: 'Loop subdivision',
      vertices: 10,
      faces: 16,
      source: { kind: 'operation', request: { kind: 'subdivide', scheme: 'loop', level: 0 } },
    });
    expect(new Set(names).size).toBe(4);
  });

  it('keeps the last phase on show after the final Step, and steps back phase by phase to the start', async () => {
    const session = await sessionWith(writeSoup(torus(6, 4), 'off'), 't.off');
    const { total } = session.start({ kind: 'subdivide', scheme: 'catmull-clark' }).stepping!;
    expect(total).toBeGreaterThanOrEqual(3);
    // each phase as stepping forward shows it: its name, diff and mesh
    const forward: { name: string; diff: unknown; contents: unknown }[] = [];
    for (let i = 0; i < total!; i++) {
      const shown = session.step();
      forward.push({ name: shown.phase!.name, diff: shown.diff, contents: meshContents(shown.mesh) });
    }
    let snapshot = session.snapshot();
    // the operation is in the history, and its last phase stays: name, diff, the one who ended it
    expect(snapshot.stepping).toBeNull();
    expect(snapshot.ended).toEqual({ label: 'Catmull-Clark subdivision', phases: total, total });
    expect(snapshot.phase?.name).toBe(forward[total! - 1].name);
    expect(snapshot.diff).toEqual(forward[total! - 1].diff);
    expect(forward.some((phase) => (phase.diff as { total: number }).total > 0)).toBe(true);
    expect(snapshot.history.index).toBe(1);
    // back into the operation: phase 3, its mesh and diff as they were going forward
    for (let phases = total! - 1; phases >= 1; phases--) {
      snapshot = session.stepBack();
      expect(snapshot.problems).toEqual([]);
      expect(snapshot.ended).toBeNull();
      expect(snapshot.stepping).toEqual({ label: 'Catmull-Clark subdivision', phases, total });
      expect(snapshot.phase?.name).toBe(forward[phases - 1].name);
      expect(snapshot.diff).toEqual(forward[phases - 1].diff);
      expect(meshContents(snapshot.mesh)).toEqual(forward[phases - 1].contents);
    }
    // the start: the mesh before the operation, and no phase before it
    snapshot = session.stepBack();
    expect(snapshot.stepping?.phases).toBe(0);
    expect(snapshot.stats.faces).toBe(6 * 4);
    expect(() => session.stepBack()).toThrow(/at its start/);
    // forward again to the end: the same mesh, one history entry for it
    for (let i = 0; i < total!; i++) snapshot = session.step();
    expect(meshContents(snapshot.mesh)).toEqual(forward[total! - 1].contents);
    expect(snapshot.history.items.map((item) => item.label)).toEqual(['open t.off', 'Catmull-Clark subdivision']);
    // undo after the end undoes the whole operation, and leaves the last phase
    snapshot = session.undo();
    expect(snapshot.ended).toBeNull();
    expect(snapshot.stats.faces).toBe(6 * 4);
    expect(() => session.stepBack()).toThrow(/no operation/);
  });

  it('steps a smoothing back in place, and Run to end does not keep a last phase', async () => {
    const session = await sessionWith(writeSoup(uvSphere(12, 16), 'ply-binary'), 'sphere.ply');
    const start = Array.from(session.snapshot().mesh.positions);
    session.start({ kind: 'smooth', options: { method: 'taubin', iterations: 1 } });
    const first = Array.from(session.step().mesh.positions);
    session.step();
    expect(session.snapshot().ended?.phases).toBe(2);
    expect(Array.from(session.stepBack().mesh.positions)).toEqual(first);
    expect(Array.from(session.stepBack().mesh.positions)).toEqual(start);
    const run = await session.runToEnd();
    expect(run.ended).toBeNull();
    expect(run.stepping).toBeNull();
    expect(Array.from(session.undo().mesh.positions)).toEqual(start);
  });

  it('gives the same mesh stepping as the library straight through', async () => {
    const session = await sessionWith(writeSoup(torus(6, 4), 'off'), 't.off');
    session.start({ kind: 'subdivide', scheme: 'catmull-clark' });
    let snapshot = session.snapshot();
    while (session.snapshot().stepping) snapshot = session.step();
    const { mesh } = buildMesh(torus(6, 4));
    subdivide(mesh, 'catmull-clark');
    expect(meshContents(snapshot.mesh)).toEqual(meshContents(mesh));
  });

  it('counts √3 levels, so the boundary of an open mesh is split on every second one', async () => {
    const session = await sessionWith(writeSoup(disk(1), 'off'), 'disk.off');
    const boundaryEdges = () => session.snapshot().stats.boundaryEdges;
    expect(boundaryEdges()).toBe(6);
    for (const [level, phases, boundary] of [[0, 3, 6], [1, 5, 18], [2, 3, 18]] as const) {
      const started = session.start({ kind: 'subdivide', scheme: 'sqrt3' });
      expect(started.stepping?.total, `level ${level}`).toBe(phases);
      for (let i = 0; i < phases; i++) session.step();
      expect(session.snapshot().stepping).toBeNull();
      expect(boundaryEdges()).toBe(boundary);
    }
  });

  it('smooths in phases and keeps only the moved positions in the history', async () => {
    const session = await sessionWith(writeSoup(uvSphere(20, 30), 'ply-binary'), 'sphere.ply');
    const opened = session.historyBytes();
    const started = session.start({ kind: 'smooth', options: { method: 'taubin', iterations: 2 } });
    expect(started.stepping).toEqual({ label: 'Taubin smoothing, 2 iterations', phases: 0, total: 4 });
    for (let i = 0; i < 4; i++) expect(session.step().problems).toEqual([]);
    const done = session.snapshot();
    expect(done.stepping).toBeNull();
    expect(done.history.items.at(-1)?.label).toBe('Taubin smoothing, 2 iterations');
    // the entry is a difference (positions only), not a second mesh
    const positions = done.mesh.positions.subarray(0, 3 * done.mesh.vertexSlots).byteLength;
    expect(session.historyBytes()).toBeLessThan(opened + 2 * positions + 1000);
    // the start (nothing changed yet) and each step reached the page as patches (the last
    // snapshot here was asked for whole)
    expect(session.patched.slice(-6)).toEqual([true, true, true, true, true, false]);
  });

  it('decimates in batches down to the target, refusing a quad mesh with the reason', async () => {
    const session = await sessionWith(writeSoup(uvSphere(20, 30), 'off'), 'sphere.off');
    expect(session.snapshot().unavailable.decimate).toBeNull();
    session.start({ kind: 'decimate', options: { targetFaces: 200 } });
    let snapshot = session.step();
    expect(snapshot.phase?.values?.vertices).toBeDefined();
    while (session.snapshot().stepping) snapshot = session.step();
    expect(snapshot.stats.faces).toBeLessThanOrEqual(200);
    expect(snapshot.problems).toEqual([]);
    expect(snapshot.stats.genus).toBe(0);
    const quads = await sessionWith(cubeFile(), 'cube.off');
    expect(quads.snapshot().unavailable.decimate).toMatch(/needs triangles/);
    expect(() => quads.start({ kind: 'decimate', options: { targetFaces: 4 } })).toThrow(TopologyError);
  });

  it('cancels a stepped operation back to the mesh before it', async () => {
    const session = await sessionWith(cubeFile(), 'cube.off');
    session.start({ kind: 'subdivide', scheme: 'catmull-clark' });
    expect(session.step().stats.vertices).toBeGreaterThan(8);
    const snapshot = session.cancel();
    expect(snapshot.stats.vertices).toBe(8);
    expect(snapshot.stepping).toBeNull();
    expect(snapshot.history.items).toHaveLength(1);
  });

  it('refuses an operation that does not apply, leaving everything as it was', async () => {
    const session = await sessionWith(cubeFile(), 'cube.off');
    const before = session.snapshot();
    expect(() => session.start({ kind: 'subdivide', scheme: 'loop' })).toThrow(TopologyError);
    expect(() => session.start({ kind: 'subdivide', scheme: 'loop' })).toThrow(/triangles/);
    const after = session.snapshot();
    expect(after.stepping).toBeNull();
    expect(after.history).toEqual(before.history);
  });

  it('applies a local edit with its exact pointer diff, and undoes and redoes it', async () => {
    const session = await sessionWith(writeSoup(torus(4, 4), 'off'), 't.off');
    const before = session.snapshot();
    const beforeMesh = before.mesh.clone();
    const edited = session.edit({ kind: 'poke-face', face: 3 });
    expect(edited.stats.faces).toBe(16 - 1 + 4);
    expect(edited.diff!.changes).toEqual(diffPointers(beforeMesh, edited.mesh).changes);
    expect(session.patched.at(-1)).toBe(true);
    expect(edited.history.items.map((i) => i.label)).toEqual(['open t.off', 'poke f3']);
    expect(session.undo().stats).toEqual(before.stats);
    expect(session.redo().stats).toEqual(edited.stats);
    expect(session.jump(0).history.index).toBe(0);
    // an edit made after going back replaces the undone branch
    const branched = session.edit({ kind: 'split-edge', edge: 0 });
    expect(branched.history.items.map((i) => i.label)).toEqual(['open t.off', 'split e0']);
    expect(() => session.edit({ kind: 'flip-edge', edge: 0 })).toThrow(TopologyError);
  });

  it('runs to the end in one call, reporting progress after each phase', async () => {
    const session = await sessionWith(writeSoup(tetrahedron(), 'off'), 'tet.off');
    const events: number[] = [];
    session.setProgressListener((event) => events.push(event.fraction));
    session.start({ kind: 'subdivide', scheme: 'loop' });
    const snapshot = await session.runToEnd();
    expect(snapshot.stats.faces).toBe(16);
    expect(events).toEqual([0.25, 0.5, 0.75, 1]);
  });

  it('hears a cancel while running to the end', async () => {
    const session = await sessionWith(writeSoup(tetrahedron(), 'off'), 'tet.off');
    session.start({ kind: 'subdivide', scheme: 'loop' });
    const running = session.runToEnd();
    session.cancel();
    const snapshot = await running;
    expect(snapshot.stats.faces).toBe(4);
    expect(snapshot.history.items).toHaveLength(1);
  });

  it('exports the current mesh in the asked format', async () => {
    const session = await sessionWith(cubeFile(), 'cube.off');
    const text = new TextDecoder().decode(await session.exportMesh('obj'));
    expect(text.match(/^f /gm)).toHaveLength(6);
  });
});

describe('a patched snapshot', () => {
  it.each([
    ['a disk', () => disk(6)],
    ['an annulus', () => annulus(24)],
    ['a sphere', () => uvSphere(16, 24)],
  ])('carries its change’s check and the exact boundary edges, the rest pending until details() (%s)', async (_, shape) => {
    const { session, page } = await sessionAndPage(shape());
    const random = seededRandom(20261126);
    let patched = 0;
    let version = 0;
    for (let i = 0; i < 60; i++) {
      const request = randomEdit(page.mesh!, random);
      const roll = random();
      const snapshot = roll < 0.7 && request ? session.edit(request) : roll < 0.85 ? session.undo() : session.redo();
      const shown = page.take(snapshot);
      version = snapshot.version;
      if (!snapshot.patch) continue;
      patched++;
      const whole = meshStats(shown.mesh);
      const step = `${i}: ${roll < 0.7 && request ? JSON.stringify(request) : 'undo or redo'}`;
      expect(shown.pending, step).toBe(true);
      expect(shown.problems, step).toEqual([]);
      const exact = ({ vertices, edges, faces, eulerCharacteristic, boundaryEdges }: typeof whole) => ({ vertices, edges, faces, eulerCharacteristic, boundaryEdges });
      expect(exact(shown.stats), step).toEqual(exact(whole));
    }
    expect(patched).toBeGreaterThan(40);
    // the full pass agrees, and is of this snapshot
    const details = session.details();
    expect(details.version).toBe(version);
    expect(details.problems).toEqual([]);
    expect(details.stats).toEqual(meshStats(page.mesh!));
  });

  it.each([
    ['a disk', () => disk(6)],
    ['a sphere', () => uvSphere(16, 24)],
  ])('after smoothing steps, details() measures the moved surface and agrees with a full pass, and after an edit too (%s)', async (_, shape) => {
    const { session, page } = await sessionAndPage(shape());
    page.take(session.start({ kind: 'smooth', options: { method: 'laplacian', iterations: 2, boundary: 'smooth' } }));
    const areas: number[] = [];
    for (let i = 0; i < 2; i++) {
      const stepped = page.take(session.step());
      expect(stepped.pending).toBe(true);
      const details = session.details();
      expect(details.version).toBe(stepped.version);
      expect(details.stats).toEqual(meshStats(page.mesh!));
      expect(details.problems).toEqual([]);
      areas.push(details.stats.surfaceArea);
    }
    // the surface did move: a measure kept from before the step would not have agreed
    expect(areas[1]).not.toBe(areas[0]);
    // the second step ended the operation: an edit now is a patch of the smoothed mesh
    const edge = [...page.mesh!.edges()].find((e) => canFlipEdge(page.mesh!, e) === null)!;
    const edited = page.take(session.edit({ kind: 'flip-edge', edge }));
    expect(edited.pending).toBe(true);
    expect(session.details().stats).toEqual(meshStats(page.mesh!));
  });

  it('keeps the problems a broken mesh had before the change, for the full pass to sort out', async () => {
    const session = new EditingSession();
    session.adopt(await loadFile(writeSoup(disk(6), 'off'), 'disk.off'));
    const { mesh } = buildMesh(disk(6));
    const v = [...mesh.vertices()].find((u) => !mesh.isBoundaryVertex(u))!;
    // an edge whose flip stays two rings away from v
    const nearV = new Set([v]);
    for (let ring = 0; ring < 2; ring++) for (const u of [...nearV]) for (const w of vertexAdjacentVertices(mesh, u)) nearV.add(w);
    const cornersNear = (h: number) => [...faceVertices(mesh, mesh.heFace[h])].some((u) => nearV.has(u));
    const far = [...mesh.edges()].find((e) => canFlipEdge(mesh, e) === null && !cornersNear(2 * e) && !cornersNear(2 * e + 1))!;
    mesh.vHalfedge[v] = mesh.vHalfedge[v] ^ 1; // a halfedge that ends at v
    const practiced = session.practice(serializeMesh(mesh), 'a broken disk', null);
    expect(practiced.details.problems.length).toBeGreaterThan(0);
    // the check of what the flip touches alone would find nothing
    expect(validateChange(mesh, flipEdge(mesh, far).record!)).toEqual([]);
    const edited = session.edit({ kind: 'flip-edge', edge: far });
    expect(edited.patch).not.toBeNull();
    expect(edited.details.pending).toBe(true);
    expect(edited.details.problems).toEqual(practiced.details.problems);
    expect(session.details().problems).toEqual(practiced.details.problems);
  });
});

describe('loading files for the session', () => {
  it('raises the parser error with its place, and leaves the session untouched', async () => {
    const session = await sessionWith(cubeFile(), 'cube.off');
    const bad = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n');
    await expect(loadFile(bad, 'bad.off')).rejects.toThrow(ParseError);
    await expect(loadFile(bad, 'bad.off')).rejects.toThrow(/line 6/);
    expect(session.snapshot().stats.faces).toBe(6);
  });

  it('reports progress from reading to building, ending at 1', async () => {
    const fractions: number[] = [];
    await loadFile(writeSoup(torus(40, 40), 'ply-binary'), 't.ply', (event) => fractions.push(event.fraction));
    expect(fractions.at(-1)).toBe(1);
    expect([...fractions].sort((a, b) => a - b)).toEqual(fractions);
  });

  // (binary files are read in bulk, a few milliseconds per million rows: they need no finer steps)
  it.each(['off', 'ply', 'obj'] as const)('reports a big %s text file in small steps, none a tenth of the work', async (format) => {
    const fractions: number[] = [];
    await loadFile(writeSoup(torus(600, 600), format), `big.${format}`, (event) => fractions.push(event.fraction));
    const steps = fractions.slice(1).map((f, i) => f - fractions[i]!);
    expect(Math.max(...steps)).toBeLessThan(0.1);
  });
});

describe('snapshots cross the worker boundary by transfer', () => {
  it('lists every buffer, and transferring empties the sender’s arrays', async () => {
    const session = new EditingSession();
    session.adopt(await loadFile(cubeFile(), 'cube.off'));
    const snapshot = session.snapshot();
    const buffers = transferables(snapshot);
    expect(buffers).toContain(snapshot.mesh!.heNext.buffer);
    expect(buffers).toContain(snapshot.render!.triangles.buffer);
    const received = structuredClone(snapshot, { transfer: buffers });
    expect(snapshot.mesh!.heNext.byteLength).toBe(0);
    expect(snapshot.render!.triangles.byteLength).toBe(0);
    expect(received.mesh!.slots.edges).toBe(12);
    // and the session still has its mesh
    expect(session.snapshot().mesh!.slots.edges).toBe(12);
  });

  it('copies the drawing arrays for the picking worker only for a mesh past PICK_IN_WORKER_ABOVE triangles', async () => {
    expect(new RenderLayout().full(buildMesh(cube()).mesh).picking).toBeNull();
    const big = buildMesh(uvSphere(200, 400)).mesh; // 2 · 400 · 199 triangles
    expect(big.nFaces).toBeGreaterThan(PICK_IN_WORKER_ABOVE);
    const render = new RenderLayout().full(big);
    const picking = render.picking!;
    expect(picking.positions).toEqual(render.positions);
    expect(picking.triangles).toEqual(render.triangles.subarray(0, 3 * render.counts.triangles));
    // copies, each sent on its own buffer: the page keeps drawing while the picking worker has its own
    expect(picking.positions.buffer).not.toBe(render.positions.buffer);
    expect(picking.triangles.buffer).not.toBe(render.triangles.buffer);
    const session = new EditingSession();
    session.adopt(await loadFile(cubeFile(), 'cube.off'));
    const snapshot = session.snapshot();
    expect(transferables({ ...snapshot, render })).toEqual(expect.arrayContaining([picking.positions.buffer, picking.triangles.buffer]));
  });
});

describe('triangles for drawing', () => {
  it('splits a non-convex face into triangles that stay inside it', async () => {
    // an L-shaped hexagon listed from (2, 1): a fan from there would cover the notch
    const { mesh } = buildMesh(soupFromArrays([0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0], [[2, 3, 4, 5, 0, 1]]));
    const render = new RenderLayout().full(mesh);
    const triangles = render.triangles.subarray(0, 3 * render.counts.triangles);
    const triangleFace = render.triangleFace.subarray(0, render.counts.triangles);
    expect(triangles.length).toBe(3 * 4);
    expect(Array.from(triangleFace)).toEqual([0, 0, 0, 0]);
    let area = 0;
    for (let t = 0; t < triangles.length; t += 3) {
      const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]].map((v) => mesh.position(v));
      const triangle = ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
      expect(triangle).toBeGreaterThan(0); // counter-clockwise: none folds over the notch
      area += triangle;
    }
    expect(area).toBeCloseTo(3, 12);
  });
});
