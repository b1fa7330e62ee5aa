/**
 * What a helper thread does with a level's topology steps (see `helper-thread.ts`): adopts the
 * shared arrays as a mesh, runs the steps of the scheme's phases straight through, and reports the
 * slot counts they leave.
 */
import type { SlotCounts } from '../mesh-arrays.js';
import { deserializeMesh } from '../serialize.js';
import { butterflyLevel } from './butterfly.js';
import { catmullClarkLevel } from './catmull-clark.js';
import type { TopologyTask } from './helper-thread.js';
import type { SchemeLevel } from './level.js';
import { linearLevel } from './linear.js';
import { loopLevel } from './loop.js';

/** The schemes a level of which is described for `level.ts` (√3's is not). */
const levels: Record<string, SchemeLevel> = { loop: loopLevel, butterfly: butterflyLevel, 'catmull-clark': catmullClarkLevel, linear: linearLevel };

export function runTopologyTask(task: TopologyTask): SlotCounts {
  if (!Object.hasOwn(levels, task.scheme)) throw new Error(`no topology steps for '${task.scheme}'`);
  const mesh = deserializeMesh(task.mesh);
  for (const phase of levels[task.scheme].phases) {
    if ('topology' in phase) phase.topology(mesh, false, task.oldVertices, task.work);
  }
  return { vertexSlots: mesh.vertexSlots, edgeSlots: mesh.edgeSlots, faceSlots: mesh.faceSlots };
}
