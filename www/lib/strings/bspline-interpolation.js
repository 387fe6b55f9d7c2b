/** The English strings of www/demos/bspline-interpolation.js (keys start with the demo's `strings` prefix "bsplineInterpolation"). */
export const BSPLINE_INTERPOLATION = {
  "bsplineInterpolation.title": "bsplineInterpolation",
};
