import { describe, expect, it } from 'vitest';
import { buildMesh, disk, fan, seededRandom, torus } from '../../src/index.js';
import { hopsFor, isRight, makeQuestion } from '../../src/ui/quiz.js';
import { traversals } from '../../src/ui/panels/traversal.js';
import { breadcrumbText, elementName, isMove, MAX_BREADCRUMB_STEPS, type Selection, walk, type WalkStep } from '../../src/ui/selection.js';
import { decodeViewState, encodeViewState } from '../../src/ui/share.js';

describe('quiz questions', () => {
  it('ask where a path of pointers leads, and the answer is that walk', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const random = seededRandom(7);
    for (let i = 0; i < 200; i++) {
      const question = makeQuestion(mesh, random, 1 + (i % 5))!;
      expect(question.moves).toHaveLength(1 + (i % 5));
      let at = question.start;
      for (const move of question.moves) at = walk(mesh, at, move) as typeof at;
      expect(at).toEqual(question.answer);
      expect(question.text).toBe(`Which ${question.answer.kind} is h${question.start.id}.${question.moves.join('.')}?`);
      expect(isRight(question, question.answer)).toBe(true);
      expect(isRight(question, { kind: question.answer.kind, id: question.answer.id + 1 })).toBe(false);
    }
  });

  it('never asks for the face of a boundary halfedge', () => {
    const { mesh } = buildMesh(fan(3));
    const random = seededRandom(3);
    for (let i = 0; i < 300; i++) {
      const question = makeQuestion(mesh, random, 3)!;
      expect(question.path).toHaveLength(4);
      if (question.answer.kind === 'face') expect(question.answer.id).toBeGreaterThanOrEqual(0);
    }
  });

  it('under target naming, asks for targets, never origins, and the answer is the target', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const random = seededRandom(5);
    const vertexQuestions = Array.from({ length: 200 }, () => makeQuestion(mesh, random, 1, 'target')!).filter((q) => q.answer.kind === 'vertex');
    expect(vertexQuestions.length).toBeGreaterThan(10);
    for (const question of vertexQuestions) {
      expect(question.moves).toEqual(['target']);
      expect(question.answer.id).toBe(mesh.heVertex[mesh.heNext[question.start.id]]);
    }
  });

  it('starts the fan traversal at the vertex a selected halfedge names: its origin or its target', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const fanOf = traversals.find((t) => t.title === 'Faces around this vertex')!;
    for (const convention of ['origin', 'target'] as const) {
      const steps = fanOf.steps(mesh, { kind: 'halfedge', id: 7 }, convention);
      const v = convention === 'origin' ? mesh.heVertex[7] : mesh.heVertex[mesh.heNext[7]];
      expect(Array.isArray(steps) && mesh.heVertex[steps[0]!.h]).toBe(v);
    }
  });

  it('grows harder with the streak of right answers, up to five hops', () => {
    expect([0, 1, 2, 3, 4, 20].map(hopsFor)).toEqual([1, 1, 2, 2, 3, 5]);
  });

  it('replays the same questions from the same seed', () => {
    const { mesh } = buildMesh(disk(2));
    const a = makeQuestion(mesh, seededRandom(11), 3);
    const b = makeQuestion(mesh, seededRandom(11), 3);
    expect(a).toEqual(b);
  });
});

