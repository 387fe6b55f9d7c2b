// The offline worker (README "Deploy"; issue 26). One file, two roles:
//
// - In the built site (`make dist`) scripts/service-worker.mjs writes it to `sw.js` at the site
//   root with BUILD filled in: the version (a hash of every precached file's path and content),
//   the SHA-256 of each unhashed one, and the files (every hashed asset, the HTML entry points,
//   embed.js, the manifest and icons).
//   Installing stores them all in the cache `splinelab-<version>` (all or nothing: a failed fetch
//   fails the install, and the browser retries at the next visit); from then on a request for one
//   of them, or a navigation to a page of the site (query ignored), is answered from that cache,
//   online or not; anything else goes to the network as without a worker.
// - A new deployment changes the version, so the browser's update check (at every navigation;
//   sw.js is served no-cache) installs the new worker beside the old. It waits, as browsers do by
//   default (no skipWaiting, no clients.claim), until no page of the old version is open, then
//   activates and deletes every other `splinelab-` cache. A page is thus served by one worker
//   and one cache for its whole life: never a mix of two versions, and the lazy chunks it loads
//   later (a demo, a language, three.js) are still there.
// - In development (`make serve` of www/) nothing registers a worker (www/lib/offline.js), and
//   this file, with no files listed, is the pass-through that retires one: if a built site's
//   worker is left on the origin (e.g. `make serve-dist` on the same port), the browser's update
//   check fetches this file, which installs at once, deletes the caches and unregisters itself:
//   the page that brought it was still the built one, the next load is www/'s (a reload).
const BUILD = { version: "dev", files: [] };
const PREFIX = "splinelab-";
const CACHE = `${PREFIX}${BUILD.version}`;
const PASS_THROUGH = BUILD.files.length === 0;
const SCOPE = new URL(self.registration.scope);
const LISTED = new Set(BUILD.files);

/** The SHA-256 of `body` in hex. */
async function sha256(body) {
  const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", body));
  return Array.from(digest, (b) => b.toString(16).padStart(2, "0")).join("");
}

/** Fetches every listed file, then stores them all in this version's cache; rejects (failing
 * the install, with nothing stored) on any error. A hashed file (assets/) may come from the HTTP
 * cache: its name says its content. The others (pages, embed.js, manifest, icons) are
 * revalidated and must have this build's SHA-256 (BUILD.digests), or the install fails and is
 * retried at the next visit: a host or CDN still sending an old page cannot put it beside this
 * version's files. */
async function precache() {
  const fetched = await Promise.all(
    BUILD.files.map(async (path) => {
      const url = new URL(path, SCOPE);
      const expected = BUILD.digests?.[path];
      const response = await fetch(url, { cache: expected ? "no-cache" : "default" });
      if (!response.ok) throw new Error(`splinelab offline: ${path}: HTTP ${response.status}`);
      const body = await response.arrayBuffer();
      if (expected && (await sha256(body)) !== expected)
        throw new Error(`splinelab offline: ${path} is not this version's`);
      // Stored as a new response (a redirected one may not answer a navigation) whose headers no
      // longer say br/gzip or the encoded length: the body is decoded.
      const headers = new Headers(response.headers);
      headers.delete("content-encoding");
      headers.delete("content-length");
      const { status, statusText } = response;
      return [url, new Response(body, { status, statusText, headers })];
    }),
  );
  const cache = await caches.open(CACHE);
  await Promise.all(fetched.map(([url, response]) => cache.put(url, response)));
}

/** Deletes the caches of every other version; the pass-through also leaves the origin. */
async function activate() {
  for (const key of await caches.keys())
    if (key.startsWith(PREFIX) && key !== CACHE) await caches.delete(key);
  if (!PASS_THROUGH) return;
  await self.registration.unregister();
}

/** The listed file `request` asks for (a navigation to a folder means its index.html), or null. */
function listedPath(request) {
  if (request.method !== "GET") return null;
  const url = new URL(request.url);
  if (url.origin !== SCOPE.origin || !url.pathname.startsWith(SCOPE.pathname)) return null;
  let path = url.pathname.slice(SCOPE.pathname.length);
  if (request.mode === "navigate" && (path === "" || path.endsWith("/"))) path += "index.html";
  return LISTED.has(path) ? path : null;
}

/** The cached copy of `path`, or the network's answer if the cache lost it (storage cleared). */
async function answer(path, request) {
  const cache = await caches.open(CACHE);
  return (await cache.match(new URL(path, SCOPE))) ?? fetch(request);
}

self.addEventListener("install", (event) => {
  if (PASS_THROUGH) self.skipWaiting();
  else event.waitUntil(precache());
});

self.addEventListener("activate", (event) => event.waitUntil(activate()));

if (!PASS_THROUGH)
  self.addEventListener("fetch", (event) => {
    const path = listedPath(event.request);
    if (path) event.respondWith(answer(path, event.request));
  });
