/** The English strings of www/demos/hermite.js (keys start with the demo's `strings` prefix "hermite"). */
export const HERMITE = {
  "hermite.title": "hermite",
};
