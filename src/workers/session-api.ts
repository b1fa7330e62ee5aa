/**
 * The session's methods as the worker exposes them: its verbs taken from the table in protocol.ts,
 * each snapshot's buffers transferred rather than copied.
 */
import { transfer } from 'comlink';
import { type SessionApi, type Snapshot, snapshotVerbNames, type SnapshotVerbs, transferables } from './protocol.js';
import type { EditingSession } from './session.js';

export function sessionApi(session: EditingSession): SessionApi {
  const send = (snapshot: Snapshot) => transfer(snapshot, transferables(snapshot));
  const verbs = Object.fromEntries(
    snapshotVerbNames.map((verb) => [verb, async (...args: unknown[]) => send(await (session[verb] as (...args: unknown[]) => Snapshot | Promise<Snapshot>)(...args))]),
  ) as SnapshotVerbs<Promise<Snapshot>>;
  return {
    ...verbs,
    details: async () => session.details(),
    fingerprint: async () => session.fingerprint(),
    seams: async () => {
      const edges = session.seams();
      return transfer(edges, [edges.buffer]);
    },
    exportMesh: async (format) => {
      const bytes = await session.exportMesh(format);
      return transfer(bytes, [bytes.buffer as ArrayBuffer]);
    },
    setProgressListener: async (listener) => session.setProgressListener(listener),
  };
}
