import { defineConfig } from 'vite';

export default defineConfig({
  // the app builds to site/ (a static site); dist/ is the library's (tsc)
  build: { target: 'es2022', outDir: 'site', chunkSizeWarningLimit: 1200 },
  worker: { format: 'es' },
  // known up front, so the dev server never reloads the page to add a dependency it just found
  optimizeDeps: {
    include: [
      'three',
      'comlink',
      'earcut',
      'three-mesh-bvh',
      'three/examples/jsm/controls/OrbitControls.js',
      'three/examples/jsm/renderers/CSS2DRenderer.js',
      'three/examples/jsm/controls/TransformControls.js',
    ],
  },
});
