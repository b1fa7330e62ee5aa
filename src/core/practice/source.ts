/**
 * A solution as the student writes it: a module whose default export is the function
 * (`export default function (mesh, input) { … }`). It is parsed first (acorn), so a syntax error
 * is reported at its line and column, and a solution that imports anything is refused before it
 * runs: everything it needs is the mesh API. Then it is compiled as the body of a function, with
 * `export default` become an assignment in place, so every line the engine reports is the
 * student's own.
 */
import { parse, type Node } from 'acorn';
import { SolutionError } from './solution-error.js';

/** The file name the engine gives the solution's frames (`//# sourceURL`), so stacks name its lines. */
export const SOLUTION_FILE = 'solution.js';

/** A stack frame of the solution: its line and column. */
const SOLUTION_FRAME = new RegExp(`${SOLUTION_FILE.replace('.', '\\.')}:(\\d+):\\d+`);

/** The variable the default export is assigned to in the compiled body. */
const DEFAULT_EXPORT = '__solution';

/**
 * The body of a function that evaluates the solution and returns its default export.
 * @throws SolutionError for a syntax error, an import, an export other than one default.
 */
export function solutionBody(source: string): string {
  let program: Node & { body: Node[] };
  try {
    program = parse(source, { ecmaVersion: 'latest', sourceType: 'module', locations: true }) as Node & { body: Node[] };
  } catch (error) {
    const { loc } = error as { loc?: { line: number; column: number } };
    const message = (error as Error).message.replace(/\s*\(\d+:\d+\)$/, '');
    throw new SolutionError(`syntax error: ${message}${loc ? ` (column ${loc.column + 1})` : ''}`, loc?.line ?? null);
  }
  const forbidden = findImport(program);
  if (forbidden) throw new SolutionError('a solution cannot import anything: everything it needs is the mesh API', forbidden.loc!.start.line);
  const exports = program.body.filter((node) => node.type.startsWith('Export'));
  // (the parser itself refuses a second default export)
  const defaults = exports.filter((node) => node.type === 'ExportDefaultDeclaration') as (Node & { declaration: Node })[];
  const other = exports.find((node) => node.type !== 'ExportDefaultDeclaration');
  if (other) throw new SolutionError('only `export default` is understood: export the function as the default', other.loc!.start.line);
  if (defaults.length === 0) throw new SolutionError('no `export default`: write `export default function (mesh, input) { … }`', null);
  const { start, declaration } = defaults[0];
  const body = `${source.slice(0, start)}${DEFAULT_EXPORT} = ${source.slice(declaration.start)}`;
  // the declaration and the return sit on the first and last lines, so line numbers stay the student's
  return `"use strict"; let ${DEFAULT_EXPORT}; ${body}\n;return ${DEFAULT_EXPORT};\n//# sourceURL=${SOLUTION_FILE}`;
}

/** The first `import` declaration, `import(…)` or `import.meta` anywhere in the tree. */
function findImport(node: unknown): Node | null {
  if (!node || typeof node !== 'object') return null;
  if (Array.isArray(node)) {
    for (const child of node) {
      const found = findImport(child);
      if (found) return found;
    }
    return null;
  }
  const typed = node as Node;
  const isImportMeta = typed.type === 'MetaProperty' && (typed as Node & { meta: { name: string } }).meta.name === 'import';
  if (typed.type === 'ImportDeclaration' || typed.type === 'ImportExpression' || isImportMeta) return typed;
  for (const [key, value] of Object.entries(node)) {
    if (key === 'loc' || typeof value !== 'object') continue;
    const found = findImport(value);
    if (found) return found;
  }
  return null;
}

/**
 * The solution's line in a stack trace: the first frame in `SOLUTION_FILE`, minus `offset` (the
 * lines the engine puts before a compiled body). Null when no frame is the solution's.
 */
export function solutionLine(stack: string | undefined, offset: number): number | null {
  if (!stack) return null;
  const match = SOLUTION_FRAME.exec(stack);
  return match ? Number(match[1]) - offset : null;
}

/** Frames of the mesh API above the solution's at a write: this function, the line getter, the log, the write, the method. */
const API_FRAMES = 6;

/** A frame as V8 hands it to `Error.prepareStackTrace`, reduced to what is read here. */
interface CallSite {
  /** The file, or for compiled code the name its `//# sourceURL` gives. */
  getScriptNameOrSourceURL(): string | null | undefined;
  getLineNumber(): number | null;
}

/**
 * The solution's line the code is at now (as `solutionLine` of a stack taken here). V8 hands the
 * stack over as call sites when asked to, which costs a small part of formatting it as text (and,
 * where source maps are on, of mapping every frame): a write logs its line this way, and a
 * subdivision's trace has a million writes. Other engines give the text, read by `solutionLine`.
 */
export function currentSolutionLine(offset: number): number | null {
  const [prepare, limit] = [Reflect.get(Error, 'prepareStackTrace'), Reflect.get(Error, 'stackTraceLimit')];
  // Reflect.set: a solution that froze Error gets its lines from the text, not an exception
  const structured = Reflect.set(Error, 'prepareStackTrace', (_error: Error, sites: CallSite[]) => sites);
  // the solution's frame is the first below the mesh API's few (or below a built-in that called
  // the API back, as forEach does): no need to take more
  Reflect.set(Error, 'stackTraceLimit', API_FRAMES + 2);
  const stack: unknown = new Error().stack;
  Reflect.set(Error, 'stackTraceLimit', limit);
  if (structured) Reflect.set(Error, 'prepareStackTrace', prepare);
  if (typeof stack === 'string' || !Array.isArray(stack)) return solutionLine(typeof stack === 'string' ? stack : undefined, offset);
  for (const site of stack as CallSite[]) {
    const line = site.getScriptNameOrSourceURL() === SOLUTION_FILE ? site.getLineNumber() : null;
    if (line !== null) return line - offset;
  }
  return null;
}
