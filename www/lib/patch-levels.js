/**
 * Drawing support for the surface demos' constructions on the 2D layer of a 3D figure
 * (view3d.js): a de Casteljau triangle whose points are flat xyz (what `BezierSurface.deCasteljau`
 * returns, levels concatenated: level 0 with n + 1 points, level r with n + 1 − r, the apex
 * last), and coloured outlines of sub-patches. Nothing here computes geometry: points are
 * projected with `view.project` and painted.
 */
import { levelStart } from "./triangle.js";

/** Points of a de Casteljau triangle of degree n: (n + 1)(n + 2) / 2. */
export const trianglePoints = (n) => ((n + 1) * (n + 2)) / 2;

/** Points of levels 0 … `upTo` of a triangle of degree n (the control points included). */
export function pointsUpToLevel(n, upTo) {
  let count = 0;
  for (let level = 0; level <= Math.min(upTo, n); level++) count += n + 1 - level;
  return count;
}

const p = new Float64Array(3);

/**
 * Draws levels 1 … min(`upTo`, n) of the triangle of degree n that starts at point `offset` of
 * `flat` (xyz): each level a polyline in `theme.levelStroke[level − 1]` with its points in
 * `theme.levelPoint[level − 1]` (the 2D de Casteljau demo's colours). Returns the number of
 * points drawn.
 */
export function drawTriangle3(r, view, flat, offset, n, upTo) {
  const theme = r.theme;
  let drawn = 0;
  for (let level = 1; level <= Math.min(upTo, n); level++) {
    const start = offset + levelStart(n, level);
    const count = n + 1 - level;
    const colour = (level - 1) % theme.levelStroke.length;
    if (count > 1) {
      r.beginPath();
      for (let j = 0; j < count; j++) {
        const k = 3 * (start + j);
        view.project(flat[k], flat[k + 1], flat[k + 2], p);
        if (j === 0) r.moveTo(p[0], p[1]);
        else r.lineTo(p[0], p[1]);
      }
      r.paint(theme.levelStroke[colour]);
    }
    for (let j = 0; j < count; j++) {
      const k = 3 * (start + j);
      view.project(flat[k], flat[k + 1], flat[k + 2], p);
      r.point(p[0], p[1], theme.levelPoint[colour]);
      drawn += 1;
    }
  }
  return drawn;
}

/** The apex (the last point) of the triangle of degree n starting at point `offset`, as xyz. */
export function apexOf(flat, offset, n, out) {
  const k = 3 * (offset + trianglePoints(n) - 1);
  out[0] = flat[k];
  out[1] = flat[k + 1];
  out[2] = flat[k + 2];
  return out;
}

/** The polyline through the given points of `flat` (xyz), by point index `at(j)`, j < count. */
export function indexedPath3(r, view, flat, count, at) {
  r.beginPath();
  for (let j = 0; j < count; j++) {
    const k = 3 * at(j);
    view.project(flat[k], flat[k + 1], flat[k + 2], p);
    if (j === 0) r.moveTo(p[0], p[1]);
    else r.lineTo(p[0], p[1]);
  }
}
