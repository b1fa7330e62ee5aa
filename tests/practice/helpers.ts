/** Running solutions in this process (the sandbox's own code, without its worker or lock-down) and reading the test solutions. */
import { readFileSync } from 'node:fs';
import { serializeMesh } from '../../src/core/index.js';
import { findExercise, gradeSolution, type GradeReport, type RunOutput, SolutionError, type SolutionRunner } from '../../src/core/practice/index.js';
import { type SandboxMessage, serveRequest } from '../../src/workers/practice-sandbox.js';

export const inProcess: SolutionRunner = async (source, runs) => {
  const outputs: RunOutput[] = [];
  let refused: Extract<SandboxMessage, { kind: 'refused' }> | null = null;
  serveRequest({ source, runs: runs.map(({ mesh, input }) => ({ mesh: serializeMesh(mesh), input })) }, (message) => {
    if (message.kind === 'output') outputs.push(message.output);
    if (message.kind === 'refused') refused = message;
  });
  if (refused) throw new SolutionError((refused as { message: string }).message, (refused as { line: number | null }).line);
  return outputs;
};

/**
 * A test solution's source. A global operation builds on the local ones as a student's would: a
 * line `// with: split-edge as splitEdge, …` appends those solutions, each default export renamed.
 */
export function solution(name: string): string {
  const source = readFileSync(new URL(`./solutions/${name}.js`, import.meta.url), 'utf8');
  const uses = /^\/\/ with: (.*)$/m.exec(source)?.[1].split(', ') ?? [];
  return [source, ...uses.map((use) => {
    const [file, alias] = use.split(' as ');
    return solution(file).replace('export default function', `function ${alias}`);
  })].join('\n');
}

export function grade(exercise: string, solutionName: string): Promise<GradeReport> {
  return gradeSolution(findExercise(exercise)!, solution(solutionName), inProcess);
}

export function failures(report: GradeReport): string[] {
  return report.checks.filter((c) => !c.passed).map((c) => `${c.name} — ${c.message}`);
}
