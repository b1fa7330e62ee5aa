/** Parse and build one file: the work of the loader worker (and of tests, without a worker). */
import { buildMesh, seamEdges, serializeMesh } from '../core/index.js';
import { readMeshAsync } from '../core/io/index.js';
import type { LoadedFile, OpenOptions, ProgressListener } from './protocol.js';

/** Parsing is most of the work; building the rest. */
const READ_SHARE = 0.6;

/** How the loader reads: what the page asked (`OpenOptions`), and where the Draco decoder comes from there (see `GltfReadOptions`). */
export interface LoadOptions extends OpenOptions {
  dracoDecoder?: () => Promise<unknown>;
}

/** `options`: the files a `.gltf` names (its buffers), opened together with it; the weld distance. */
export async function loadFile(bytes: Uint8Array, name: string, onProgress?: ProgressListener, options: LoadOptions = {}): Promise<LoadedFile> {
  const weldTolerance = options.weldTolerance ?? 0;
  const file = await readMeshAsync(bytes, {
    fileName: name,
    resources: options.resources,
    weldTolerance,
    dracoDecoder: options.dracoDecoder,
    onProgress: (fraction) => onProgress?.({ label: `reading ${name}`, fraction: READ_SHARE * fraction }),
  });
  const { mesh, report } = buildMesh(file.soup, {
    onProgress: (fraction) => onProgress?.({ label: 'building the halfedges', fraction: READ_SHARE + (1 - READ_SHARE) * fraction }),
  });
  return {
    mesh: serializeMesh(mesh),
    report,
    file: {
      name,
      format: file.format,
      encoding: file.encoding,
      counts: file.counts,
      comments: file.comments,
      notes: file.notes,
      weldTolerance,
      seams: mesh.halfedgeAttributes.size > 0 ? seamEdges(mesh).length : null,
    },
  };
}

/** Passes on at most one call per `intervalMs` (and always the last, fraction 1). */
export function throttle(listener: ProgressListener, intervalMs = 50): ProgressListener {
  let last = -Infinity;
  return (event) => {
    const now = performance.now();
    if (now - last < intervalMs && event.fraction < 1) return;
    last = now;
    listener(event);
  };
}
