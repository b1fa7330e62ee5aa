/**
 * What a loader worker runs: parse and build one file, hand the result over transferred. The
 * library's worker (`loader.worker.ts`) and the app's (`src/ui/loader.worker.ts`, which can also
 * decode Draco in the browser) are this with their own Draco decoder or none.
 */
import { expose, transfer } from 'comlink';
import { loadFile, throttle } from './load.js';
import { installErrorTransfer, type LoaderApi, transferables } from './protocol.js';

export function exposeLoader(dracoDecoder?: () => Promise<unknown>): void {
  installErrorTransfer();
  const loader: LoaderApi = {
    async load(bytes, name, onProgress, options) {
      const loaded = await loadFile(bytes, name, throttle(onProgress), { ...options, dracoDecoder });
      return transfer(loaded, transferables(loaded));
    },
  };
  expose(loader);
}
