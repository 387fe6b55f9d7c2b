/** The English strings of www/demos/lagrange.js (keys start with the demo's `strings` prefix "lagrange"). */
export const LAGRANGE = {
  "lagrange.title": "lagrange",
};
