/**
 * Loads the splinelab wasm package once per page. The gallery, the playground and every
 * `<spline-lab>` element share one memoised promise, so the module is fetched and compiled
 * once. URLs resolve relative to this file, so embeds work from any page location.
 */

import { t } from "./strings.js";
import { errorText } from "./core-errors.js";

const PACKAGE_URL = new URL("../pkg/splinelab.js", import.meta.url);
/** The module itself: fetched and compiled (streaming) while its glue, PACKAGE_URL, loads. */
export const WASM_URL = new URL("../pkg/splinelab_bg.wasm", import.meta.url);

let loading = null;
/** The initialised package once `loadWasm` has resolved (for synchronous checks, see `loadedWasm`). */
let loaded = null;

/**
 * The smallest module using a SIMD128 instruction (`() -> v128`: `i32.const 0`,
 * `i8x16.splat`, `i8x16.popcnt`). The package is built with SIMD128 (.cargo/config.toml), which
 * browsers run since Chrome 91, Firefox 89 and Safari 16.4; an older one cannot compile it.
 */
const SIMD_PROBE = new Uint8Array([
  0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15,
  253, 98, 11,
]);

/** Set on the Error `loadWasm` rejects with when the browser has no WebAssembly SIMD. */
export const NO_SIMD = "no-simd";

/** Resolves to the initialised package namespace (`sl.BezierCurve`, `sl.bernstein`, …). */
export function loadWasm() {
  loading ??= (async () => {
    if (typeof WebAssembly !== "object" || !WebAssembly.validate(SIMD_PROBE)) {
      throw Object.assign(new Error(t("app.noSimd")), { code: NO_SIMD });
    }
    // The wasm compiles as it streams in (the server sends application/wasm), in parallel with
    // the glue's download; a page that preloaded it (boot.js) gets the preloaded response.
    // A host sending another type: compiled from the bytes instead.
    const compiled = WebAssembly.compileStreaming(fetch(WASM_URL)).catch(() =>
      fetch(WASM_URL)
        .then((r) => r.arrayBuffer())
        .then((bytes) => WebAssembly.compile(bytes)),
    );
    const module = await import(PACKAGE_URL.href);
    await module.default({ module_or_path: compiled }); // wasm-bindgen init with the compiled module
    loaded = module;
    return module;
  })().catch((err) => {
    loading = null; // a later call may retry (e.g. after `make build`)
    throw err;
  });
  return loading;
}

/**
 * The initialised package, or null before `loadWasm` has resolved. States are validated only
 * after it has (app.js, embed.js), so a field check may ask the core (lib/bspline.js `knotsField`).
 */
export function loadedWasm() {
  return loaded;
}

/** What to tell the reader when `loadWasm` failed with `err`. */
export function loadFailureMessage(err) {
  return err?.code === NO_SIMD
    ? err.message
    : t("app.wasmFailed", { message: err?.message ?? String(err) });
}

/**
 * A declarative demo's `ui.replace(next)` (demo.js: the model is built first), or, when the
 * core refuses `next`, its reason in the status line and nothing changed. Returns true when
 * replaced.
 */
export function replaceOrReport(ui, next) {
  try {
    ui.replace(next);
    return true;
  } catch (err) {
    ui.status(t("status.rejected", { message: errorText(err) }), "error");
    return false;
  }
}
