/**
 * three.js for the 3D figures, loaded lazily from the vendored copy (`www/vendor/three/`, made by
 * `scripts/vendor.mjs`; never a CDN). Only a demo that declares `figure3d` asks for it, so a 2D
 * demo page or a 2D `<spline-lab>` embed fetches no three.js file.
 *
 * `prepareFigure(demo)` is what a host (the playground page, `<spline-lab>`, the gallery
 * thumbnails, the tests) awaits before `mountDemo`: the mount itself stays synchronous, and a
 * 3D figure finds three.js already there (`loadedThree()`).
 */

let loading = null;
let loaded = null;

/** A memoised promise of `{ THREE, OrbitControls }` (a failed load is retried on the next call). */
export function loadThree() {
  loading ??= Promise.all([
    import("../vendor/three/three.module.js"),
    import("../vendor/three/OrbitControls.js"),
  ]).then(
    ([THREE, controls]) => {
      loaded = { THREE, OrbitControls: controls.OrbitControls };
      return loaded;
    },
    (err) => {
      loading = null;
      throw err;
    },
  );
  return loading;
}

/** `{ THREE, OrbitControls }` once loaded, else null. */
export function loadedThree() {
  return loaded;
}

/** Resolves when `demo` can be mounted: at once for a 2D demo, after three.js for a 3D one. */
export function prepareFigure(demo) {
  return demo?.figure3d ? loadThree() : Promise.resolve(null);
}
