/**
 * Practice mode's core: the mesh API a student's solution sees (every write logged with its line,
 * every read budgeted), the exercises, and the grading of a run against the library's own
 * operation. Where the solution runs (a sandbox worker) is the caller's; see `workers/practice-*`.
 */
export * from './broken-since.js';
export * from './compare.js';
export * from './exercise.js';
export * from './exercises.js';
export * from './grade.js';
export * from './grade-solution.js';
export * from './mesh-api.js';
export * from './run.js';
export * from './solution-error.js';
export * from './source.js';
export * from './what-to-fix.js';
export * from './writes.js';
export * from './drawable.js';
export * from './properties.js';
