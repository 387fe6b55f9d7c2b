/** The English strings of www/demos/parametrization.js (keys start with the demo's `strings` prefix "parametrization"). */
export const PARAMETRIZATION = {
  "parametrization.title": "parametrization",
};
