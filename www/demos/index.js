/**
 * The demo registry: a small manifest of every demo, in gallery order. The gallery, the
 * playground, the `<spline-lab>` element and the browser tests all find demos here (see
 * lib/README.md for the module contract). Nothing here imports a demo module: `loadDemo(id)`
 * fetches one when it is shown, so an embed of one demo loads only that demo.
 *
 * Each entry: `id` (the URL id and the module's file name), `section` (syllabus section, the
 * gallery grouping), `strings` (the prefix of the demo's keys in lib/strings.js: the gallery
 * shows `t(`${strings}.title`)` and `.summary` without loading the module), `tall` (the demo
 * makes its figure `.sl-figure-tall`: the poster's box, before the module is loaded, has the
 * live figure's size; scripts/posters.mjs checks it) and `load()` (the module's dynamic import). To add a demo: write `www/demos/<id>.js` and add its entry below;
 * the browser tests check that the entry agrees with the module's own `id`, `section` and
 * `strings`.
 */
import { t } from "../lib/strings.js";

/** All demos, in the order the gallery shows them within their section. */
export const demos = Object.freeze(
  [
    // Section 1 (typed parametric curves): parametric-curve.
    {
      id: "parametric-curve",
      section: 1,
      strings: "parametricCurve",
      load: () => import("./parametric-curve.js"),
    },
    {
      id: "de-casteljau",
      section: 2,
      strings: "deCasteljau",
      load: () => import("./de-casteljau.js"),
    },
    {
      id: "bernstein",
      tall: true,
      section: 2,
      strings: "bernstein",
      load: () => import("./bernstein.js"),
    },
    {
      id: "subdivision",
      section: 2,
      strings: "subdivision",
      load: () => import("./subdivision.js"),
    },
    { id: "flattening", section: 2, strings: "flattening", load: () => import("./flattening.js") },
    {
      id: "line-intersection",
      section: 2,
      strings: "lineIntersection",
      load: () => import("./line-intersection.js"),
    },
    { id: "joining", section: 2, strings: "joining", load: () => import("./joining.js") },
    {
      id: "bezier-properties",
      section: 2,
      strings: "bezierProperties",
      load: () => import("./bezier-properties.js"),
    },
    {
      id: "derivatives",
      section: 2,
      strings: "derivatives",
      load: () => import("./derivatives.js"),
    },
    {
      id: "bspline-basis",
      section: 3,
      strings: "bsplineBasis",
      load: () => import("./bspline-basis.js"),
    },
    { id: "de-boor", section: 3, strings: "deBoor", load: () => import("./de-boor.js") },
    {
      id: "knot-vectors",
      section: 3,
      strings: "knotVectors",
      load: () => import("./knot-vectors.js"),
    },
    {
      id: "local-control",
      section: 3,
      strings: "localControl",
      load: () => import("./local-control.js"),
    },
    {
      id: "knot-insertion",
      section: 3,
      strings: "knotInsertion",
      load: () => import("./knot-insertion.js"),
    },
    {
      id: "multiplicity",
      section: 3,
      strings: "multiplicity",
      load: () => import("./multiplicity.js"),
    },
    {
      id: "matrix-form",
      section: 3,
      strings: "matrixForm",
      load: () => import("./matrix-form.js"),
    },
    {
      id: "weights",
      tall: true,
      section: 4,
      strings: "weights",
      load: () => import("./weights.js"),
    },
    { id: "conics", section: 4, strings: "conics", load: () => import("./conics.js") },
    {
      id: "nurbs-circle",
      section: 4,
      strings: "nurbsCircle",
      load: () => import("./nurbs-circle.js"),
    },
    { id: "projective", section: 4, strings: "projective", load: () => import("./projective.js") },
    {
      id: "negative-weights",
      tall: true,
      section: 4,
      strings: "negativeWeights",
      load: () => import("./negative-weights.js"),
    },
    {
      id: "lagrange",
      tall: true,
      section: 5,
      strings: "lagrange",
      load: () => import("./lagrange.js"),
    },
    {
      id: "hermite",
      tall: true,
      section: 5,
      strings: "hermite",
      load: () => import("./hermite.js"),
    },
    { id: "cardinal", section: 5, strings: "cardinal", load: () => import("./cardinal.js") },
    {
      id: "cubic-spline",
      tall: true,
      section: 5,
      strings: "cubicSpline",
      load: () => import("./cubic-spline.js"),
    },
    {
      id: "parametrization",
      tall: true,
      section: 5,
      strings: "parametrization",
      load: () => import("./parametrization.js"),
    },
    {
      id: "bspline-interpolation",
      section: 5,
      strings: "bsplineInterpolation",
      load: () => import("./bspline-interpolation.js"),
    },
    {
      id: "interpolate-approximate",
      section: 5,
      strings: "interpolateApproximate",
      load: () => import("./interpolate-approximate.js"),
    },
    {
      id: "bezier-patch",
      section: 6,
      strings: "bezierPatch",
      load: () => import("./bezier-patch.js"),
    },
    {
      id: "patch-de-casteljau",
      section: 6,
      strings: "patchDeCasteljau",
      load: () => import("./patch-de-casteljau.js"),
    },
    {
      id: "patch-subdivision",
      section: 6,
      strings: "patchSubdivision",
      load: () => import("./patch-subdivision.js"),
    },
    {
      id: "nurbs-surface",
      section: 6,
      strings: "nurbsSurface",
      load: () => import("./nurbs-surface.js"),
    },
    {
      id: "surface-interpolation",
      section: 6,
      strings: "surfaceInterpolation",
      load: () => import("./surface-interpolation.js"),
    },
    {
      id: "surface-revolution",
      section: 6,
      strings: "surfaceRevolution",
      load: () => import("./surface-revolution.js"),
    },
    // Section 1 (the gallery groups by section, keeping this order within it): the typed
    // piecewise curve, after `parametric-curve`.
    { id: "piecewise", section: 1, strings: "piecewise", load: () => import("./piecewise.js") },
    // Section 7 (interactive design): draw a stroke, get the curve (issue 25).
    { id: "sketch", section: 7, strings: "sketch", load: () => import("./sketch.js") },
  ].map(Object.freeze),
);

/** The manifest entry of demo `id`, or undefined (no module is loaded). */
export function findDemo(id) {
  return demos.find((demo) => demo.id === id);
}

/** Promises of the modules asked for so far, by id (each module is imported once). */
const loading = new Map();

/**
 * The module of demo `id` (memoised: every caller gets the same promise). Rejects with an
 * `Error` for an id that is not in the manifest, or when the module fails to load; a failed
 * load is forgotten, so a later call tries again.
 */
export function loadDemo(id) {
  const entry = findDemo(id);
  if (!entry) return Promise.reject(new Error(t("error.unknownDemo", { id })));
  let promise = loading.get(id);
  if (!promise) {
    promise = entry.load();
    promise.catch(() => loading.delete(id));
    loading.set(id, promise);
  }
  return promise;
}
