import { existsSync } from 'node:fs';
import { defineConfig, devices } from '@playwright/test';

/**
 * Headless Chromium against the Vite dev server. Test tools cannot download browsers here, so a
 * system Chromium (Debian's `chromium` package) is used when present; elsewhere Playwright's own.
 */
const systemChromium = ['/usr/bin/chromium', '/usr/bin/chromium-browser'].find((path) => existsSync(path));
// E2E_PORT lets two checkouts run their browser tests at once, each against its own build
const port = Number(process.env.E2E_PORT ?? 5183);

/** The tests that measure time, run last, after every other test (see e2e/timed.spec.ts). */
const timed = /timed\.spec\.ts$/;

const chromium = {
  ...devices['Desktop Chrome'],
  viewport: { width: 1280, height: 800 },
  launchOptions: {
    executablePath: systemChromium,
    args: [
      '--no-sandbox',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      // WebGL in software where there is no GPU
      '--use-angle=swiftshader',
      '--enable-unsafe-swiftshader',
    ],
  },
};

export default defineConfig({
  testDir: 'e2e',
  timeout: 60_000,
  expect: { timeout: 15_000 },
  // one browser at a time: drawing in software keeps both cores busy, and two browsers took as
  // long in all (8.7 min against 8.1) while each test's clock measured the other
  fullyParallel: false,
  workers: 1,
  retries: 0,
  reporter: [['list']],
  outputDir: 'test-results',
  use: {
    baseURL: `http://localhost:${port}`,
    viewport: { width: 1280, height: 800 },
    trace: 'retain-on-failure',
  },
  projects: [
    { name: 'chromium', testIgnore: timed, use: chromium },
    // last: it starts once every other test is done
    { name: 'timed', testMatch: timed, dependencies: ['chromium'], use: chromium },
  ],
  // the production build, served as a static host would (strict Content-Security-Policy included);
  // the <halfedge-view> element's own bundle too, which e2e/embed.spec.ts serves to a page of its own
  webServer: {
    command: `npx vite build --logLevel warn && npm run build:element && npx vite preview --port ${port} --strictPort`,
    url: `http://localhost:${port}`,
    reuseExistingServer: !process.env.CI,
    timeout: 120_000,
  },
});
