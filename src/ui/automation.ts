/**
 * `window.halfedgeLab`: the documented automation object for test authors (see
 * docs/automation.md). Everything a student can do by clicking, without pixel-clicking: open a
 * mesh, select, walk, step operations, and read the state the page shows.
 */
import type { PageSnapshot } from '../workers/page-copy.js';
import { type HalfedgeMesh, meshArrays } from '../core/index.js';
import { type Snapshot, type SnapshotVerbs, type StudentVerb, studentVerbNames } from '../workers/protocol.js';
import type { App } from './app.js';
import { commandNamed, commands, runCommand } from './commands.js';
import { recordOf } from './records.js';
import { type ElementKind, elementName, type Move, parseElementName, type Selection } from './selection.js';
import { newPlacement, placeArrow } from './scene/arrow-placement.js';

export function automation(app: App) {
  const mesh = (): HalfedgeMesh => {
    if (!app.mesh) throw new Error('no mesh is open yet');
    return app.mesh;
  };
  /** The mesh as drawn (in the exploded view, its parts pulled apart): where to click an element. */
  const drawn = (): HalfedgeMesh => {
    if (!app.drawn) throw new Error('no mesh is open yet');
    return app.drawn;
  };
  const asSelection = (element: string | Selection): Selection => {
    const s = typeof element === 'string' ? parseElementName(element) : element;
    if (!s) throw new Error(`'${String(element)}' is not an element name like h17, v4, f5 or e8`);
    return s;
  };
  return {
    /** Resolves once the first mesh is drawn. */
    ready: app.ready,
    /**
     * Opens a file from bytes; resolves true when it loaded, false on a parse error (shown on the
     * page). `files`: for a `.gltf`, the files it names (its `.bin`), by name; `options.weldTolerance`:
     * weld STL and glTF vertices within this distance.
     */
    open: (bytes: Uint8Array | ArrayBuffer | number[], name: string, files?: Record<string, Uint8Array | ArrayBuffer | number[]>, options: { weldTolerance?: number } = {}) =>
      app.opening.openBytes(bytesOf(bytes), name, null, {
        resources: files ? new Map(Object.entries(files).map(([file, data]) => [file, bytesOf(data)])) : undefined,
        weldTolerance: options.weldTolerance,
      }),
    /** Opens one of the sample models by file name (see `samples()`). */
    openSample: (file: string) => app.opening.openSample(file),
    samples: () => app.opening.samples.map((s) => s.file),
    /** Selects an element: `'h17'`, `{ kind: 'vertex', id: 4 }`, or null to clear. */
    select: (element: string | Selection | null) => app.select(element === null ? null : asSelection(element)),
    /** Follows a pointer from the selection: next, prev, twin, face, origin, target, edge, halfedge, twin.next, prev.twin. */
    walk: (move: Move) => app.walk(move),
    back: () => app.back(),
    /** The record of an element as the inspector shows it: `{ next: 'h18', origin: 'v4', … }`. */
    record: (element: string | Selection) => {
      const fields: Record<string, string> = {};
      for (const { field, value } of recordOf(mesh(), asSelection(element), app.inspection.convention)) {
        if (!field) continue;
        fields[field] = 'element' in value ? elementName(value.element) : value.text;
      }
      return fields;
    },
    /** Where an element appears on the canvas (CSS pixels from the canvas's top-left), to click it. */
    screenPosition: (element: string | Selection) => {
      const s = asSelection(element);
      const m = drawn();
      let point: [number, number, number];
      if (s.kind === 'halfedge') {
        const placement = placeArrow(m, s.id, newPlacement(), app.scale);
        point = [0, 1, 2].map((i) => 0.35 * placement.start[i] + 0.65 * placement.end[i]) as [number, number, number];
      } else if (s.kind === 'vertex') point = m.position(s.id) as [number, number, number];
      else if (s.kind === 'edge') {
        const [a, b] = [m.origin(m.edgeHalfedge(s.id)), m.origin(m.twin(m.edgeHalfedge(s.id)))].map((v) => m.position(v));
        point = [0, 1, 2].map((i) => (a[i] + b[i]) / 2) as [number, number, number];
      }
      else {
        // the middle of the face's first triangle lies inside the face even when it is not convex
        const h = m.faceHalfedge(s.id);
        const corners = [m.origin(h), m.target(h), m.origin(m.prev(h))].map((v) => m.position(v));
        point = [0, 1, 2].map((i) => (corners[0][i] + corners[1][i] + corners[2][i]) / 3) as [number, number, number];
      }
      const { x, y, visible } = app.viewer.project(point);
      return { x, y, visible };
    },
    /** What a click at canvas point (x, y) would pick (a promise: a large mesh is picked in a worker). */
    pickAt: async (x: number, y: number, filter?: 'auto' | ElementKind) => {
      const s = await app.pickAt(x, y, filter);
      return s ? elementName(s) : null;
    },
    setConvention: (convention: 'origin' | 'target') => app.setConvention(convention),
    /** Marks the seams (edges where the file split its vertices; the File tab's button) or clears them; resolves to how many were marked. */
    showSeams: (on: boolean) => app.toggleSeams(on),
    setPresentation: (on: boolean) => app.setPresentation(on),
    /** Turns the exploded view on or off (the *Explode parts* button, B); resolves to whether it is on (off on a mesh of one part). */
    explode: async (on: boolean) => app.setExploded(on),
    /** Selects boundary loop `index`'s halfedge and frames the loop (the HUD's “frame” button); false when there is no such loop. */
    frameBoundaryLoop: (index: number) => app.frameBoundaryLoop(index),
    /** The student's verbs (protocol.ts): `start(request)`, `step()`, `stepBack()`, `runToEnd()`, `cancel()`, `edit(request)`, `undo()`, `redo()`, `jump(index)`; each resolves to `{ version }`, or null when refused (the page says why). */
    ...(Object.fromEntries(studentVerbNames.map((verb) => [verb, (...args: unknown[]) => (app.request as (verb: StudentVerb, ...args: unknown[]) => Promise<Snapshot | null>)(verb, ...args).then(summary)])) as SnapshotVerbs<
      Promise<{ version: number } | null>,
      StudentVerb
    >),
    /**
     * The app's commands, from the one table the keys, the buttons and the help are made from
     * (commands.ts): each `{ name, keys, label, help, unavailable }` (`label`: its button's name, or
     * null; `unavailable`: null, or why it does not apply now).
     */
    commands: () =>
      commands.map((c) => ({ name: c.name, keys: c.keys, label: c.button?.label ?? null, help: c.help(app.inspection.convention), unavailable: c.unavailable?.(app.commandTarget) ?? null })),
    /** Runs a command by name, as its key or button does; null when it ran, else why it does not apply now (said on the page too). */
    command: (name: string) => {
      const found = commandNamed(name);
      if (!found) throw new Error(`there is no command '${name}' (commands: ${commands.map((c) => c.name).join(', ')})`);
      return runCommand(app.commandTarget, found);
    },
    /** The link "Copy link" copies (and copies it): the sample, the steps since it, the selection, the camera. */
    shareLink: () => app.shareLink(),
    /** The quiz: `ask()` a new question; `question()` the current one, with its answer (for tests). */
    quiz: {
      ask: () => app.quiz.ask()?.text ?? null,
      question: () => {
        const q = app.quiz.question;
        return q ? { text: q.text, answer: elementName(q.answer), path: q.path.map(elementName), waiting: app.quiz.active } : null;
      },
      score: () => ({ right: app.quiz.right, asked: app.quiz.asked }),
    },
    /**
     * Practice mode (see docs/practice.md): `load(id)` opens an exercise in the Practice tab,
     * `setCode(text)` puts a solution in the editor, `run()` runs it on every fixture and resolves
     * to `{ passed, checks, writes, firstBroken, fixtures, error }`; `show(fixture, n)` shows a
     * fixture after its first n writes, `showRead(fixture, n)` a query's fixture with its reads up
     * to read n marked; `state()` is what the panel shows. `setUseMine(on)` is the "Use my code"
     * switch: while on, `edit()` or `start()` of the loaded exercise's operation (and its button)
     * runs the solution on the mesh in the view (see `state().lastEdit`).
     */
    practice: {
      list: async () => (await app.practice()).exercises.map((e) => e.id),
      load: async (id: string) => {
        const panel = await app.practice();
        panel.load(id);
        app.showTab('practice');
        await panel.open();
      },
      setCode: async (text: string) => {
        const panel = await app.practice();
        await panel.open();
        panel.setCode(text);
      },
      run: async () => (await app.practice()).run(),
      setUseMine: async (on: boolean) => (await app.practice()).setUseMine(on),
      show: async (fixture: number, writes: number) => (await app.practice()).show(fixture, writes),
      showRead: async (fixture: number, read: number) => (await app.practice()).showRead(fixture, read),
      state: async () => (await app.practice()).state(),
    },
    /** The session's fingerprint of its mesh and the page's of its own copy (`meshFingerprint`): equal when every patch landed right. */
    fingerprints: () => app.client.fingerprints(),
    /** Stops the editing worker as if it had run out of memory (the page should restart it and restore the mesh). */
    simulateWorkerCrash: () => app.client.simulateCrash(),
    /** Everything the page shows, as plain data. */
    state: () => ({
      selection: app.inspection.selection ? elementName(app.inspection.selection) : null,
      breadcrumb: app.inspection.path.map((step) => ({ move: step.move, to: elementName(step.to) })),
      convention: app.inspection.convention,
      message: app.message,
      stats: app.snapshot?.stats ?? null,
      problems: app.snapshot?.problems ?? [],
      file: app.snapshot?.file ?? null,
      repairs: app.snapshot?.report?.repairs.map((r) => ({ kind: r.kind, count: r.count })) ?? [],
      /** Whether the seams are marked in the view. */
      seamsShown: app.seamsShown,
      /** Whether the exploded view is on: the parts of the mesh drawn pulled apart. */
      exploded: app.exploded,
      /** Whether the cutting plane gizmo is on the view (Show plane); an operation's end hides it. */
      planeShown: app.planeShown,
      /** Each boundary loop of the mesh on screen: one of its boundary halfedges and its number of edges. */
      boundaryLoops: app.boundaryLoops().map(({ halfedge, length }) => ({ halfedge, length })),
      phase: phaseState(app.snapshot),
      /** True until the full counts and checks of the last change have arrived (`stats` beyond V, E, F, χ; `problems`). */
      pending: app.snapshot?.pending ?? false,
      /** Whether the last snapshot came as a patch of the page's copy (an edit, undo, redo or smoothing step) rather than a whole mesh. */
      patched: (app.snapshot?.renderPatch ?? null) !== null,
      stepping: app.snapshot?.stepping ?? null,
      /** The operation the last Step ended, while its last phase stays on show (`stepBack()` goes back into it). */
      ended: app.snapshot?.ended ?? null,
      history: app.snapshot?.history ?? null,
      version: app.snapshot?.version ?? 0,
      frames: app.viewer.frames,
      /**
       * The last edit: its kind, whose code made it (`solution` with "Use my code" on, else
       * `library`) and its pointer writes (a solution's writes; the library's pointers changed).
       */
      lastEdit: app.lastEdit,
      /** After an extrusion or a bevel: the number a drag on the view sets (`offset` or `amount`) and its value; null otherwise. */
      adjusting: app.adjust.target && { kind: app.adjust.target.request.kind, field: app.adjust.target.field, value: app.adjust.target.value },
      /** When the last snapshot arrived and when the view was last drawn (performance.now()). */
      shownAt: app.shown.at,
      drawnAt: app.viewer.lastDrawAt,
    }),
  };
}

