/**
 * Everything about changing a mesh: the writer every write goes through, the record it keeps, the
 * pointer diff read off the record, and the phases of the operations that carry one each.
 */
export * from './diff.js';
export * from './operation.js';
export * from './record.js';
export * from './recorder.js';
export * from './writer.js';
