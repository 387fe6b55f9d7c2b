/**
 * A label for a point lying on a leg P_{i−1}P_i of a control polygon (a point made by knot
 * insertion, Q_i = (1 − α_i) P_{i−1} + α_i P_i): placed along the leg's normal n (canvas px) on
 * the side away from the polygon's centroid c, i.e. the sign of (x − c)·n, so it stays off both
 * the leg and the inside of the polygon. A degenerate leg (shorter than 1 px) labels upwards.
 */
import { placeLabel } from "./handles.js";

/** Labels (x, y) with `text` beside leg i of the flat polygon `P` (`[x0, y0, x1, y1, …]`). */
export function labelOffLeg(r, v, P, text, x, y, i, style, radius) {
  let nx = v.sy(P[2 * i + 1]) - v.sy(P[2 * i - 1]);
  let ny = v.sx(P[2 * i]) - v.sx(P[2 * i - 2]);
  const length = Math.hypot(nx, ny);
  if (length < 1) {
    nx = 0;
    ny = -1;
  } else {
    nx /= length;
    ny /= length;
  }
  let cx = 0;
  let cy = 0;
  const count = P.length / 2;
  for (let j = 0; j < count; j++) {
    cx += v.sx(P[2 * j]);
    cy += v.sy(P[2 * j + 1]);
  }
  const away = (x - cx / count) * nx + (y - cy / count) * ny < 0 ? -1 : 1;
  placeLabel(r, text, x, y, away * nx, away * ny, radius, style);
}
