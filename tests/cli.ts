/** The command line run as a user runs it: a child process of its own. */
import { execFile } from 'node:child_process';
import { join } from 'node:path';

export interface CliRun {
  status: number;
  stdout: string;
  stderr: string;
  ms: number;
}

const repo = join(import.meta.dirname, '..');

/** `halfedge-lab ARGS…`, from the sources (about a second); its exit status and output. */
export function runCli(...args: string[]): Promise<CliRun> {
  const started = Date.now();
  return new Promise((resolve) => {
    // the project's own tsx, not through npx, which took as long again to find it
    execFile(join(repo, 'node_modules/.bin/tsx'), ['src/cli/main.ts', ...args], { cwd: repo, timeout: 60_000 }, (error, stdout, stderr) => {
      resolve({ status: error ? ((error as { code?: number }).code ?? -1) : 0, stdout, stderr, ms: Date.now() - started });
    });
  });
}
