/**
 * The package as its users get it: packed with `npm pack` from a checkout that was never built
 * (as publishing does, and installing from a git URL), installed into a fresh project, then
 * imported from Node (with its type declarations), run as a CLI, and bundled by Vite with the
 * worker subpath.
 */
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

const root = join(import.meta.dirname, '..');
const run = (command: string, args: string[], cwd: string) =>
  execFileSync(command, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], env: { ...process.env, npm_config_loglevel: 'error' } });

/**
 * A checkout of the working tree: the files git tracks or would track (so no `dist/`), with the
 * repository's installed packages beside them.
 */
function freshCheckout(): string {
  const checkout = mkdtempSync(join(tmpdir(), 'halfedge-lab-checkout-'));
  const files = run('git', ['ls-files', '--cached', '--others', '--exclude-standard', '-z'], root).split('\0').filter(Boolean);
  for (const file of files) {
    if (!existsSync(join(root, file))) continue; // deleted, not yet committed
    if (file === 'node_modules') continue; // a symbolic link to the packages (not matched by node_modules/): linked below
    mkdirSync(join(checkout, file, '..'), { recursive: true });
    cpSync(join(root, file), join(checkout, file));
  }
  symlinkSync(join(root, 'node_modules'), join(checkout, 'node_modules'), 'dir');
  return checkout;
}

describe('the packed package in a fresh project', () => {
  let project = '';
  let checkout = '';

  beforeAll(() => {
    project = mkdtempSync(join(tmpdir(), 'halfedge-lab-user-'));
    checkout = freshCheckout();
    expect(existsSync(join(checkout, 'dist'))).toBe(false);
    const tarball = run('npm', ['pack', '--pack-destination', project, '--json'], checkout);
    const file = (JSON.parse(tarball) as Array<{ filename: string }>)[0]!.filename;
    writeFileSync(join(project, 'package.json'), JSON.stringify({ name: 'user', private: true, type: 'module' }));
    run('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', join(project, file)], project);
  }, 240_000);

  afterAll(() => {
    for (const dir of [project, checkout]) if (dir) rmSync(dir, { recursive: true, force: true });
  });

  it('imports in Node and builds a valid mesh', () => {
    writeFileSync(
      join(project, 'use.mjs'),
      `import { buildMesh, meshStats, torus, validate, writeMesh } from 'halfedge-lab';
       import { SessionClient } from 'halfedge-lab/worker';
       const { mesh } = buildMesh(torus(8, 6));
       const stats = meshStats(mesh);
       console.log(JSON.stringify({ genus: stats.genus, problems: validate(mesh).length, client: typeof SessionClient, bytes: writeMesh(mesh, 'off').length > 0 }));`,
    );
    expect(JSON.parse(run('node', ['use.mjs'], project))).toEqual({ genus: 1, problems: 0, client: 'function', bytes: true });
  });

  it('subdivides in Node with a helper thread, into shared memory, as this thread alone would', () => {
    writeFileSync(
      join(project, 'helper.mjs'),
      `import { buildMesh, subdivide, torus, useHelperThread, validate } from 'halfedge-lab';
       const level = () => { const { mesh } = buildMesh(torus(250, 200)); subdivide(mesh, 'catmull-clark'); return mesh; };
       const helped = level();
       useHelperThread(null);
       const alone = level();
       const same = ['heNext', 'heVertex', 'positions'].every((k) => helped[k].every((x, i) => Object.is(x, alone[k][i])));
       console.log(JSON.stringify({ shared: helped.heNext.buffer instanceof SharedArrayBuffer, alone: alone.heNext.buffer instanceof SharedArrayBuffer, same, problems: validate(helped).length }));`,
    );
    expect(JSON.parse(run('node', ['helper.mjs'], project))).toEqual({ shared: true, alone: false, same: true, problems: 0 });
  });

  it('ships type declarations that a strict TypeScript project accepts', () => {
    writeFileSync(
      join(project, 'use.ts'),
      `import { buildMesh, type HalfedgeMesh, installHelperThread, tetrahedron, vertexOutgoingHalfedges } from 'halfedge-lab';
       import type { PageSnapshot } from 'halfedge-lab/worker';
       installHelperThread({ minFaces: 100_000 });
       const mesh: HalfedgeMesh = buildMesh(tetrahedron()).mesh;
       const out: number[] = [...vertexOutgoingHalfedges(mesh, 0)];
       export const faces: PageSnapshot['stats']['faces'] = out.length;`,
    );
    writeFileSync(
      join(project, 'tsconfig.json'),
      JSON.stringify({ compilerOptions: { strict: true, module: 'nodenext', moduleResolution: 'nodenext', target: 'es2022', noEmit: true, skipLibCheck: false, lib: ['es2022', 'dom'], types: [] }, files: ['use.ts'] }),
    );
    expect(() => run(join(root, 'node_modules/.bin/tsc'), ['-p', 'tsconfig.json'], project)).not.toThrow();
  });

  it('installs the command line tool', () => {
    writeFileSync(join(project, 'cube.off'), 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n');
    const stats = JSON.parse(run(join(project, 'node_modules/.bin/halfedge-lab'), ['stats', 'cube.off', '--json'], project));
    expect(stats.mesh).toMatchObject({ vertices: 8, edges: 12, faces: 6, genus: 0, closed: true });
  });

  it('writes a course autograder with the grader built into the package', () => {
    writeFileSync(join(project, 'COURSE.json'), JSON.stringify({ exercises: [{ id: 'flip-edge', file: 'flip-edge.js', points: 5 }] }));
    const made = run(join(project, 'node_modules/.bin/halfedge-lab'), ['autograder', 'COURSE.json', '--out', 'autograder.zip'], project);
    expect(made).toContain('wrote autograder.zip: 1 exercise, 16 tests, 5 points');
    expect(existsSync(join(project, 'node_modules/halfedge-lab/dist/grader/grader.mjs'))).toBe(true);
    const names = readFileSync(join(project, 'autograder.zip')).toString('latin1');
    for (const name of ['setup.sh', 'run_autograder', 'grader.mjs', 'course.json']) expect(names).toContain(name);
  });

  it('bundles the worker subpath in a Vite app', () => {
    writeFileSync(join(project, 'index.html'), '<script type="module" src="./main.js"></script>');
    writeFileSync(join(project, 'main.js'), `import { SessionClient } from 'halfedge-lab/worker';\nwindow.client = new SessionClient();\n`);
    // pre-bundling would break the worker's new URL(…, import.meta.url): see the README
    writeFileSync(join(project, 'vite.config.js'), `export default { optimizeDeps: { exclude: ['halfedge-lab'] }, worker: { format: 'es' } };`);
    run(join(root, 'node_modules/.bin/vite'), ['build', '--logLevel', 'error'], project);
    const assets = readdirSync(join(project, 'dist/assets'));
    expect(assets.some((name) => /^session\.worker.*\.js$/.test(name))).toBe(true);
    expect(assets.some((name) => /^loader\.worker.*\.js$/.test(name))).toBe(true);
  });
});
