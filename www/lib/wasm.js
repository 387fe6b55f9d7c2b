/**
 * Loads the splinelab wasm package once per page. The gallery, the playground and every
 * `<spline-lab>` element share one memoised promise, so the module is fetched and compiled
 * once. URLs resolve relative to this file, so embeds work from any page location.
 */

const PACKAGE_URL = new URL("../pkg/splinelab.js", import.meta.url);

let loading = null;

/** Resolves to the initialised package namespace (`sl.BezierCurve`, `sl.bernstein`, …). */
export function loadWasm() {
  loading ??= (async () => {
    const module = await import(PACKAGE_URL.href);
    await module.default(); // wasm-bindgen init: fetches splinelab_bg.wasm next to splinelab.js
    return module;
  })().catch((err) => {
    loading = null; // a later call may retry (e.g. after `make build`)
    throw err;
  });
  return loading;
}
