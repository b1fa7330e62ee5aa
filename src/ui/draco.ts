/**
 * The Draco decoder in a browser worker: `draco3dgltf`'s decoder script, bundled, and its
 * WebAssembly, fetched — both only when a Draco-compressed file comes. The script is written for
 * Node and the web alike; given the WebAssembly's bytes it reads no file of its own.
 */
import wasmUrl from 'draco3dgltf/draco_decoder_gltf.wasm?url';

export async function browserDracoDecoder(): Promise<unknown> {
  const [{ default: createDecoderModule }, wasmBinary] = await Promise.all([
    import('draco3dgltf/draco_decoder_gltf_nodejs.js'),
    fetch(wasmUrl).then((response) => {
      if (!response.ok) throw new Error(`the Draco decoder could not be fetched (${response.status})`);
      return response.arrayBuffer();
    }),
  ]);
  return createDecoderModule({ wasmBinary });
}
