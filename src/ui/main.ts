/**
 * The page's entry: start the app (the whole app, or with `?embed` only the view and the panels
 * `panels=` names), expose the automation object, open the first model.
 */
import { App, pageHost } from './app.js';
import { automation } from './automation.js';
import { parsePanels, unknownPanelsMessage } from './embed.js';
import { keepForOffline } from './offline.js';
import { decodeViewState } from './share.js';

const params = new URLSearchParams(location.search);
const embed = parsePanels(params.get('panels'));
// yield once before making the view, whose first task is long (a WebGL context and its first
// shaders: half a second in software rendering), so that the browser finishes loading the page
// first: in two sets of 20 first loads, the sample was drawn after a median of 0.87 and 0.94 s,
// against 1.07 and 1.08 s without
await new Promise((resolve) => setTimeout(resolve));
const app = new App(pageHost(params.has('embed') ? embed.panels : null));
window.halfedgeLab = automation(app);

/**
 * Opens the model a link names, then its selection and camera; or the first sample, when the link
 * names none or one that is not here (a typo, a sample since renamed): the page is never empty.
 */
async function openFirstModel(): Promise<void> {
  const state = decodeViewState(location.search);
  if (state.naming) app.setConvention(state.naming);
  await app.opening.loadSampleList();
  const first = app.opening.samples[0]?.file ?? 'tetrahedron.off';
  if (!state.model) {
    await app.opening.openSample(first);
  } else if (await app.opening.openSample(state.model)) {
    if (await app.replay(state.steps)) app.applyViewState(state);
  } else if (await app.opening.openSample(first)) {
    app.say(`This link names a sample that is not here (${state.model}), so ${first} is open instead.`, 'alert');
  }
  // after what the link got wrong besides (a model that is not here, a step, a selection), not instead of it
  if (params.has('embed') && embed.unknown.length > 0) {
    const before = document.getElementById('status')?.getAttribute('role') === 'alert' ? `${app.message} ` : '';
    app.say(`${before}${unknownPanelsMessage(embed.unknown)}`, 'alert');
  }
}

/** `?exercise=…` opens an exercise in the Practice tab (after the first model: the view is never empty). */
async function openExercise(): Promise<void> {
  const value = params.get('exercise');
  if (!value) return;
  try {
    const { exerciseFromLink } = await import('./practice-link.js');
    (await app.practice()).add(await exerciseFromLink(value));
    app.showTab('practice');
  } catch (error) {
    app.say(`Could not open the exercise ${value}: ${(error as Error).message}`, 'alert');
  }
}

void openFirstModel().then(() => {
  void openExercise();
  if (import.meta.env.PROD) void keepForOffline().catch(() => {});
});
