import { describe, expect, it } from 'vitest';
import { buildMesh, decimation, loopSubdivision, type Phase, phaseElements, smoothing, uvSphere } from '../../src/index.js';
import { phaseHighlight, phaseMeanings } from '../../src/ui/highlights.js';
import { phaseColors } from '../../src/ui/colors.js';
import { PHASE_MARKS, type ShownPhase } from '../../src/workers/protocol.js';

const sphere = () => buildMesh(uvSphere(16, 24)).mesh;
/** A phase as the session shows it to the page. */
const shown = (phase: Phase): ShownPhase => ({ ...phase, ...phaseElements(phase.change!, PHASE_MARKS) });
const movedMarks = (mesh: ReturnType<typeof sphere>, phase: ShownPhase) => phaseHighlight(mesh, phase).vertices.filter((v) => v.color === phaseColors.moved);

describe('the marks of a phase', () => {
  it('leave the colours of a smoothing step to show how far each vertex moved, without a dot on every vertex', () => {
    const mesh = sphere();
    const phase = shown(smoothing(mesh, { method: 'laplacian', iterations: 1 }).next().value as Phase);
    expect(phase.movedCount).toBe(mesh.nVertices);
    expect(phase.values!.vertices!.length).toBe(mesh.vertexSlots);
    expect(movedMarks(mesh, phase)).toEqual([]);
  });

  it('mark the vertices a decimation pass moved, a few among many, beside its colours', () => {
    const mesh = sphere();
    const phases = decimation(mesh, { targetFaces: mesh.nFaces - 20 });
    let phase = shown(phases.next().value as Phase);
    while (!phase.moved.vertices) phase = shown(phases.next().value as Phase);
    const moved = phase.moved.vertices;
    expect(phase.values?.vertices).toBeDefined();
    expect(2 * moved.length).toBeLessThan(mesh.nVertices);
    expect(movedMarks(mesh, phase).map((v) => v.id)).toEqual([...moved].filter((v) => !mesh.vDeleted[v]));
  });
});

describe('the legend of a phase', () => {
  it('names only the colours its marks use', () => {
    const mesh = sphere();
    const smoothed = shown(smoothing(mesh, { method: 'laplacian', iterations: 1 }).next().value as Phase);
    expect(phaseMeanings(phaseHighlight(mesh, smoothed))).toEqual([]);
    const loop = buildMesh(uvSphere(8, 12)).mesh;
    const split = shown(loopSubdivision(loop).next().value as Phase);
    expect(phaseMeanings(phaseHighlight(loop, split))).toEqual(['created', 'rewired']);
  });
});
