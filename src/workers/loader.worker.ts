/** The loader worker: parses and builds one file off the session, so cancel can terminate it. */
import { expose, transfer } from 'comlink';
import { loadFile, throttle } from './load.js';
import { installErrorTransfer, type LoaderApi, transferables } from './protocol.js';

installErrorTransfer();

const loader: LoaderApi = {
  async load(bytes, name, onProgress, options) {
    const loaded = await loadFile(bytes, name, throttle(onProgress), options);
    return transfer(loaded, transferables(loaded));
  },
};

expose(loader);
