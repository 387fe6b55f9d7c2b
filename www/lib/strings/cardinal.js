/** The English strings of www/demos/cardinal.js (keys start with the demo's `strings` prefix "cardinal"). */
export const CARDINAL = {
  "cardinal.title": "cardinal",
};
