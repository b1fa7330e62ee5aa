/** The README's library example runs as written (against this checkout's sources). */
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { expect, it } from 'vitest';

const root = join(import.meta.dirname, '..');

it('runs the library example of the README', () => {
  const readme = readFileSync(join(root, 'README.md'), 'utf8');
  const example = /## The library\s+```ts\n([\s\S]*?)```/.exec(readme)?.[1];
  expect(example).toBeDefined();
  const folder = mkdtempSync(join(tmpdir(), 'readme-'));
  try {
    copyFileSync(join(root, 'public/models/bunny.ply'), join(folder, 'bunny.ply'));
    const source = example!.replace("from 'halfedge-lab'", `from '${join(root, 'src/index.ts')}'`);
    writeFileSync(join(folder, 'example.ts'), source);
    const output = execFileSync(join(root, 'node_modules/.bin/tsx'), ['example.ts'], { cwd: folder, encoding: 'utf8' });
    expect(output).toContain('[]'); // validate found nothing
    expect(output.trim().split('\n').length).toBeGreaterThan(3); // the one-ring was printed
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
});
