import { expose } from 'comlink';
import { describe, expect, it } from 'vitest';
import { buildMesh, disk, serializeMesh, validate } from '../../src/index.js';
import { SessionClient } from '../../src/workers/client.js';
import { snapshotVerbNames } from '../../src/workers/protocol.js';
import { EditingSession } from '../../src/workers/session.js';
import { sessionApi } from '../../src/workers/session-api.js';

/** A worker whose script fails to load: it never answers, and reports an error at once. */
class UnloadableWorker extends EventTarget {
  postMessage(): void {}
  terminate(): void {}
  constructor() {
    super();
    queueMicrotask(() => this.dispatchEvent(new Event('error', { cancelable: true })));
  }
}

describe('SessionClient', () => {
  it('does not restart, over and over, a worker that could not load', async () => {
    let started = 0;
    const messages: string[] = [];
    const client = new SessionClient({
      createSessionWorker: () => {
        started++;
        return new UnloadableWorker() as unknown as Worker;
      },
    });
    client.onRestart = (message) => messages.push(message);
    await new Promise((resolve) => setTimeout(resolve, 50));
    expect(started).toBe(1);
    expect(messages).toEqual(['the editing worker could not start; reload the page to try again']);
    await expect(client.snapshot()).rejects.toThrow(/editing worker stopped/);
  });
});

/** A session worker in this process: the worker's own api on one end of a channel, the client on the other. */
function inProcessWorker(): Worker {
  const { port1, port2 } = new MessageChannel();
  expose(sessionApi(new EditingSession()), port1);
  return Object.assign(port2, {
    terminate: () => {
      port1.close();
      port2.close();
    },
  }) as unknown as Worker;
}

describe('SessionClient and the session worker, from the table of verbs', () => {
  it('has a method for every verb but adopt, and each reaches the session', async () => {
    const client = new SessionClient({ createSessionWorker: inProcessWorker });
    try {
      for (const verb of snapshotVerbNames) expect(typeof (client as unknown as Record<string, unknown>)[verb], verb).toBe(verb === 'adopt' ? 'undefined' : 'function');
      const opened = await client.restore(serializeMesh(buildMesh(disk(4)).mesh), 'disk');
      const edges = opened.mesh.nEdges;
      const grows = opened.mesh.isBoundaryEdge(5) ? 2 : 3; // the edge's second half, and one across each face beside it
      const flipped = await client.edit({ kind: 'flip-edge', edge: 3 });
      expect(flipped.renderPatch, 'an edit arrives as a patch').not.toBeNull();
      expect(validate(flipped.mesh)).toEqual([]);
      const split = await client.request('edit', { kind: 'split-edge', edge: 5, triangulate: true });
      expect(split.mesh.nEdges).toBe(edges + grows);
      expect((await client.undo()).mesh.nEdges).toBe(edges);
      expect((await client.redo()).mesh.nEdges).toBe(edges + grows);
      expect((await client.jump(0)).history.index).toBe(0);
      const fingerprints = await client.fingerprints();
      expect(fingerprints.page).toBe(fingerprints.session);
      const faces = (await client.snapshot()).mesh.nFaces;
      await client.start({ kind: 'subdivide', scheme: 'loop' });
      expect((await client.step()).stepping?.phases).toBe(1);
      expect((await client.cancel())?.mesh.nFaces).toBe(faces);
      await client.start({ kind: 'subdivide', scheme: 'loop' });
      const subdivided = await client.runToEnd();
      expect(subdivided.mesh.nFaces).toBe(4 * faces);
      expect(subdivided.history.items.at(-1)?.label).toMatch(/Loop/);
    } finally {
      client.dispose();
    }
  });
});
