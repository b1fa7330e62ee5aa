/**
 * The halfedge core: pure TypeScript (no DOM, no three.js, no Node built-ins), so the same code
 * runs in a Web Worker, in Node and in a plain page.
 */
export * from './attributes.js';
export * from './build.js';
export * from './circulators.js';
export * from './components.js';
export * from './change/index.js';
export * from './live-ids.js';
export * from './errors.js';
export * from './fingerprint.js';
export * from './geometry.js';
export * from './mesh.js';
export * from './mesh-arrays.js';
export * from './random.js';
export * from './report.js';
export * from './serialize.js';
export * from './shapes.js';
export * from './spatial-order.js';
export * from './soup.js';
export * from './seams.js';
export * from './stats.js';
export * from './triangles.js';
export * from './validate.js';
export * from './validate-around.js';
export * from './io/index.js';
export * from './edits/index.js';
export * from './cut/index.js';
export * from './subdivision/index.js';
export * from './smoothing/index.js';
export * from './decimation/index.js';
export * from './remeshing/index.js';
