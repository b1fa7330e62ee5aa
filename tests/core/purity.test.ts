import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join, relative } from 'node:path';
import { describe, expect, it } from 'vitest';

const coreDir = join(import.meta.dirname, '../../src/core');
/** Packages the core may use: pure JavaScript, no DOM. */
const allowedPackages = new Set(['earcut', 'acorn', '@gltf-transform/core', '@gltf-transform/extensions', 'meshoptimizer/decoder']);

function sourceFiles(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sourceFiles(path) : path.endsWith('.ts') ? [path] : [];
  });
}

const imports = (source: string) => [...source.matchAll(/(?:import|export)[^'"]*?from\s+['"]([^'"]+)['"]|import\(\s*['"]([^'"]+)['"]\s*\)/g)].map((m) => m[1] ?? m[2]!);

describe('the core import graph', () => {
  const files = sourceFiles(coreDir);

  it('has source files to check', () => {
    expect(files.length).toBeGreaterThan(5);
  });

  it.each(files.map((f) => [relative(coreDir, f), f]))('%s imports only the core and allowed packages', (_, file) => {
    const source = readFileSync(file, 'utf8');
    for (const specifier of imports(source)) {
      if (specifier.startsWith('.')) {
        const target = join(file, '..', specifier);
        expect(relative(coreDir, target).startsWith('..'), `${specifier} leaves src/core`).toBe(false);
      } else {
        expect(allowedPackages.has(specifier), `package '${specifier}'`).toBe(true);
      }
    }
    // no browser or Node globals either (the core tsconfig has neither in its lib)
    expect(source).not.toMatch(/\b(document|window|navigator|process|require)\s*[.(]/);
  });
});
