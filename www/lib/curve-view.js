/**
 * Drawing support for typed curves on a 2D figure (parametric-curve; a space curve is drawn by
 * the 3D figure, curve-space.js): points mapped by a linear map `m` (rows: the figure's x and
 * y), polylines clipped to a box in CSS px (a plot near a pole, a hodograph that runs off,
 * an osculating circle of a huge radius: exports stay within TeX's dimensions), robust bounds
 * (a pole's extremes left out) and nice scales. Nothing here computes the curve: the points are
 * the core's (`plot`, `sampleUniform`, `derivative`).
 */
import { clipSegment } from "./clip.js";
import { arrow } from "./draw.js";
import { localeDecimal } from "./format.js";

/** Robust bounds: the quantiles kept when the extremes run far off (a pole). */
const ROBUST_QUANTILE = 0.1;
const ROBUST_SPREAD = 3;
/** Drawing is clipped to the canvas widened by this many CSS px. */
export const CLIP_MARGIN_PX = 40;

/** The figure's x and y of a model point (x, y, z) under the map `m` (3 × 3, row-major). */
export const pu = (m, x, y, z) => m[0] * x + m[1] * y + m[2] * z;
export const pw = (m, x, y, z) => m[3] * x + m[4] * y + m[5] * z;
/** The third coordinate of a point of `dim` numbers at `k` (0 for a plane curve). */
export const zAt = (flat, k, dim) => (dim === 3 ? flat[k + 2] : 0);

/**
 * [lo, hi] of the finite values, or of their central part when the extremes run far beyond it
 * (a pole): the figure fits what can be seen. Drawing support.
 */
export function robustRange(values) {
  if (values.length === 0) return [-1, 1];
  values.sort((p, q) => p - q);
  const n = values.length;
  const lo = values[Math.floor(ROBUST_QUANTILE * (n - 1))];
  const hi = values[Math.ceil((1 - ROBUST_QUANTILE) * (n - 1))];
  const min = values[0];
  const max = values[n - 1];
  if (max - min <= ROBUST_SPREAD * (hi - lo) + 1e-12) return [min, max];
  const pad = 0.1 * (hi - lo);
  return [lo - pad, hi + pad];
}

/** The largest of 1, 2, 5 × 10^k not above x: the scale of the arrows and the hodograph. */
export function niceScale(x) {
  if (!(x > 0) || !Number.isFinite(x)) return 1;
  const k = Math.floor(Math.log10(x));
  const m = x / 10 ** k;
  return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * 10 ** k;
}

/** "1/2", "1/20", "2", "0.5" — a scale as text (fractions for the small ones). */
export function scaleText(s) {
  const inverse = Math.round(1 / s);
  if (s < 1 && Math.abs(inverse * s - 1) < 1e-9) return `1/${inverse}`;
  return localeDecimal(String(s));
}

/** Scratch for clipping (drawing allocates nothing per frame). */
const clipOut = new Float64Array(4);
const pen = {
  has: false,
  down: false,
  x: 0,
  y: 0,
  x0: 0,
  y0: 0,
  x1: 0,
  y1: 0,
  maxLength: Infinity,
};

/** Starts a polyline clipped to the screen box [x0, x1] × [y0, y1] (CSS px). */
export function penStart(x0, y0, x1, y1, maxLength = Infinity) {
  pen.has = false;
  pen.down = false;
  pen.x0 = x0;
  pen.y0 = y0;
  pen.x1 = x1;
  pen.y1 = y1;
  pen.maxLength = maxLength;
}

/** The next vertex (CSS px) of the clipped polyline; a non-finite one breaks it. */
export function penTo(r, x, y) {
  if (!(Number.isFinite(x) && Number.isFinite(y))) {
    pen.has = false;
    pen.down = false;
    return;
  }
  if (pen.has && Math.hypot(x - pen.x, y - pen.y) <= pen.maxLength) {
    if (clipSegment(pen.x, pen.y, x, y, pen.x0, pen.y0, pen.x1, pen.y1, clipOut)) {
      if (!pen.down || clipOut[0] !== pen.x || clipOut[1] !== pen.y)
        r.moveTo(clipOut[0], clipOut[1]);
      r.lineTo(clipOut[2], clipOut[3]);
      pen.down = clipOut[2] === x && clipOut[3] === y;
    } else {
      pen.down = false;
    }
  } else {
    pen.down = false;
  }
  pen.has = true;
  pen.x = x;
  pen.y = y;
}

/** The canvas widened by CLIP_MARGIN_PX, as the pen's box. */
export function penOnCanvas(r, v) {
  const margin = CLIP_MARGIN_PX * r.scale;
  penStart(-margin, -margin, r.width + margin, r.height + margin);
}

/** A flat list of points of `dim` numbers (runs split by NaN), projected, as a clipped path. */
export function flatRunsPath(r, v, flat, dim, m, ox = 0, oy = 0, scale = 1) {
  for (let k = 0; k + dim <= flat.length; k += dim) {
    const x = scale * flat[k];
    const y = scale * flat[k + 1];
    const z = scale * zAt(flat, k, dim);
    penTo(r, v.sx(ox + pu(m, x, y, z)), v.sy(oy + pw(m, x, y, z)));
  }
}

/** An arrow from (x0, y0) to (x1, y1) CSS px; beyond the canvas only its visible shaft. */
export function clippedArrow(r, v, x0, y0, x1, y1, style) {
  const margin = CLIP_MARGIN_PX * r.scale;
  const inside = (x, y) =>
    x >= -margin && x <= r.width + margin && y >= -margin && y <= r.height + margin;
  if (inside(x0, y0) && inside(x1, y1)) {
    arrow(r, x0, y0, x1, y1, style);
    return true;
  }
  if (clipSegment(x0, y0, x1, y1, -margin, -margin, r.width + margin, r.height + margin, clipOut)) {
    r.beginPath();
    r.moveTo(clipOut[0], clipOut[1]);
    r.lineTo(clipOut[2], clipOut[3]);
    r.paint(style);
  }
  return false;
}

/** [[first t, last t], …] of the runs of a plot's parameters (NaN between runs). */
export function plotRuns(ts) {
  const runs = [];
  let first = null;
  let last = null;
  for (const u of ts) {
    if (Number.isNaN(u)) {
      if (first !== null) runs.push([first, last]);
      first = null;
      continue;
    }
    first ??= u;
    last = u;
  }
  if (first !== null) runs.push([first, last]);
  return runs.map(([a, b]) => [Number(a.toFixed(6)), Number(b.toFixed(6))]);
}
