/** The browser's practice sandbox: one request per worker, which is thrown away after it (see `practice-sandbox.ts`). */
import { lockDown, type SandboxMessage, type SandboxRequest, serveRequest } from './practice-sandbox.js';

// taken before the lock-down shuts postMessage to the solution
const post = self.postMessage.bind(self);
self.onmessage = (event: MessageEvent<SandboxRequest>) => serveRequest(event.data, (message: SandboxMessage) => post(message));
lockDown();