describe('share links', () => {
  it('round-trip the model, selection, naming, camera and mode', () => {
    const state = {
      model: 'torus.off',
      steps: [
        { kind: 'operation' as const, request: { kind: 'cut' as const, plane: [0, 0, 1, 0] as [number, number, number, number], keep: 'above' as const } },
        { kind: 'edit' as const, request: { kind: 'flip-edge' as const, edge: 3 } },
      ],
      selection: { kind: 'halfedge' as const, id: 17 },
      walk: ['next' as const, 'twin' as const, 'prev.twin' as const],
      naming: 'target' as const,
      camera: { position: [1, 2.5, -3], target: [0, 0, 0.25], zoom: 1.5, shift: [0.125, -0.0625] as [number, number] },
      mode: 'top' as const,
      exploded: true,
    };
    expect(decodeViewState(encodeViewState(state))).toEqual(state);
    expect(encodeViewState(state)).toMatch(/&explode=on$/);
    expect(decodeViewState(encodeViewState({ ...state, exploded: false }))).toEqual({ ...state, exploded: false });
    expect(decodeViewState('model=torus.off&explode=yes').exploded).toBe(false);
  });

  it('are written to be read: steps as calls with their settings, the walk as its moves, nothing percent-encoded', () => {
    const steps = [
      { kind: 'operation' as const, request: { kind: 'subdivide' as const, scheme: 'loop' as const, level: 0 } },
      { kind: 'operation' as const, request: { kind: 'cut' as const, plane: [0, 0.5, 1, -0.25] as [number, number, number, number], keep: 'both' as const, cap: false } },
      { kind: 'operation' as const, request: { kind: 'smooth' as const, options: { method: 'taubin' as const, iterations: 3, lambda: 0.5, mu: -0.53 } } },
      { kind: 'operation' as const, request: { kind: 'decimate' as const, options: { targetFaces: 100 } } },
      { kind: 'edit' as const, request: { kind: 'split-edge' as const, edge: 12, triangulate: true } },
      { kind: 'edit' as const, request: { kind: 'triangulate-mesh' as const } },
    ];
    const state = { model: 'torus.off', steps, selection: { kind: 'halfedge' as const, id: 4 }, walk: ['next' as const, 'twin.next' as const], naming: null, camera: { position: [1, 2, 3], target: [0, 0, 0], zoom: 1, shift: [0, 0] as [number, number] }, mode: null, exploded: false };
    const query = encodeViewState(state);
    expect(query).toBe(
      'model=torus.off&ops=subdivide(scheme:loop,level:0);cut(plane:0/0.5/1/-0.25,keep:both,cap:false);smooth(method:taubin,iterations:3,lambda:0.5,mu:-0.53);' +
        'decimate(targetFaces:100);split-edge(edge:12,triangulate:true);triangulate-mesh&select=h4&walk=next,twin.next&camera=1,2,3,0,0,0,1,0,0',
    );
    expect(decodeViewState(query)).toEqual(state);
  });

  it('open links written before, whose steps were JSON', () => {
    const steps = [{ kind: 'edit', request: { kind: 'flip-edge', edge: 3 } }];
    expect(decodeViewState(new URLSearchParams({ model: 'torus.off', ops: JSON.stringify(steps), select: 'h17' }).toString())).toMatchObject({ steps, selection: { kind: 'halfedge', id: 17 }, walk: [] });
  });

  it('leave out steps and walks that are not what they claim', () => {
    expect(decodeViewState('ops=flip-edge(edge:3);eval(alert(1))').steps).toEqual([]);
    expect(decodeViewState('ops=flip-edge(__proto__:3)').steps).toEqual([]);
    expect(decodeViewState('select=h1&walk=next,sideways').walk).toEqual([]);
  });

  it('read a link made before the camera kept its shift as one whose target is in the middle', () => {
    expect(decodeViewState('camera=1,2,3,0,0,0,1').camera).toEqual({ position: [1, 2, 3], target: [0, 0, 0], zoom: 1, shift: [0, 0] });
  });

  it('drop what is malformed instead of trusting it', () => {
    expect(decodeViewState('model=cube.off&ops=[{"kind":"eval"}]&select=x9&naming=tail&camera=1,2,nan&mode=sideways&explode=1')).toEqual({
      model: 'cube.off',
      steps: [],
      selection: null,
      walk: [],
      naming: null,
      camera: null,
      mode: null,
      exploded: false,
    });
  });
});

describe('the breadcrumb', () => {
  it('shows a short walk whole, and a long one as its start, how many steps are left out, and its last steps', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const path: WalkStep[] = [{ move: null, to: { kind: 'halfedge', id: 0 } }];
    for (let i = 0; i < 3; i++) path.push({ move: 'next', to: walk(mesh, path[path.length - 1]!.to, 'next') as Selection });
    expect(breadcrumbText(path)).toBe(`h0 → next → ${path.slice(1).map((s) => elementName(s.to)).join(' → next → ')}`);
    for (let i = 0; i < 20; i++) path.push({ move: 'twin', to: walk(mesh, path[path.length - 1]!.to, 'twin') as Selection });
    const text = breadcrumbText(path);
    expect(text.startsWith(`h0 → … ${path.length - MAX_BREADCRUMB_STEPS} steps … → twin → `)).toBe(true);
    // the start, the gap, and the last MAX − 1 steps
    expect(text.split(' → ')).toHaveLength(2 + 2 * (MAX_BREADCRUMB_STEPS - 1));
    expect(text.endsWith(elementName(path[path.length - 1]!.to))).toBe(true);
    // presentation mode's shorter form: the start, the gap and the last three steps
    expect(breadcrumbText(path, 4).split(' → ')).toHaveLength(2 + 2 * 3);
  });

  it('never leaves out a single step: it would take as much room as saying it', () => {
    const { mesh } = buildMesh(torus(6, 5));
    const path: WalkStep[] = [{ move: null, to: { kind: 'halfedge', id: 0 } }];
    for (let i = 0; i < MAX_BREADCRUMB_STEPS; i++) path.push({ move: 'next', to: walk(mesh, path[path.length - 1]!.to, 'next') as Selection });
    expect(breadcrumbText(path)).not.toContain('…');
    path.push({ move: 'twin', to: walk(mesh, path[path.length - 1]!.to, 'twin') as Selection });
    expect(breadcrumbText(path)).toContain('… 2 steps …');
  });

  it('follows only the record fields that are pointers', () => {
    expect(['next', 'origin', 'target', 'halfedge', 'edge'].every(isMove)).toBe(true);
    expect(['position', 'degree', 'boundary', ''].some(isMove)).toBe(false);
  });
});
