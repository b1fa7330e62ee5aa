import { meshStats, type Repair, validate } from '../../index.js';
import { type LoadedMesh, loadMesh, parseOptions } from '../io.js';
import type { Command } from './index.js';

/** The `stats --json` document: what the file held, what the mesh is, what was repaired. */
export function statsDocument(loaded: LoadedMesh) {
  const { file, mesh, report } = loaded;
  const { faceDegrees, componentDetails, ...counts } = meshStats(mesh, report);
  return {
    file: loaded.path,
    format: file.format,
    encoding: file.encoding,
    input: { vertices: file.counts.vertices, faces: file.counts.faces },
    mesh: counts,
    faceDegrees,
    components: componentDetails,
    repairs: report.repairs.map(flattenRepair),
    problems: validate(mesh),
    comments: file.comments,
    notes: file.notes,
  };
}

/** A repair with the ids of all its listed incidents gathered by kind of element. */
function flattenRepair(repair: Repair) {
  const ids = (key: 'vertices' | 'faces' | 'inputVertices' | 'inputFaces') => [
    ...new Set(repair.incidents.flatMap((i) => i[key] ?? [])),
  ];
  return {
    kind: repair.kind,
    count: repair.count,
    message: repair.message,
    vertices: ids('vertices'),
    faces: ids('faces'),
    inputVertices: ids('inputVertices'),
    inputFaces: ids('inputFaces'),
    incidents: repair.incidents.map((i) => i.message),
  };
}

export const stats: Command = {
  usage: 'stats FILE [--json]',
  summary: 'counts, topology (χ, genus, boundary loops), repairs and what the reader noted',
  async run(args, reading) {
    const { values, positionals } = parseOptions(args, { json: { type: 'boolean' } }, 1);
    const doc = statsDocument(await loadMesh(positionals[0]!, reading));
    if (values.json) {
      console.log(JSON.stringify(doc, null, 2));
      return 0;
    }
    const m = doc.mesh;
    const rows: Array<[string, unknown]> = [
      ['file', `${doc.file} (${doc.format}, ${doc.encoding})`],
      ['in the file', `${doc.input.vertices} vertices, ${doc.input.faces} faces`],
      ['mesh', `V ${m.vertices}, E ${m.edges}, F ${m.faces}, halfedges ${m.halfedges}`],
      ['Euler characteristic', `χ = V − E + F = ${m.eulerCharacteristic}`],
      ['genus', m.genus ?? 'undefined (non-orientable or no faces)'],
      ['boundary loops', m.boundaryLoops],
      ['components', `${m.components}${m.isolatedVertices ? ` (+ ${m.isolatedVertices} isolated vertices)` : ''}`],
      ['closed / manifold / orientable', `${m.closed} / ${m.manifold} / ${m.orientable}`],
      ['face degrees', Object.entries(doc.faceDegrees).map(([d, n]) => `${n}×${d}`).join(', ') || 'none'],
      ['surface area', m.surfaceArea],
      ['volume', m.volume ?? '(open mesh)'],
    ];
    for (const [label, value] of rows) console.log(`${label.padEnd(32)} ${value}`);
    for (const r of doc.repairs) console.log(`repair: ${r.message}`);
    for (const n of doc.notes) console.log(`note: ${n}`);
    for (const p of doc.problems) console.log(`problem: ${p.message}`);
    return 0;
  },
};
