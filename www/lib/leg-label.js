/**
 * A label for a point lying on a leg P_{i−1}P_i of a control polygon (a point made by knot
 * insertion, Q_i = (1 − α_i) P_{i−1} + α_i P_i): placed along the leg's normal (canvas px) on
 * the side away from the polygon's centroid, so it stays off both the leg and the inside of the
 * polygon (handles.js `normalAwayFrom`; a degenerate leg labels above left).
 */
import { normalAwayFrom, placeLabel } from "./handles.js";

/** Scratch normal [nx, ny] (nothing is allocated while drawing). */
const normal = new Float64Array(2);

/** Labels (x, y) with `text` beside leg i of the flat polygon `P` (`[x0, y0, x1, y1, …]`). */
export function labelOffLeg(r, v, P, text, x, y, i, style, radius) {
  let cx = 0;
  let cy = 0;
  const count = P.length / 2;
  for (let j = 0; j < count; j++) {
    cx += v.sx(P[2 * j]);
    cy += v.sy(P[2 * j + 1]);
  }
  const ax = v.sx(P[2 * i - 2]);
  const ay = v.sy(P[2 * i - 1]);
  normalAwayFrom(ax, ay, v.sx(P[2 * i]), v.sy(P[2 * i + 1]), x, y, cx / count, cy / count, normal);
  placeLabel(r, text, x, y, normal[0], normal[1], radius, style);
}
