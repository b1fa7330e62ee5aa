/** A solution that cannot be run: a syntax error, no default export, an import. Its own module: the page needs it without the parser. */
export class SolutionError extends Error {
  override readonly name = 'SolutionError';
  constructor(
    message: string,
    readonly line: number | null,
  ) {
    super(line === null ? message : `line ${line}: ${message}`);
  }
}
