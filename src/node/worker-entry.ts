/**
 * How to start a worker thread on a module of this library: built, its `.js` file; from source
 * (tests, `npm run cli`), an eval'd script that first registers the TypeScript loader the caller
 * runs under, then imports the `.ts` file.
 */
import { basename, extname } from 'node:path';
import { fileURLToPath } from 'node:url';

export interface WorkerEntry {
  code: string | URL;
  eval: boolean;
}

/** The worker module `path` (relative to `base`, the caller's `import.meta.url`, without extension). */
export function workerEntry(base: string, path: string): WorkerEntry {
  const extension = extname(fileURLToPath(base));
  const file = new URL(`${path}${extension}`, base);
  return extension === '.ts'
    ? { code: `import('tsx/esm/api').then(({ register }) => (register(), import(${JSON.stringify(file.href)})))`, eval: true }
    : { code: file, eval: false };
}

/** The caller's own module (`base`: its `import.meta.url`) started again as a worker: a bundle that is its own worker. */
export function selfEntry(base: string): WorkerEntry {
  const file = fileURLToPath(base);
  return workerEntry(base, `./${basename(file, extname(file))}`);
}
