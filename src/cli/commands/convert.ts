import { loadMesh, parseOptions, saveMesh } from '../io.js';
import type { Command } from './index.js';

export const convert: Command = {
  usage: 'convert IN OUT [--format ply|ply-binary|off|obj|glb|json]',
  summary: 'read, build (with repairs) and write; the format follows OUT',
  async run(args, reading) {
    const { values, positionals } = parseOptions(args, { format: { type: 'string' } }, 2);
    const { mesh } = await loadMesh(positionals[0]!, reading);
    await saveMesh(mesh, positionals[1]!, values.format);
    return 0;
  },
};
