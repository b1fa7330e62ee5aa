/**
 * Quiz mode: a question about where a path of pointers leads; the student answers by clicking
 * the element in the view; the app says right or wrong and shows the path. Questions get longer
 * after right answers.
 */
import type { HalfedgeMesh } from '../../core/index.js';
import type { Convention } from '../records.js';
import { el, replace } from '../dom.js';
import { hopsFor, isRight, makeQuestion, type Question } from '../quiz.js';
import { elementName, type Selection } from '../selection.js';

export interface QuizActions {
  mesh(): HalfedgeMesh | null;
  /** The naming in use: a path may end at a halfedge's origin or target, as the naming says. */
  convention(): Convention;
  /** Shows the path walked (start … answer) in the view, or clears it. */
  showPath(question: Question | null, picked: Selection | null): void;
}

export class QuizPanel {
  question: Question | null = null;
  /** Waiting for the student's click. */
  active = false;
  right = 0;
  asked = 0;
  private streak = 0;
  private readonly prompt = el('p', { class: 'quiz-question', 'aria-live': 'polite' });
  private readonly verdict = el('p', { class: 'quiz-verdict', role: 'status' });
  private readonly score = el('p', { class: 'note' });

  constructor(
    container: HTMLElement,
    private readonly actions: QuizActions,
    private readonly random: () => number = Math.random,
  ) {
    replace(
      container,
      el('p', { class: 'note' }, 'The app names a halfedge and a path of pointers; click the element the path leads to. Paths grow longer as you get them right.'),
      el('button', { type: 'button', 'aria-keyshortcuts': 'Q', onclick: () => this.ask() }, 'New question'),
      this.prompt,
      this.verdict,
      this.score,
    );
  }

  /** Asks a new question (about the current mesh). */
  ask(): Question | null {
    const mesh = this.actions.mesh();
    this.question = mesh ? makeQuestion(mesh, this.random, hopsFor(this.streak), this.actions.convention()) : null;
    this.active = this.question !== null;
    this.prompt.textContent = this.question ? `${this.question.text} Click it in the view.` : 'Open a mesh with faces first.';
    this.verdict.textContent = '';
    this.verdict.className = 'quiz-verdict';
    this.actions.showPath(this.question ? { ...this.question, path: [this.question.start] } : null, null);
    return this.question;
  }

  /**
   * Stops waiting for an answer and takes the path off the view (the question's text stays): a
   * selection, Esc, another tab or another model takes the view back.
   */
  end(): void {
    this.active = false;
    this.actions.showPath(null, null);
  }

  /** The student's answer; returns whether it was right. */
  answer(picked: Selection): boolean {
    const question = this.question;
    if (!question || !this.active) return false;
    this.active = false;
    this.asked++;
    const right = isRight(question, picked);
    if (right) {
      this.right++;
      this.streak++;
    } else this.streak = 0;
    const path = question.path.map((s, i) => (i === 0 ? elementName(s) : `${question.moves[i - 1]} → ${elementName(s)}`)).join(' → ');
    this.verdict.textContent = right
      ? `Right: ${path}.`
      : `Not quite: you picked ${elementName(picked)}. The path is ${path}.`;
    this.verdict.className = `quiz-verdict ${right ? 'right' : 'wrong'}`;
    this.score.textContent = `${this.right} of ${this.asked} right${this.streak > 1 ? `, ${this.streak} in a row` : ''}.`;
    this.actions.showPath(question, picked);
    return right;
  }
}
