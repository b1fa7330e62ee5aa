/**
 * Offline use: the service worker (public/sw.js) keeps the whole built site when it installs, so
 * after one visit the app and all its samples open without a network. Not in development, where
 * the files change under it.
 */
export async function keepForOffline(): Promise<void> {
  if ('serviceWorker' in navigator) await navigator.serviceWorker.register(`${import.meta.env.BASE_URL}sw.js`);
}
