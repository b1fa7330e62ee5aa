import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { defineConfig, type Plugin } from 'vite';

/** The page's markup is src/ui/layout.html, which the <halfedge-view> element builds from too. */
function appLayout(): Plugin {
  return {
    name: 'app-layout',
    transformIndexHtml: (html) => html.replace('<!-- app layout: src/ui/layout.html -->', readFileSync(new URL('src/ui/layout.html', import.meta.url), 'utf8')),
  };
}

/** Lists every file of the built site in offline.json, for the service worker to keep (public/sw.js). */
function offlineList(): Plugin {
  let outDir = '';
  return {
    name: 'offline-list',
    apply: 'build',
    configResolved: (config) => void (outDir = config.build.outDir),
    // after everything, public/ included, is written
    closeBundle() {
      const files = readdirSync(outDir, { recursive: true, withFileTypes: true })
        .filter((entry) => entry.isFile())
        .map((entry) => relative(outDir, join(entry.parentPath, entry.name)).split('\\').join('/'))
        .filter((file) => file !== 'sw.js' && file !== 'index.html' && !file.endsWith('.map'));
      // the page is asked for as the folder, not by its file name
      writeFileSync(join(outDir, 'offline.json'), JSON.stringify(['./', ...files.sort()]));
    },
  };
}

export default defineConfig({
  // the app builds to site/ (a static site); dist/ is the library's (tsc)
  build: { target: 'es2022', outDir: 'site', chunkSizeWarningLimit: 1200 },
  worker: { format: 'es' },
  plugins: [appLayout(), offlineList()],
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
