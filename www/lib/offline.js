/** The longest registration waits for the first page to be shown (ms). */
const FIRST_PAGE_WAIT_MS = 15000;

/**
 * Registers the offline worker (www/sw.js, README "Deploy") in the built site only.
 *
 * `make dist` defines SPLINELAB_SERVICE_WORKER (esbuild `define`, scripts/service-worker.mjs) as
 * the worker's URL relative to the bundle in assets/, i.e. `sw.js` at the site root, whose scope
 * is then the whole site. In development (www/, unbundled) it is undefined and nothing is
 * registered: every reload gets the current files from `make serve`. The embed does not call
 * this: it runs inside other people's pages, whose origin is not the playground's.
 *
 * Registration waits for the page's `load` event and then for `firstPage` (app.js's start: the
 * page the link asked for, shown; at most FIRST_PAGE_WAIT_MS), so the precache (the whole site,
 * ~2.9 MiB) does not compete with the first figure's downloads: a demo's wasm is asked for after
 * its poster's paint, after `load`, and on a slow link would otherwise share it with the
 * precache. A failure leaves the site working online as before.
 */
export function registerOffline(firstPage = Promise.resolve()) {
  if (typeof SPLINELAB_SERVICE_WORKER === "undefined" || !("serviceWorker" in navigator)) return;
  const url = new URL(SPLINELAB_SERVICE_WORKER, import.meta.url);
  const shown = Promise.race([
    Promise.resolve(firstPage).catch(() => {}),
    new Promise((resolve) => setTimeout(resolve, FIRST_PAGE_WAIT_MS)),
  ]);
  const register = () => shown.then(() => navigator.serviceWorker.register(url)).catch(() => {});
  if (document.readyState === "complete") register();
  else addEventListener("load", register, { once: true });
}
