/**
 * The files a `.gltf` names for its buffers, for a caller that must read or fetch them before the
 * file can be read (the command line from beside it, the `<halfedge-view>` element from its URL).
 * Light on purpose: glTF-Transform loads only with the reader (`gltf.ts`).
 */
import { decodeText } from './text.js';

/** The URIs of a `.gltf`'s external buffers as written (`data:` URIs are inside); none when the bytes are not JSON (the reader then says where it breaks). */
export function gltfBufferUris(bytes: Uint8Array): string[] {
  let json: unknown;
  try {
    json = JSON.parse(decodeText(bytes));
  } catch {
    return [];
  }
  const buffers = (json as { buffers?: unknown } | null)?.buffers;
  return (Array.isArray(buffers) ? buffers : [])
    .map((buffer) => (buffer as { uri?: unknown } | null)?.uri)
    .filter((uri): uri is string => typeof uri === 'string' && !uri.startsWith('data:'));
}
