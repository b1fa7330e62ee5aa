/** The session worker: a thin shell exposing `EditingSession`, transferring every snapshot. */
import { expose, transfer } from 'comlink';
import { installErrorTransfer, type SessionApi, type Snapshot, transferables } from './protocol.js';
import { EditingSession } from './session.js';

installErrorTransfer();

const session = new EditingSession();
const send = (snapshot: Snapshot) => transfer(snapshot, transferables(snapshot));

const api: SessionApi = {
  adopt: async (loaded, sample) => send(session.adopt(loaded, sample)),
  restore: async (mesh, label) => send(session.restore(mesh, label)),
  practice: async (mesh, label, diff) => send(session.practice(mesh, label, diff)),
  snapshot: async () => send(session.snapshot()),
  details: async () => session.details(),
  fingerprint: async () => session.fingerprint(),
  seams: async () => {
    const edges = session.seams();
    return transfer(edges, [edges.buffer]);
  },
  start: async (request) => send(session.start(request)),
  step: async () => send(session.step()),
  runToEnd: async () => send(await session.runToEnd()),
  cancel: async () => send(session.cancel()),
  edit: async (request) => send(session.edit(request)),
  undo: async () => send(session.undo()),
  redo: async () => send(session.redo()),
  jump: async (index) => send(session.jump(index)),
  exportMesh: async (format) => {
    const bytes = await session.exportMesh(format);
    return transfer(bytes, [bytes.buffer as ArrayBuffer]);
  },
  setProgressListener: async (listener) => session.setProgressListener(listener),
};

expose(api);
