// What the view marks for a state of a real run: the writes of the wrong flip on its first fixture,
// and the reads of the one-ring solution.
import { describe, expect, it } from 'vitest';
import { whyNotDrawable } from '../../src/core/practice/drawable.js';
import { describeWrite, replayWrites } from '../../src/core/practice/writes.js';
import { colors } from '../../src/ui/colors.js';
import { readMarks, writeMarks } from '../../src/ui/practice-marks.js';
import { grade } from './helpers.js';

describe('the marks of a practice state', () => {
  it('marks the element each write stored and the one it now points to, labelling the last four', async () => {
    const { fixtures } = await grade('flip-edge', 'wrong/flip-forgets-vertex');
    const { before, writes } = fixtures[0];
    // writes 1–5 of a flip leave next and prev half-way: the view draws the fixture with all five marked
    const after5 = replayWrites(before.clone(), writes, 5);
    expect(whyNotDrawable(after5)).not.toBeNull();
    const marked = writes.slice(0, 5);
    const spec = writeMarks(before, marked);
    expect(spec.labels.map((l) => l.text)).toEqual(marked.slice(1).map(describeWrite).flatMap((text, i) => [text, `h${marked[i + 1].new}`]));
    for (const write of marked) {
      expect(spec.halfedges).toContainEqual(expect.objectContaining({ id: write.index, color: colors.selected }));
      const colour = write.field === 'next' ? colors.next : colors.prev;
      expect(spec.halfedges).toContainEqual(expect.objectContaining({ id: write.new, color: colour }));
    }
  });

  it('marks an origin write with the vertex, and skips elements the mesh drawn does not have', async () => {
    const { fixtures } = await grade('split-edge', 'split-edge');
    const { before, writes } = fixtures[0];
    const origin = writes.find((w) => w.field === 'origin')!;
    const atOrigin = writes.indexOf(origin);
    const state = replayWrites(before.clone(), writes, atOrigin + 1);
    const spec = writeMarks(state, [origin]);
    expect(spec.vertices).toEqual([{ id: origin.new, color: colors.origin }]);
    expect(spec.labels[0].text).toBe(describeWrite(origin));
    // on the fixture before the split, the new vertex and halfedge are not there: nothing is drawn for them
    const none = writeMarks(before, [origin]);
    expect(none.vertices).toEqual([]);
    expect(none.halfedges.every((h) => h.id < before.halfedgeSlots)).toBe(true);
  });

  it('marks the halfedges a query read, each once, and labels the current read', async () => {
    const { fixtures } = await grade('one-ring', 'one-ring');
    const { before, visits } = fixtures[0];
    expect(visits.length).toBeGreaterThan(3);
    const step = 3;
    const spec = readMarks(before, visits, step);
    const earlier = new Set(visits.slice(0, step));
    expect(spec.halfedges.filter((h) => h.color === colors.next).map((h) => h.id).sort()).toEqual([...earlier].sort());
    expect(spec.halfedges.at(-1)).toEqual({ id: visits[step], color: colors.selected });
    expect(spec.labels).toEqual([expect.objectContaining({ text: `read ${step + 1}: h${visits[step]}` })]);
  });
});
