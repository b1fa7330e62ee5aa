/** The page's entry: start the app, expose the automation object, open the first model. */
import { App } from './app.js';
import { automation } from './automation.js';
import { keepForOffline } from './offline.js';
import { decodeViewState } from './share.js';

const app = new App();
window.halfedgeLab = automation(app);

/** Opens the model a link names (or the first sample), then its selection and camera. */
async function openFirstModel(): Promise<void> {
  const state = decodeViewState(location.search);
  await app.loadSampleList();
  if (await app.openSample(state.model ?? app.samples[0]?.file ?? 'tetrahedron.off')) app.applyViewState(state);
}

void openFirstModel().then(() => {
  if (import.meta.env.PROD) void keepForOffline().catch(() => {});
});
