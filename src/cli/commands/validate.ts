import { validate } from '../../index.js';
import { loadMesh, parseOptions } from '../io.js';
import type { Command } from './index.js';

export const validateCommand: Command = {
  usage: 'validate FILE',
  summary: 'exit 0 if the file is a clean halfedge mesh, 1 listing what had to be repaired',
  async run(args, reading) {
    const { positionals } = parseOptions(args, {}, 1);
    const { file, mesh, report } = await loadMesh(positionals[0]!, reading);
    const problems = validate(mesh);
    // what the reader dropped or skipped (a normal that was NaN): said, but the mesh is not unclean for it
    for (const note of file.notes) console.log(`note: ${note}`);
    for (const repair of report.repairs) {
      console.log(`${repair.kind}: ${repair.message}`);
      for (const incident of repair.incidents.slice(0, 20)) console.log(`  ${incident.message}`);
      if (repair.count > 20) console.log(`  … and ${repair.count - 20} more`);
    }
    for (const problem of problems) console.log(`invariant ${problem.invariant}: ${problem.message}`);
    const clean = report.repairs.length === 0 && problems.length === 0;
    console.log(clean ? 'ok: a clean, manifold, oriented mesh' : 'not clean: see above');
    return clean ? 0 : 1;
  },
};
