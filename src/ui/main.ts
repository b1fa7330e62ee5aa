/** The page's entry: start the app, expose the automation object, open the first model. */
import { App } from './app.js';
import { automation } from './automation.js';

const app = new App();
window.halfedgeLab = automation(app);

async function openFirstModel(): Promise<void> {
  const params = new URLSearchParams(location.search);
  await app.loadSampleList();
  await app.openSample(params.get('model') ?? app.samples[0]?.file ?? 'tetrahedron.off');
}

void openFirstModel();
