/**
 * Loads the splinelab wasm package once per page. The gallery, the playground and every
 * `<spline-lab>` element share one memoised promise, so the module is fetched and compiled
 * once. URLs resolve relative to this file, so embeds work from any page location.
 */

import { t } from "./strings.js";

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

/**
 * Builds a new wasm object with `build()` — first, before the old one is freed, since the core
 * may refuse the input. On a refusal (the constructor throws) the reason goes to the status line
 * (`ctx.status`) and the result is null; the demo then keeps its old object and state:
 *
 *   const built = buildOrReport(() => new sl.BSplineCurve(flatten(next.points), 2, p, knots), ctx);
 *   if (!built) return false;
 *   curve.free();
 *   curve = built;
 */
export function buildOrReport(build, ctx) {
  try {
    return build();
  } catch (err) {
    ctx.status(t("status.rejected", { message: err.message }), "error");
    return null;
  }
}
