// Keeps the app usable offline once it has been loaded. On install it keeps every file of the
// built site (offline.json lists them), so the first visit is enough; after that each same-origin
// GET is answered from the network when there is one (and the answer kept, so the copy stays
// fresh), and from what was kept when there is not. Meshes opened from disk never go through here.
const CACHE = 'halfedge-lab';

self.addEventListener('install', (event) => {
  event.waitUntil(
    fetch('offline.json')
      .then((response) => response.json())
      .then((files) => caches.open(CACHE).then((cache) => cache.addAll(files)))
      .then(() => self.skipWaiting()),
  );
});
self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(
    fetch(request)
      .then((response) => {
        if (response.ok) {
          const copy = response.clone();
          event.waitUntil(caches.open(CACHE).then((cache) => cache.put(request, copy)));
        }
        return response;
      })
      // ignoreVary: a file kept from this worker's own request (no Origin header) answers a module request (with one)
      .catch(() => caches.match(request, { ignoreSearch: true, ignoreVary: true }).then((kept) => kept ?? Response.error())),
  );
});
