/**
 * Running solutions in this process (the sandbox's own code, without its worker or lock-down),
 * reading the test solutions, and the first-broken search as it first was, to hold the grader's to.
 */
import { readFileSync } from 'node:fs';
import { type HalfedgeMesh, serializeMesh, validate, type Violation } from '../../src/core/index.js';
import { applyWrite, findExercise, gradeSolution, type GradeReport, keyOf, type PracticeWrite, replayWriter, type RunOutput, SolutionError, type SolutionRunner } from '../../src/core/practice/index.js';
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

/**
 * `brokenSince` the slow way, as the grader first did it: `validate` the whole mesh after every
 * write and note when each final violation began to fail. The oracle for the grader's search
 * (it costs the writes times the mesh, so only for small fixtures).
 */
export function brokenSinceByValidating(before: HalfedgeMesh, writes: readonly PracticeWrite[], final: readonly Violation[]): number[] {
  const wanted = new Set(final.map(keyOf));
  const failingIn = (mesh: HalfedgeMesh) => new Set(validate(mesh, { limit: Infinity }).map(keyOf).filter((key) => wanted.has(key)));
  const onset = new Map<string, number>();
  let failing = failingIn(before);
  for (const key of failing) onset.set(key, -1);
  const mesh = before.clone();
  const writer = replayWriter(mesh);
  writes.forEach((write, i) => {
    applyWrite(writer, write);
    const now = failingIn(mesh);
    for (const key of now) if (!failing.has(key)) onset.set(key, i);
    failing = now;
  });
  return final.map((v) => onset.get(keyOf(v))!);
}
