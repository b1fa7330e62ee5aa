/** halfedge-lab: a halfedge (DCEL) mesh library. */
export * from './core/index.js';
