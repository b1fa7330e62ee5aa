/**
 * A session as the page sees it, without a worker: every snapshot is taken into one `PageCopy`
 * (whole or patched, as the app's client does), and a pending snapshot gets its full details at
 * once (as the app asks for them), so tests read real counts and checks. And a random local edit
 * for such a session to apply.
 */
import type { HalfedgeMesh } from '../../src/core/mesh.js';
import { cannotEdit, type EditRequest } from '../../src/workers/operations.js';
import type { Snapshot } from '../../src/workers/protocol.js';
import { PageCopy, type PageSnapshot } from '../../src/workers/page-copy.js';
import type { EditingSession } from '../../src/workers/session.js';

export interface PageSession {
  session: EditingSession;
  page: PageCopy;
  /** Every snapshot taken so far, whole (false) or patched (true). */
  patched: boolean[];
  /** Every snapshot taken so far: whether its counts came from a change record, the full pass after (`pending`). */
  counted: boolean[];
  snapshot(): PageSnapshot;
  start(...args: Parameters<EditingSession['start']>): PageSnapshot;
  step(): PageSnapshot;
  stepBack(): PageSnapshot;
  runToEnd(): Promise<PageSnapshot>;
  cancel(): PageSnapshot;
  edit(...args: Parameters<EditingSession['edit']>): PageSnapshot;
  solution(...args: Parameters<EditingSession['solution']>): PageSnapshot;
  undo(): PageSnapshot;
  redo(): PageSnapshot;
  jump(index: number): PageSnapshot;
}

export function pageSession(session: EditingSession): PageSession {
  const page = new PageCopy();
  const patched: boolean[] = [];
  const counted: boolean[] = [];
  const take = (snapshot: Snapshot): PageSnapshot => {
    patched.push(snapshot.patch !== null);
    counted.push(snapshot.details.pending);
    const shown = page.take(snapshot);
    if (!shown.pending) return shown;
    const { version: _, ...details } = session.details();
    return { ...shown, ...details, pending: false };
  };
  take(session.snapshot());
  return {
    session,
    page,
    patched,
    counted,
    snapshot: () => take(session.snapshot()),
    start: (request) => take(session.start(request)),
    step: () => take(session.step()),
    stepBack: () => take(session.stepBack()),
    runToEnd: async () => take(await session.runToEnd()),
    cancel: () => take(session.cancel()),
    edit: (request) => take(session.edit(request)),
    solution: (...args) => take(session.solution(...args)),
    undo: () => take(session.undo()),
    redo: () => take(session.redo()),
    jump: (index) => take(session.jump(index)),
  };
}

/** A local edit that applies to `mesh`, on an element chosen by `random`, or null after 50 misses. */
export function randomEdit(mesh: HalfedgeMesh, random: () => number): EditRequest | null {
  for (let attempt = 0; attempt < 50; attempt++) {
    const edge = Math.floor(random() * mesh.edgeSlots);
    const face = Math.floor(random() * mesh.faceSlots);
    const kinds: EditRequest[] = [
      { kind: 'flip-edge', edge },
      { kind: 'split-edge', edge, triangulate: true },
      { kind: 'collapse-edge', edge },
      { kind: 'poke-face', face },
      { kind: 'erase-edge', edge },
      { kind: 'split-edge', edge },
    ];
    const request = kinds[Math.floor(random() * kinds.length)];
    if (!cannotEdit(mesh, request)) return request;
  }
  return null;
}
