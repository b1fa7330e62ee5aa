/** The loader worker: parses and builds one file off the session, so cancel can terminate it. */
import { exposeLoader } from './loader-api.js';

exposeLoader();
