/**
 * Drawing support for curves the core plots in runs (`plot(tolerance, box)` of a typed curve:
 * runs separated by a NaN vertex where the curve jumps, has a pole or is undefined): the box a
 * figure fits around finite samples with a pole's far values left out, the runs as one path, and
 * a vertex to name a curve at. Not a curve algorithm: the vertices are the core's.
 */

/** A range wider than this many times the 5–95 % spread has a pole: the box keeps the spread. */
const POLE_SPREAD = 20;

/** The box of the finite samples (a pole's far values left out), never empty. */
export function boxOf(samples) {
  const xs = [];
  const ys = [];
  for (const flat of samples) {
    for (let k = 0; k + 1 < flat.length; k += 2) {
      if (Number.isFinite(flat[k]) && Number.isFinite(flat[k + 1])) {
        xs.push(flat[k]);
        ys.push(flat[k + 1]);
      }
    }
  }
  if (xs.length === 0) return [-1, -1, 1, 1];
  const range = (v) => {
    v.sort((a, b) => a - b);
    const lo = v[Math.floor(0.05 * (v.length - 1))];
    const hi = v[Math.ceil(0.95 * (v.length - 1))];
    const spread = hi - lo;
    return v[v.length - 1] - v[0] > POLE_SPREAD * spread && spread > 0
      ? [lo - spread, hi + spread]
      : [v[0], v[v.length - 1]];
  };
  let [x0, x1] = range(xs);
  let [y0, y1] = range(ys);
  const size = Math.max(x1 - x0, y1 - y0, 1e-9);
  if (x1 - x0 < 1e-3 * size || x1 === x0) [x0, x1] = [x0 - size / 2 || -1, x1 + size / 2 || 1];
  if (y1 - y0 < 1e-3 * size || y1 === y0) [y0, y1] = [y0 - size / 2 || -1, y1 + size / 2 || 1];
  return [x0, y0, x1, y1];
}

/** The runs of a flat polyline with NaN vertices between them, as one path. */
export function runsPath(r, v, flat) {
  r.beginPath();
  let open = false;
  for (let k = 0; k + 1 < flat.length; k += 2) {
    const x = flat[k];
    const y = flat[k + 1];
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      open = false;
      continue;
    }
    if (open) r.lineTo(v.sx(x), v.sy(y));
    else r.moveTo(v.sx(x), v.sy(y));
    open = true;
  }
}

/** A finite vertex near the middle of a flat polyline (a piece's name goes there), or -1. */
export function middleVertex(flat) {
  const n = flat.length / 2;
  for (let step = 0; step < n; step++) {
    for (const k of [Math.floor(n / 2) + step, Math.floor(n / 2) - step]) {
      if (k >= 0 && k < n && Number.isFinite(flat[2 * k]) && Number.isFinite(flat[2 * k + 1]))
        return k;
    }
  }
  return -1;
}
