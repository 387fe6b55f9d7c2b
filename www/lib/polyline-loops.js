/**
 * Drawing support, not a curve algorithm: where the core's samples of one stretch of a curve
 * cross themselves — a loop inside a segment (uniform Catmull–Rom between unevenly spaced
 * points). `stretchCrossing(flat, from, to, out)` looks at the polyline through samples
 * `from … to − 1` of a flat `[x0, y0, x1, y1, …]` array and writes the first crossing of two
 * legs that do not share a vertex into `out` (`[x, y]`), returning true, or returns false.
 * O(m²) in the stretch's sample count m (kept small, e.g. 64 per segment).
 */

/** Whether leg (a, b) and leg (c, d) cross properly; the point into `out`. */
function legsCross(f, a, b, c, d, out) {
  const ax = f[2 * a];
  const ay = f[2 * a + 1];
  const rx = f[2 * b] - ax;
  const ry = f[2 * b + 1] - ay;
  const cx = f[2 * c];
  const cy = f[2 * c + 1];
  const sx = f[2 * d] - cx;
  const sy = f[2 * d + 1] - cy;
  const denominator = rx * sy - ry * sx;
  if (denominator === 0) return false;
  const u = ((cx - ax) * sy - (cy - ay) * sx) / denominator;
  const v = ((cx - ax) * ry - (cy - ay) * rx) / denominator;
  if (u <= 0 || u >= 1 || v <= 0 || v >= 1) return false;
  out[0] = ax + u * rx;
  out[1] = ay + u * ry;
  return true;
}

/** The first self-crossing of the polyline through samples from … to − 1 (see the module doc). */
export function stretchCrossing(flat, from, to, out) {
  for (let a = from; a < to - 1; a++) {
    for (let c = a + 2; c < to - 1; c++) {
      if (legsCross(flat, a, a + 1, c, c + 1, out)) return true;
    }
  }
  return false;
}
