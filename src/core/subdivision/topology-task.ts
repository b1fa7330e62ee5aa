/**
 * What a helper thread does with a level's topology steps (see `helper-thread.ts`): adopts the
 * shared arrays as a mesh, runs the scheme's steps straight through, and reports the slot counts
 * they leave.
 */
import type { SlotCounts } from '../mesh-arrays.js';
import { deserializeMesh } from '../serialize.js';
import { catmullClarkSteps } from './catmull-clark.js';
import type { HelpedScheme, TopologyStep, TopologyTask } from './helper-thread.js';
import { loopSteps } from './loop.js';

const stepsOf: Record<HelpedScheme, readonly TopologyStep[]> = { loop: loopSteps, 'catmull-clark': catmullClarkSteps };

export function runTopologyTask(task: TopologyTask): SlotCounts {
  if (!Object.hasOwn(stepsOf, task.scheme)) throw new Error(`no topology steps for '${task.scheme}'`);
  const steps = stepsOf[task.scheme];
  const mesh = deserializeMesh(task.mesh);
  for (const step of steps) step(mesh, false, task.oldVertices, task.fanWork);
  return { vertexSlots: mesh.vertexSlots, edgeSlots: mesh.edgeSlots, faceSlots: mesh.faceSlots };
}
