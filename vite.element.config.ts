import { defineConfig } from 'vite';

/**
 * The <halfedge-view> element as a bundle of its own: the package's `halfedge-lab/element`
 * (dist/element/element.js, its workers and on-demand parts beside it). The page's build is
 * vite.config.ts; the library's, tsc.
 */
export default defineConfig({
  // its workers and chunks are found beside element.js, wherever a site puts it
  base: './',
  publicDir: false,
  build: {
    target: 'es2022',
    outDir: 'dist/element',
    emptyOutDir: true,
    chunkSizeWarningLimit: 1200,
    lib: { entry: 'src/ui/element.ts', formats: ['es'], fileName: 'element' },
  },
  worker: { format: 'es' },
});