/**
 * The last phase (or, after a local edit, the edit): its name, explanation and pointer diff, the
 * diff as `{ total, changes }` with the first 1,000 changes as `{ field, index, old, new }`
 * (`field` the array written: `heNext`, `hePrev`, `heVertex`, `heFace`, `vHalfedge`, `fHalfedge`).
 */
function phaseState(snapshot: PageSnapshot | null) {
  if (!snapshot || (!snapshot.phase && !snapshot.diff)) return null;
  const label = snapshot.history.items[snapshot.history.index]?.label ?? '';
  const diff = snapshot.diff && {
    total: snapshot.diff.total,
    changes: snapshot.diff.changes.slice(0, 1000).map(({ element, id, field, before, after }) => ({
      field: meshArrays.find((spec) => spec.owner === element && spec.field === field)!.name,
      index: id,
      old: before,
      new: after,
    })),
  };
  return { name: snapshot.phase?.name ?? label, explanation: snapshot.phase?.explanation ?? '', diff };
}

function summary(snapshot: { version: number } | null) {
  return snapshot ? { version: snapshot.version } : null;
}

export type HalfedgeLabAutomation = ReturnType<typeof automation>;

declare global {
  interface Window {
    halfedgeLab: HalfedgeLabAutomation;
  }
}

function bytesOf(data: Uint8Array | ArrayBuffer | number[]): Uint8Array<ArrayBuffer> {
  return data instanceof Uint8Array ? (data as Uint8Array<ArrayBuffer>) : new Uint8Array(data as ArrayBuffer);
}
