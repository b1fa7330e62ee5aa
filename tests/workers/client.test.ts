import { describe, expect, it } from 'vitest';
import { SessionClient } from '../../src/workers/client.js';

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
