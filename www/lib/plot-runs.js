/**
 * Drawing support for curves the core plots in runs (`plot(tolerance, box)` of a typed curve:
 * runs separated by a NaN vertex where the curve jumps, has a pole or is undefined): the box a
 * figure fits around finite samples with a pole's far values left out, the runs as one path, and
 * a vertex to name a curve at. Not a curve algorithm: the vertices are the core's.
 */
import { placeLabel } from "./handles.js";

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

/** The core's plot of every curve of `parts` within `tolerance` (world units) inside `box`. */
export function plotParts(parts, tolerance, box) {
  const plots = parts.map((part) => part.plot(tolerance, box));
  return { points: plots.map((p) => p.points), complete: plots.every((p) => p.complete) };
}

/** `box` [x0, y0, x1, y1] grown by `margin` times its size on every side. */
export function grownBox(box, margin) {
  const w = box[2] - box[0];
  const h = box[3] - box[1];
  return [box[0] - margin * w, box[1] - margin * h, box[2] + margin * w, box[3] + margin * h];
}

/** The chord error a plot made for the window shown keeps, in CSS px. */
const TOLERANCE_PX = 0.25;
/** A plot is made again when its chord error exceeds this many CSS px (zoomed in). */
const COARSE_PX = 1;
/** The window grown by this much (its size per side) is the new plot's box. */
const WINDOW_MARGIN = 1;

/**
 * Keeps `shape` (`{ tolerance, plotBox, points, complete }`, `points` one flat run list per
 * curve of `parts`) fine enough for `view`'s window: when a chord may stray more than COARSE_PX
 * (zoomed in) or the window reaches beyond the plotted box (zoomed out, panned far), the curves
 * are plotted again for this window, in place. Run before a frame: rare (a zoom step), never
 * per frame of a small pan.
 */
export function refineForWindow(view, parts, shape) {
  const win = view.getWindow();
  const perPx = 1 / view.scale;
  const box = shape.plotBox;
  const inside = win[0] >= box[0] && win[1] >= box[1] && win[2] <= box[2] && win[3] <= box[3];
  if (inside && shape.tolerance <= COARSE_PX * perPx) return;
  shape.tolerance = TOLERANCE_PX * perPx;
  shape.plotBox = grownBox(win, WINDOW_MARGIN);
  Object.assign(shape, plotParts(parts, shape.tolerance, shape.plotBox));
}

/**
 * Names a plotted curve: `text` beside its middle vertex, `gap` CSS px out along the normal, on
 * the outer side of its bend (away from the midpoint of the chord between its first and last
 * finite vertex; a straight one on the left of its direction). Allocates nothing.
 */
export function nameRun(r, v, flat, text, style, gap) {
  const k = middleVertex(flat);
  if (k < 0) return;
  const n = flat.length / 2;
  let first = 0;
  while (!Number.isFinite(flat[2 * first] + flat[2 * first + 1])) first++;
  let last = n - 1;
  while (!Number.isFinite(flat[2 * last] + flat[2 * last + 1])) last--;
  const x = v.sx(flat[2 * k]);
  const y = v.sy(flat[2 * k + 1]);
  // The normal of the local direction (left of it), turned away from the chord's midpoint.
  let a = k > first && Number.isFinite(flat[2 * k - 2] + flat[2 * k - 1]) ? k - 1 : k;
  let b = k < last && Number.isFinite(flat[2 * k + 2] + flat[2 * k + 3]) ? k + 1 : k;
  if (a === b) [a, b] = [first, last];
  let nx = v.sy(flat[2 * b + 1]) - v.sy(flat[2 * a + 1]);
  let ny = -(v.sx(flat[2 * b]) - v.sx(flat[2 * a]));
  const length = Math.hypot(nx, ny);
  if (!(length > 0)) {
    placeLabel(r, text, x, y, -Math.SQRT1_2, -Math.SQRT1_2, gap, style);
    return;
  }
  nx /= length;
  ny /= length;
  const mx = x - (v.sx(flat[2 * first]) + v.sx(flat[2 * last])) / 2;
  const my = y - (v.sy(flat[2 * first + 1]) + v.sy(flat[2 * last + 1])) / 2;
  const sign = nx * mx + ny * my < 0 ? -1 : 1;
  placeLabel(r, text, x, y, sign * nx, sign * ny, gap, style);
}
