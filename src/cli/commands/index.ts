/** The CLI's commands, by name. Each lives in its own file. */
import { autograderCommand } from './autograder.js';
import { convert } from './convert.js';
import { cutCommand } from './cut.js';
import { decimateCommand } from './decimate.js';
import { gradeCommand } from './grade.js';
import { remeshCommand } from './remesh.js';
import { smoothCommand } from './smooth.js';
import { stats } from './stats.js';
import { subdivideCommand } from './subdivide.js';
import { validateCommand } from './validate.js';

import type { ReadSettings } from '../io.js';

export interface Command {
  usage: string;
  summary: string;
  /** Returns the exit status. `reading`: how to read the input mesh (options every command takes). */
  run(args: string[], reading?: ReadSettings): number | Promise<number>;
}

export const commands: Record<string, Command> = {
  stats,
  validate: validateCommand,
  convert,
  subdivide: subdivideCommand,
  cut: cutCommand,
  smooth: smoothCommand,
  decimate: decimateCommand,
  remesh: remeshCommand,
  grade: gradeCommand,
  autograder: autograderCommand,
};
