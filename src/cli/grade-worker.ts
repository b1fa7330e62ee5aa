/** The `grade` command's sandbox: a worker thread that runs one solution request (see `workers/practice-sandbox.ts`). */
import { serveSandboxThread } from './sandbox.js';

serveSandboxThread();
