/**
 * Offline use: a service worker (public/sw.js) keeps what the app fetches, and the files this page
 * already loaded before the worker took over are put in its cache here, so that after one visit
 * the app (and the samples seen) open without a network.
 */
const CACHE = 'halfedge-lab';

export async function keepForOffline(): Promise<void> {
  if (!('serviceWorker' in navigator) || !('caches' in window)) return;
  await navigator.serviceWorker.register(`${import.meta.env.BASE_URL}sw.js`);
  await navigator.serviceWorker.ready;
  const loaded = performance
    .getEntriesByType('resource')
    .map((entry) => entry.name)
    .filter((url) => new URL(url).origin === location.origin);
  const cache = await caches.open(CACHE);
  await cache.addAll([location.pathname, ...new Set(loaded)]);
}
