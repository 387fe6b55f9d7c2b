/** The English strings of www/demos/interpolate-approximate.js (keys start with the demo's `strings` prefix "interpolateApproximate"). */
export const INTERPOLATE_APPROXIMATE = {
  "interpolateApproximate.title": "interpolateApproximate",
};
