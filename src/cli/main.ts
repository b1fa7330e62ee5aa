#!/usr/bin/env node
/**
 * The command line: `halfedge-lab COMMAND [options]` (or `npm run cli -- COMMAND …` in the repo).
 *
 * Exit status: 0 done, 1 the command ran but found problems (e.g. `validate` on a mesh that
 * needed repairs), 2 a bad file or bad arguments, with one line on stderr saying what and where.
 */
import { installHelperThread } from '../node/helper-thread.js';
import { commands } from './commands/index.js';
import { reportFailure, takeReadSettings, UsageError } from './io.js';

// as a program of the library's users would, through its Node entry
installHelperThread();

function usage(): string {
  const lines = Object.values(commands).map((c) => `  ${c.usage.padEnd(58)} ${c.summary}`);
  const reading = `  ${'--weld-tolerance D'.padEnd(58)} weld STL and glTF vertices within D (default: equal positions only)`;
  return ['usage: halfedge-lab COMMAND [options]', '', 'commands:', ...lines, '', 'every command that reads a mesh also takes:', reading].join('\n');
}

async function main(argv: string[]): Promise<number> {
  const [name, ...rest] = argv;
  if (!name || name === '--help' || name === '-h' || name === 'help') {
    console.log(usage());
    return name ? 0 : 2;
  }
  const command = commands[name];
  if (!command) throw new UsageError(`unknown command '${name}' (try --help)`);
  const { settings, rest: args } = takeReadSettings(rest);
  return command.run(args, settings);
}

main(process.argv.slice(2)).then(
  (status) => {
    process.exitCode = status;
  },
  (error: unknown) => {
    process.exitCode = reportFailure(error);
  },
);
