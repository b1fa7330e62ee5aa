/** The page's entry: start the app, expose the automation object, open the first model. */
import { App } from './app.js';
import { automation } from './automation.js';
import { keepForOffline } from './offline.js';
import { decodeViewState } from './share.js';

const app = new App();
window.halfedgeLab = automation(app);

/**
 * Opens the model a link names, then its selection and camera; or the first sample, when the link
 * names none or one that is not here (a typo, a sample since renamed): the page is never empty.
 */
async function openFirstModel(): Promise<void> {
  const state = decodeViewState(location.search);
  await app.loadSampleList();
  const first = app.samples[0]?.file ?? 'tetrahedron.off';
  if (!state.model) {
    await app.openSample(first);
  } else if (await app.openSample(state.model)) {
    if (await app.replay(state.steps)) app.applyViewState(state);
  } else if (await app.openSample(first)) {
    app.say(`This link names a sample that is not here (${state.model}), so ${first} is open instead.`, 'alert');
  }
}

void openFirstModel().then(() => {
  if (import.meta.env.PROD) void keepForOffline().catch(() => {});
});
