import { defineConfig } from 'vite';

/**
 * The grader inside a course's autograder zip (`halfedge-lab autograder`) as one self-contained ES
 * module for Node ≥ 20, dist/grader/grader.mjs: the practice core, the sandbox and acorn bundled
 * in, only Node's own modules imported. `.mjs`, so it is a module wherever it is unpacked, with or
 * without a package.json around it. It is its own sandbox worker, so it stays one file. The
 * command uses this file when the package is installed; from source it bundles it afresh.
 */
export default defineConfig({
  publicDir: false,
  logLevel: 'warn',
  build: {
    ssr: 'src/cli/grader-main.ts',
    target: 'node20',
    outDir: 'dist/grader',
    emptyOutDir: true,
    minify: false,
    rolldownOptions: { output: { format: 'es', entryFileNames: 'grader.mjs', codeSplitting: false } },
  },
  // bundle every package too: the zip has no node_modules
  ssr: { target: 'node', noExternal: true },
});
