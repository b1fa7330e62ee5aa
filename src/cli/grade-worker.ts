/** The `grade` command's sandbox: a worker thread that runs one solution request (see `workers/practice-sandbox.ts`). */
import { parentPort } from 'node:worker_threads';
import { lockDown, type SandboxRequest, serveRequest } from '../workers/practice-sandbox.js';

const port = parentPort!;
port.once('message', (request: SandboxRequest) => serveRequest(request, (message) => port.postMessage(message)));
lockDown();
