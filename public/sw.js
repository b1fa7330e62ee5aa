// Keeps the app usable offline once it has been loaded: every same-origin GET is answered from
// the network when there is one (and the answer kept), and from what was kept when there is not.
// Nothing is sent anywhere: meshes opened from disk never go through here at all.
const CACHE = 'halfedge-lab';

self.addEventListener('install', () => self.skipWaiting());
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
      // ignoreVary: a file kept from the page's own request (no Origin header) answers a module request (with one)
      .catch(() => caches.match(request, { ignoreSearch: true, ignoreVary: true }).then((kept) => kept ?? Response.error())),
  );
});
