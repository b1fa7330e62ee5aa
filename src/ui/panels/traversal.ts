/**
 * Traversal animations with their code beside them: "halfedges of this face" and "faces around
 * this vertex" play one step at a time, highlighting the current line of a short `do … while`
 * loop and the element it is looking at. Play, pause, step, speed.
 */
import type { HalfedgeMesh } from '../../core/index.js';
import { colors } from '../colors.js';
import { el, replace } from '../dom.js';
import type { Convention } from '../records.js';
import { emptyHighlight, type HighlightSpec } from '../scene/highlight.js';
import type { Selection } from '../selection.js';

interface TraversalStep {
  line: number;
  /** The halfedge `h` holds at this step. */
  h: number;
  /** What has been visited so far. */
  visited: number[];
  done: boolean;
}

export interface Traversal {
  title: string;
  /** The code shown, line by line: the source of the function the traversal runs. */
  code: string[];
  /** The steps from the selection, or why it cannot start; a selected halfedge stands for the vertex the naming names. */
  steps(mesh: HalfedgeMesh, selection: Selection, convention: Convention): TraversalStep[] | string;
  /** Kind of element `visit` collects. */
  visits: 'halfedge' | 'face';
}

/** The part of the mesh's API the traversals' code calls. */
type Navigation = Pick<HalfedgeMesh, 'faceHalfedge' | 'vertexHalfedge' | 'next' | 'prev' | 'twin' | 'face'>;

/*
 * The code each traversal shows is the code it runs: these two functions, whose source a test
 * compares with the lines shown. They run on a stand-in for the mesh that notes every pointer read
 * (and gives up after a bound, on a mesh whose loop does not close), and the steps played are
 * what the run did.
 */
function halfedgesOfFace(mesh: Navigation, f: number, visit: (h: number) => void): void {
  const start = mesh.faceHalfedge(f);
  let h = start;
  do {
    visit(h);
    h = mesh.next(h);
  } while (h !== start);
}

function facesAroundVertex(mesh: Navigation, v: number, visit: (f: number) => void): void {
  const start = mesh.vertexHalfedge(v);
  let h = start;
  do {
    visit(mesh.face(h)); // -1: the hole beside a boundary vertex
    h = mesh.twin(mesh.prev(h)); // counter-clockwise
  } while (h !== start);
}

const faceLoop: Traversal = {
  title: 'Halfedges of this face',
  visits: 'halfedge',
  code: [
    'const start = mesh.faceHalfedge(f);',
    'let h = start;',
    'do {',
    '  visit(h);',
    '  h = mesh.next(h);',
    '} while (h !== start);',
  ],
  steps(mesh, selection) {
    const f = selection.kind === 'face' ? selection.id : selection.kind === 'halfedge' ? mesh.face(selection.id) : -1;
    if (f < 0) return 'select a face (or a halfedge of one) first';
    return recordRun(mesh, (navigation, visit) => halfedgesOfFace(navigation, f, visit));
  },
};

const vertexFan: Traversal = {
  title: 'Faces around this vertex',
  visits: 'face',
  code: [
    'const start = mesh.vertexHalfedge(v);',
    'let h = start;',
    'do {',
    '  visit(mesh.face(h)); // -1: the hole beside a boundary vertex',
    '  h = mesh.twin(mesh.prev(h)); // counter-clockwise',
    '} while (h !== start);',
  ],
  steps(mesh, selection, convention) {
    const named = (h: number) => (convention === 'origin' ? mesh.origin(h) : mesh.target(h));
    const v = selection.kind === 'vertex' ? selection.id : selection.kind === 'halfedge' ? named(selection.id) : -1;
    if (v < 0) return `select a vertex (or a halfedge ${convention === 'origin' ? 'leaving' : 'arriving at'} one) first`;
    if (mesh.vertexHalfedge(v) < 0) return `v${v} is isolated: no faces around it`;
    return recordRun(mesh, (navigation, visit) => facesAroundVertex(navigation, v, visit));
  },
};

export const traversals = [faceLoop, vertexFan];
/** The functions the traversals run, in the order of `traversals` (for the test that their source is the code shown). */
export const traversalCode = [halfedgesOfFace, facesAroundVertex];

/** The run read more pointers than a closing loop could: the mesh's loop does not close. */
class Unclosed extends Error {}

/**
 * Runs a traversal's code on a stand-in for `mesh` and turns what it did into the steps played:
 * the start read (lines 0 and 1), each visit (lines 2 and 3), each move of `h` (line 4: a move
 * may read several pointers) and the loop's test (line 5).
 */
function recordRun(mesh: HalfedgeMesh, run: (navigation: Navigation, visit: (id: number) => void) => void): TraversalStep[] | string {
  const steps: TraversalStep[] = [];
  const visited: number[] = [];
  let start = -1;
  let h = -1;
  let moving = false;
  let reads = 0;
  const read = (value: number) => {
    if (++reads > 3 * mesh.halfedgeSlots + 4) throw new Unclosed();
    return value;
  };
  const begin = (value: number) => {
    start = h = read(value);
    steps.push({ line: 0, h, visited: [], done: false }, { line: 1, h, visited: [], done: false });
    return value;
  };
  const move = (value: number) => {
    moving = true;
    h = read(value);
    return value;
  };
  /** Ends the move being made: `h` holds where it led, and the loop tests it. */
  const endMove = () => {
    if (!moving) return;
    moving = false;
    steps.push({ line: 4, h, visited: [...visited], done: false }, { line: 5, h, visited: [...visited], done: h === start });
  };
  const navigation: Navigation = {
    faceHalfedge: (f) => begin(mesh.faceHalfedge(f)),
    vertexHalfedge: (v) => begin(mesh.vertexHalfedge(v)),
    next: (g) => move(mesh.next(g)),
    prev: (g) => move(mesh.prev(g)),
    twin: (g) => move(mesh.twin(g)),
    // a face read to visit it is not a move of h
    face: (g) => read(mesh.face(g)),
  };
  const visit = (id: number) => {
    endMove();
    steps.push({ line: 2, h, visited: [...visited], done: false });
    visited.push(id);
    steps.push({ line: 3, h, visited: [...visited], done: false });
  };
  try {
    run(navigation, visit);
  } catch (error) {
    if (!(error instanceof Unclosed)) throw error;
    return `the loop from h${start} did not come back to it within ${reads} pointer reads: the mesh's pointers are broken here`;
  }
  endMove();
  return steps;
}

