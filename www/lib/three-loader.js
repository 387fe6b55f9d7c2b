/**
 * three.js for the 3D figures, loaded lazily from the vendored copy (`www/vendor/three/`, made by
 * `scripts/vendor.mjs`; never a CDN). Only a 3D figure asks for it (a demo that declares
 * `figure3d`, or one with both figures showing a state whose `dimension` is 3), so a 2D demo
 * page or a 2D `<spline-lab>` embed fetches no three.js file.
 *
 * `prepareFigure(demo)` is what a host (the playground page, `<spline-lab>`, the gallery
 * thumbnails, the tests) awaits before `mountDemo`: the mount itself stays synchronous, and a
 * 3D figure finds the rendering worker (gl-client.js) ready — the page itself then loads no
 * three.js: the worker has its own — or where no worker can run, three.js and the main thread's
 * shared WebGL renderer (shared-gl.js). A PNG export or thumbnail of a 3D figure draws on the
 * main thread and loads three.js first (`exports`, View3D `prepareExport`).
 */

import { sharedRendererMade, warmSharedRenderer } from "./shared-gl.js";
import { warmPipelines } from "./gl-warmup.js";
import { glWorkerAlive, glWorkerReady } from "./gl-client.js";

let loading = null;
let loaded = null;

/** A memoised promise of `{ THREE }` (a failed load is retried on the next call). */
export function loadThree() {
  loading ??= import("../vendor/three/three.module.js").then(
    (THREE) => {
      loaded = { THREE };
      return loaded;
    },
    (err) => {
      loading = null;
      throw err;
    },
  );
  return loading;
}

/** `{ THREE }` once loaded, else null. */
export function loadedThree() {
  return loaded;
}

/**
 * The kind of figure `state` is shown in: 3 (`figure3d`, View3D) or 2 (`figure`, View). A demo
 * that has both decides per state (`dimension(state)` → 2 | 3: a typed curve with a z(t)); a
 * missing field takes the default's, a state it cannot read is shown in 2D. Any other demo has
 * the one kind it declares.
 */
export function figureDimension(demo, state) {
  if (typeof demo?.dimension !== "function") return demo?.figure3d ? 3 : 2;
  try {
    return demo.dimension({ ...demo.defaultState, ...state }) === 3 ? 3 : 2;
  } catch {
    return 2;
  }
}

/** True when a 3D figure can be made now: the rendering worker runs, or three.js is loaded. */
export function figure3dReady() {
  return glWorkerAlive() || loaded !== null;
}

/**
 * Resolves when `demo` can be mounted with `state` (default: its starting state; a link's state
 * may be passed unchecked): at once for a 2D figure; for a 3D one, once the rendering worker is
 * ready, else after three.js and the main thread's renderer. With `exports`, three.js is loaded
 * in any case (a thumbnail or poster drawn at once after the mount).
 */
export async function prepareFigure(demo, state = demo?.defaultState, { exports = false } = {}) {
  if (figureDimension(demo, state) !== 3) return null;
  const three = exports ? loadThree() : null;
  if (await glWorkerReady()) return three && (await three);
  await loadThree();
  if (!sharedRendererMade()) {
    // The page's first 3D figure: the WebGL renderer in a task of its own, the GPU's first use
    // of the figures' programs while the main thread is free (gl-warmup.js), and the mount
    // after them (shorter tasks).
    await nextTask();
    if (warmSharedRenderer()) await nextTask();
  }
  await warmPipelines();
  return loaded;
}

const nextTask = () => new Promise((resolve) => setTimeout(resolve));
