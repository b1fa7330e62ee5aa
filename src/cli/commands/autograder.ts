/**
 * `autograder COURSE.json [--out autograder.zip]`: a Gradescope autograder for a course, as one
 * zip to upload (see docs/practice.md, "A course in a box"). It holds:
 *
 * ```
 * setup.sh          installs Node.js ≥ 20 when Gradescope builds the image (the only download)
 * run_autograder    runs the grader for each submission, with no network
 * grader.mjs        the grader and everything it needs, in one file (vite.grader.config.ts)
 * course.json       the course, an instructor's exercises pointing into exercises/
 * exercises/I-ID/   each instructor exercise: its .json, reference and fixture files
 * ```
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { basename, dirname, extname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { checkNames } from '../../core/practice/index.js';
import { type CourseEntry, loadCourse } from '../course.js';
import { parseOptions, readBytes, UsageError } from '../io.js';
import { writeZip, type ZipEntry } from '../zip.js';
import type { Command } from './index.js';

/** Run once as root when Gradescope builds the autograder's image. */
export const SETUP_SH = `#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (Ubuntu).
# The grader needs Node.js 20 or later and nothing else (grader.mjs holds all its code),
# so Node.js is the one thing fetched. Ubuntu's own package is older (12 on 22.04, 18 on
# 24.04): this takes the newest official Node.js 22 build and checks its SHA-256.
set -euo pipefail

# a Node.js new enough is already there: nothing to do
if command -v node >/dev/null && node -e 'process.exit(+process.versions.node.split(".")[0] >= 20 ? 0 : 1)'; then
  exit 0
fi

case "$(uname -m)" in
  x86_64) arch=x64 ;;
  aarch64) arch=arm64 ;;
  *) echo "setup.sh: no Node.js build for $(uname -m)" >&2; exit 1 ;;
esac
apt-get update -qq
apt-get install -y -qq --no-install-recommends ca-certificates curl xz-utils

cd "$(mktemp -d)"
base=https://nodejs.org/dist/latest-v22.x
curl -fsSL "$base/SHASUMS256.txt" | grep " node-v[0-9.]*-linux-$arch.tar.xz\\$" > SHASUMS256.txt
tarball=$(awk '{ print $2 }' SHASUMS256.txt)
curl -fsSLO "$base/$tarball"
sha256sum -c SHASUMS256.txt
mkdir -p /opt/node
tar -xJf "$tarball" -C /opt/node --strip-components=1 --no-same-owner
ln -sf /opt/node/bin/node /usr/local/bin/node
node --version
`;

/** Run by Gradescope for each submission. */
export const RUN_AUTOGRADER = `#!/usr/bin/env bash
# Gradescope runs this (copied to /autograder/run_autograder) for each submission, with no
# network: grader.mjs grades the files in $AUTOGRADER_ROOT/submission/ against course.json
# and writes $AUTOGRADER_ROOT/results/results.json (the root is /autograder on Gradescope).
set -eu
export AUTOGRADER_ROOT="\${AUTOGRADER_ROOT:-/autograder}"
exec node "$AUTOGRADER_ROOT/source/grader.mjs"
`;

export const autograderCommand: Command = {
  usage: 'autograder COURSE.json [--out autograder.zip]',
  summary: 'write a Gradescope autograder zip for a course: its exercises, the file each expects and its points',
  async run(args) {
    const { values, positionals } = parseOptions(args, { out: { type: 'string' } }, 1);
    const coursePath = positionals[0]!;
    const out = values.out ?? 'autograder.zip';
    const { exercises } = loadCourse(coursePath);

    const text = (s: string) => new TextEncoder().encode(s);
    const entries: ZipEntry[] = [
      { name: 'setup.sh', data: text(SETUP_SH), mode: 0o755 },
      { name: 'run_autograder', data: text(RUN_AUTOGRADER), mode: 0o755 },
      { name: 'grader.mjs', data: await graderBundle() },
    ];
    // the course as the grader reads it: an instructor's exercise moved into exercises/
    const course: { exercises: CourseEntry[] } = { exercises: [] };
    exercises.forEach(({ entry, exercise, source }, i) => {
      if (!source) return void course.exercises.push(entry);
      const folder = `exercises/${i}-${exercise.id.replace(/[^A-Za-z0-9._-]+/g, '-')}`;
      const file = `${folder}/${basename(source.path)}`;
      entries.push({ name: file, data: readBytes(source.path) });
      const inZip = new Set<string>();
      for (const name of source.names) {
        const path = name.split('/').filter((part) => part !== '.' && part !== '').join('/');
        if (inZip.has(path)) continue;
        inZip.add(path);
        entries.push({ name: `${folder}/${path}`, data: readBytes(join(dirname(source.path), name)) });
      }
      course.exercises.push({ exercise: file, file: entry.file, points: entry.points });
    });
    entries.push({ name: 'course.json', data: text(`${JSON.stringify(course, null, 2)}\n`) });

    try {
      writeFileSync(out, writeZip(entries));
    } catch (error) {
      throw new UsageError(`cannot write ${out}: ${(error as NodeJS.ErrnoException).code ?? (error as Error).message}`);
    }
    const points = exercises.reduce((sum, e) => sum + e.entry.points, 0);
    const tests = exercises.reduce((sum, e) => sum + checkNames(e.exercise).length, 0);
    const count = (n: number, what: string) => `${n} ${what}${n === 1 ? '' : 's'}`;
    console.log(`wrote ${out}: ${count(exercises.length, 'exercise')}, ${count(tests, 'test')}, ${count(Math.round(points * 100) / 100, 'point')} (the assignment's total on Gradescope)`);
    return 0;
  },
};

/**
 * The grader as one file. Installed, it is the one built with the package (`npm run build:grader`);
 * from source (`npm run cli`, tests), it is bundled now with Vite, a dev dependency, so the zip
 * holds this checkout's code.
 */
async function graderBundle(): Promise<Uint8Array> {
  if (extname(fileURLToPath(import.meta.url)) !== '.ts') {
    const built = new URL('../../grader/grader.mjs', import.meta.url);
    try {
      return readFileSync(built);
    } catch {
      throw new UsageError(`the grader ${fileURLToPath(built)} is missing: build it with npm run build:grader`);
    }
  }
  const { build } = await import('vite');
  const root = fileURLToPath(new URL('../../../', import.meta.url));
  const output = await build({ root, configFile: join(root, 'vite.grader.config.ts'), build: { write: false } });
  const chunks = (Array.isArray(output) ? output : [output]).flatMap((o) => ('output' in o ? o.output : [])).filter((o) => o.type === 'chunk');
  if (chunks.length !== 1) throw new Error(`the grader bundled into ${chunks.length} files, not one`);
  return new TextEncoder().encode(chunks[0]!.code);
}