/** What to light up at a step: the halfedge `h` and everything visited so far. */
export function traversalHighlight(traversal: Traversal, step: TraversalStep): HighlightSpec {
  const spec = emptyHighlight();
  for (const id of step.visited) {
    if (traversal.visits === 'face' && id >= 0) spec.faces.push({ id, color: colors.face });
    if (traversal.visits === 'halfedge') spec.halfedges.push({ id, color: colors.next });
  }
  spec.halfedges.push({ id: step.h, color: colors.selected });
  return spec;
}

export class TraversalPanel {
  private traversal: Traversal | null = null;
  private steps: TraversalStep[] = [];
  private index = 0;
  private timer: ReturnType<typeof setInterval> | null = null;
  private speed = 5; // steps per second: a vertex's fan of six faces plays in about five seconds
  private readonly code = el('pre', { class: 'code', 'aria-label': 'Traversal code' });
  private readonly message = el('p', { class: 'note', role: 'status' });
  private readonly playButton = el('button', { type: 'button', 'aria-label': 'Play traversal', onclick: () => this.toggle() }, 'Play');

  constructor(
    container: HTMLElement,
    private readonly context: () => { mesh: HalfedgeMesh | null; selection: Selection | null; convention: Convention },
    private readonly show: (spec: HighlightSpec | null) => void,
  ) {
    const choose = el(
      'div',
      { class: 'traversal-choice' },
      ...traversals.map((t, i) =>
        el('button', { type: 'button', 'data-traversal': String(i), 'aria-label': `Start traversal: ${t.title}`, onclick: () => this.begin(t) }, t.title),
      ),
    );
    const controls = el(
      'div',
      { class: 'traversal-controls' },
      this.playButton,
      el('button', { type: 'button', 'aria-label': 'Step traversal', onclick: () => this.advance() }, 'Step'),
      el('button', { type: 'button', 'aria-label': 'Stop traversal', onclick: () => this.stop() }, 'Stop'),
      el(
        'label',
        {},
        'Speed ',
        el('input', {
          type: 'range',
          min: '0.5',
          max: '8',
          step: '0.5',
          value: String(this.speed),
          'aria-label': 'Traversal speed (steps per second)',
          oninput: (event: Event) => {
            this.speed = Number((event.target as HTMLInputElement).value);
            if (this.timer) this.play();
          },
        }),
      ),
    );
    replace(container, choose, this.code, controls, this.message);
  }

  /** Starts `traversal` at the current selection. */
  begin(traversal: Traversal): void {
    this.pause();
    const { mesh, selection, convention } = this.context();
    if (!mesh || !selection) {
      this.message.textContent = 'Select an element first.';
      return;
    }
    const steps = traversal.steps(mesh, selection, convention);
    if (typeof steps === 'string') {
      this.message.textContent = steps;
      return;
    }
    this.traversal = traversal;
    this.steps = steps;
    this.index = 0;
    this.render();
  }

  advance(): void {
    if (!this.traversal) return;
    if (this.index + 1 < this.steps.length) this.index++;
    else this.pause();
    this.render();
  }

  toggle(): void {
    if (this.timer) this.pause();
    else this.play();
  }

  play(): void {
    if (!this.traversal) this.begin(traversals[0]);
    if (!this.traversal) return;
    if (this.timer) clearInterval(this.timer);
    this.timer = setInterval(() => this.advance(), 1000 / this.speed);
    this.playButton.textContent = 'Pause';
    this.playButton.setAttribute('aria-label', 'Pause traversal');
  }

  pause(): void {
    if (this.timer) clearInterval(this.timer);
    this.timer = null;
    this.playButton.textContent = 'Play';
    this.playButton.setAttribute('aria-label', 'Play traversal');
  }

  stop(): void {
    this.pause();
    this.traversal = null;
    this.steps = [];
    this.code.replaceChildren();
    this.message.textContent = '';
    this.show(null);
  }

  /** Current state, for the automation API. */
  state(): { title: string; line: number; h: number; visited: number[]; done: boolean } | null {
    const step = this.steps[this.index];
    return this.traversal && step ? { title: this.traversal.title, ...step } : null;
  }

  private render(): void {
    const traversal = this.traversal;
    const step = this.steps[this.index];
    if (!traversal || !step) return;
    replace(
      this.code,
      ...traversal.code.map((line, i) => el('span', { class: i === step.line ? 'line current' : 'line', 'data-line': String(i) }, line, '\n')),
    );
    const seen = step.visited.map((id) => (id < 0 ? 'hole' : `${traversal.visits === 'face' ? 'f' : 'h'}${id}`));
    this.message.textContent = `h = h${step.h}; visited: ${seen.join(', ') || 'nothing yet'}${step.done ? ' — back at the start: done' : ''}`;
    this.show(traversalHighlight(traversal, step));
  }
}
