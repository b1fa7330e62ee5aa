/** The fuzz targets `npm run fuzz` knows, by name (`--only NAME`). */
import { editsTarget } from './edits.js';
import { gltfTarget } from './gltf.js';
import { corpusTarget, readersTarget } from './readers.js';
import type { FuzzTarget } from './target.js';

export const targets: FuzzTarget[] = [readersTarget, corpusTarget, editsTarget, gltfTarget()];
