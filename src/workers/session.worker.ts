/** The session worker: a thin shell exposing one `EditingSession`. */
import { expose } from 'comlink';
import { installErrorTransfer } from './protocol.js';
import { EditingSession } from './session.js';
import { sessionApi } from './session-api.js';

installErrorTransfer();

expose(sessionApi(new EditingSession()));
