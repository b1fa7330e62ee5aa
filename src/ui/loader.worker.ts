/** The app's loader worker: the library's, with the Draco decoder a browser can load (draco.ts). */
import { exposeLoader } from '../workers/loader-api.js';
import { browserDracoDecoder } from './draco.js';

exposeLoader(browserDracoDecoder);
