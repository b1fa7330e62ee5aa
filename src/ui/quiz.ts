/**
 * Quiz questions: the app picks a halfedge and a path of pointers, and asks where it leads
 * ("which halfedge is h17.next.twin?"). The student answers by clicking. Longer paths as the
 * student gets them right. Pure: a question is made from the mesh and a random source.
 */
import type { HalfedgeMesh } from '../core/index.js';
import type { Convention } from './records.js';
import { elementName, type Move, type Selection, walk } from './selection.js';

export interface Question {
  start: Selection;
  moves: Move[];
  /** Every element along the path, the start first and the answer last. */
  path: Selection[];
  answer: Selection;
  text: string;
}

const halfedgeMoves: Move[] = ['next', 'prev', 'twin'];
/** The last move of a path may also lead to a vertex: the one the naming names (origin or target). */
const finalMoves = (convention: Convention): Move[] => ['next', 'prev', 'twin', convention, 'face'];

/** Hops for a student who has answered `streak` questions right in a row. */
export function hopsFor(streak: number): number {
  return Math.min(1 + Math.floor(streak / 2), 5);
}

/** A question of `hops` moves from a random halfedge, or null on a mesh without halfedges. */
export function makeQuestion(mesh: HalfedgeMesh, random: () => number, hops: number, convention: Convention = 'origin'): Question | null {
  if (mesh.nHalfedges === 0) return null;
  let h = Math.floor(random() * mesh.halfedgeSlots);
  for (let tries = 0; mesh.eDeleted[h >> 1] && tries < mesh.halfedgeSlots; tries++) h = (h + 1) % mesh.halfedgeSlots;
  const start: Selection = { kind: 'halfedge', id: h };
  const path: Selection[] = [start];
  const moves: Move[] = [];
  for (let i = 0; i < hops; i++) {
    const choices = i + 1 < hops ? halfedgeMoves : finalMoves(convention);
    // a boundary halfedge has no face: draw again until the move leads somewhere
    for (let tries = 0; tries < 20; tries++) {
      const move = choices[Math.floor(random() * choices.length)];
      const to = walk(mesh, path[path.length - 1], move);
      if (typeof to === 'string') continue;
      moves.push(move);
      path.push(to);
      break;
    }
  }
  const answer = path[path.length - 1];
  return { start, moves, path, answer, text: `Which ${answer.kind} is ${elementName(start)}.${moves.join('.')}?` };
}

export function isRight(question: Question, picked: Selection): boolean {
  return picked.kind === question.answer.kind && picked.id === question.answer.id;
}
