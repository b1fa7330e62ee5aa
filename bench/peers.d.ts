// three-mesh-halfedge's "main" is a UMD file that Node cannot load as ESM; the bench imports its
// ESM build directly, which carries the same types.
declare module 'three-mesh-halfedge/build/index.esm.js' {
  export * from 'three-mesh-halfedge';
}
