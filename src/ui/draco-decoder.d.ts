/** The decoder script of `draco3dgltf` (its package types name only the package's main). */
declare module 'draco3dgltf/draco_decoder_gltf_nodejs.js' {
  export default function createDecoderModule(options: { wasmBinary: ArrayBuffer }): Promise<unknown>;
}
