/**
 * halfedge-lab in Node (the package's `node` entry): the whole library, with a helper thread for
 * subdivision levels run straight through (see `helper-thread.ts`). `useHelperThread(null)` turns
 * it off; `installHelperThread(options)` on again.
 */
import { installHelperThread } from './helper-thread.js';

installHelperThread();

export * from '../index.js';
export { type HelperOptions, installHelperThread } from './helper-thread.js';
