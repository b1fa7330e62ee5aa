/**
 * A fuzz target with planted faults, for the runner's own test: case 1 reports a failure, case 3
 * never ends, case 5 takes its process down; the others are refused or accepted.
 */
import type { FuzzTarget } from '../../fuzz/target.js';

export const targets: FuzzTarget[] = [
  {
    name: 'planted',
    runCase(_seed, index) {
      if (index === 1) return { kind: 'failure', reason: 'planted failure', input: 'case 1' };
      if (index === 3) for (;;); // a hang only the watchdog can end
      if (index === 5) process.abort(); // a death nothing in the process can catch
      return index % 2 === 0 ? { kind: 'accepted' } : { kind: 'refused', reason: 'odd' };
    },
  },
];
