/** The English strings of www/demos/cubic-spline.js (keys start with the demo's `strings` prefix "cubicSpline"). */
export const CUBIC_SPLINE = {
  "cubicSpline.title": "cubicSpline",
};
