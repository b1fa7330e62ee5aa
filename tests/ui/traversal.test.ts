/**
 * The traversal panel plays what its code does: the code shown is the source of the function run,
 * and the steps played are the pointers that run read, on real meshes and on a broken one.
 */
import { describe, expect, it } from 'vitest';
import { buildMesh, disk, faceHalfedges, torus, vertexAdjacentFaces } from '../../src/index.js';
import { traversalCode, traversals } from '../../src/ui/panels/traversal.js';

/** A function's body as lines, indented by two spaces a level (as shown), without the body's own indentation. */
function bodyLines(source: string): string[] {
  const text = source.replace(/\t/g, '  ');
  const lines = text
    .slice(text.indexOf('{') + 1, text.lastIndexOf('}'))
    .split('\n')
    .filter((line) => line.trim() !== '');
  const indent = Math.min(...lines.map((line) => line.length - line.trimStart().length));
  return lines.map((line) => line.slice(indent).trimEnd());
}

const [faceLoop, vertexFan] = traversals;

describe('traversals', () => {
  it('show the code they run (the comments aside)', () => {
    expect(traversals).toHaveLength(traversalCode.length);
    traversals.forEach((traversal, i) => {
      const shown = traversal.code.map((line) => line.replace(/\s*\/\/.*$/, ''));
      expect(bodyLines(String(traversalCode[i]))).toEqual(shown);
    });
  });

  it("play a face's loop: every halfedge of it visited once, in order, ending back at the start", () => {
    const { mesh } = buildMesh(torus(6, 5));
    for (const f of [0, 7, 29]) {
      const steps = faceLoop.steps(mesh, { kind: 'face', id: f }, 'origin');
      if (typeof steps === 'string') throw new Error(steps);
      const last = steps.at(-1)!;
      expect(last.visited).toEqual([...faceHalfedges(mesh, f)]);
      expect(last).toMatchObject({ line: 5, done: true, h: mesh.faceHalfedge(f) });
      expect(steps.map((s) => s.line).slice(0, 8)).toEqual([0, 1, 2, 3, 4, 5, 2, 3]);
      // only the last test of the loop finds it back at the start
      expect(steps.filter((s) => s.done)).toHaveLength(1);
    }
  });

  it("play a boundary vertex's fan, the hole included, counter-clockwise", () => {
    const { mesh } = buildMesh(disk(2));
    const boundary = [...mesh.vertices()].find((v) => mesh.isBoundaryVertex(v))!;
    const steps = vertexFan.steps(mesh, { kind: 'vertex', id: boundary }, 'origin');
    if (typeof steps === 'string') throw new Error(steps);
    const visited = steps.at(-1)!.visited;
    expect(visited).toContain(-1);
    expect(new Set(visited.filter((f) => f >= 0))).toEqual(new Set(vertexAdjacentFaces(mesh, boundary)));
    // each move of h reads prev then twin, and shows as one step
    const moves = steps.filter((s) => s.line === 4);
    expect(moves).toHaveLength(visited.length);
    for (const step of moves) expect(mesh.origin(step.h)).toBe(boundary);
  });

  it("stop, saying so, on a face whose loop does not close", () => {
    const { mesh } = buildMesh(torus(6, 5));
    const h = mesh.faceHalfedge(3);
    // the loop's last halfedge points into another face's loop: it never comes back to h
    const other = mesh.faceHalfedge(10);
    mesh.heNext[mesh.prev(h)] = other;
    const steps = faceLoop.steps(mesh, { kind: 'face', id: 3 }, 'origin');
    expect(steps).toMatch(/did not come back to it within \d+ pointer reads/);
  });
});
