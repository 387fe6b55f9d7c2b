/**
 * What a typed curve's figure needs that does not depend on t (parametric-curve): the box of
 * the curve (its visible part near a pole; in space its [x, y, z] box too), the hodograph's
 * samples (the core's P′ at uniform t), its scale λ (a nice number) and its box around the
 * origin O, and where O goes beside the curve. A plane figure shows (x, y): a space curve seen
 * in 2D (while three.js loads) shows its shadow on the xy plane. Drawing support: every point is
 * the core's (`sampleUniform`, `derivativeInto`).
 */
import { niceScale, robustRange, scaleText, zAt } from "./curve-view.js";
import { t } from "./strings.js";

/** Samples for the figure's bounds and the hodograph (one derivative per sample and change). */
const BOUNDS_SAMPLES = 512;
const HODOGRAPH_SAMPLES = 256;
/** The hodograph's size as a fraction of the curve's (the scale λ is the nice number below). */
const HODOGRAPH_FRACTION = 0.35;
/** The hodograph's box reaches at most this many curve sizes from O. */
const HODOGRAPH_REACH = 0.6;
/** The speed the scale is made for: this quantile of |P′| over the samples. */
const SPEED_QUANTILE = 0.5;
/** Gap between the curve's box and the hodograph's, as a fraction of the curve's size. */
const HODOGRAPH_GAP = 0.3;
/** Padding of the hodograph's box, as a fraction of its size. */
const HODOGRAPH_PAD = 0.12;

/** The finite points of a flat list (`dim` numbers each) as coordinate lists `[xs, ys, zs]`. */
function coordinates(flat, dim, scale = 1) {
  const out = [[], [], []];
  for (let k = 0; k + dim <= flat.length; k += dim) {
    const x = scale * flat[k];
    const y = scale * flat[k + 1];
    const z = scale * zAt(flat, k, dim);
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
    out[0].push(x);
    out[1].push(y);
    out[2].push(z);
  }
  return out;
}

/** The core's P′ at HODOGRAPH_SAMPLES uniform t (NaN where undefined) and the typical speed. */
function velocities(curve, [a, b]) {
  const dim = curve.dim;
  const hodograph = new Float64Array(HODOGRAPH_SAMPLES * dim);
  const speeds = [];
  const v = new Float64Array(dim);
  for (let k = 0; k < HODOGRAPH_SAMPLES; k++) {
    // The last sample exactly at b (a + (b − a) may round past it: outside the domain).
    const tk = k === HODOGRAPH_SAMPLES - 1 ? b : a + ((b - a) * k) / (HODOGRAPH_SAMPLES - 1);
    let ok = true;
    try {
      curve.derivativeInto(tk, 1, v);
    } catch {
      ok = false;
    }
    for (let c = 0; c < dim; c++) hodograph[k * dim + c] = ok ? v[c] : Number.NaN;
    const speed = ok ? Math.hypot(...v) : Number.NaN;
    if (Number.isFinite(speed)) speeds.push(speed);
  }
  speeds.sort((p, q) => p - q);
  const typical = speeds.length ? speeds[Math.floor(SPEED_QUANTILE * (speeds.length - 1))] : 1;
  return { hodograph, typical };
}

/**
 * `{ dim, box: [x0, y0, x1, y1], box3: [x0, y0, z0, x1, y1, z1], size, hodograph, lambda, hbox
 * (relative to O), scaleCaption, polynomial }` of `curve` on `domain`.
 */
export function wholeCurve(curve, domain, prefix) {
  const dim = curve.dim;
  const [xs, ys, zs] = coordinates(curve.sampleUniform(BOUNDS_SAMPLES), dim);
  const [x0, x1] = robustRange(xs);
  const [y0, y1] = robustRange(ys);
  const [z0, z1] = dim === 3 ? robustRange(zs) : [0, 0];
  const size = Math.max(x1 - x0, y1 - y0, z1 - z0, 1e-9);
  const { hodograph, typical } = velocities(curve, domain);
  const lambda = niceScale((HODOGRAPH_FRACTION * size) / (typical || 1));
  // The hodograph's box relative to O (O included), at most HODOGRAPH_REACH curve sizes from it
  // (the velocities near a pole run off).
  const [hx, hy] = coordinates(hodograph, dim, lambda);
  const reach = HODOGRAPH_REACH * size;
  const within = ([lo, hi]) => [
    Math.max(Math.min(lo, 0), -reach),
    Math.min(Math.max(hi, 0), reach),
  ];
  const [hx0, hx1] = within(robustRange(hx));
  const [hy0, hy1] = within(robustRange(hy));
  const pad = HODOGRAPH_PAD * Math.max(hx1 - hx0, hy1 - hy0, 1e-9);
  return {
    dim,
    box: [x0, y0, x1, y1],
    box3: [x0, y0, z0, x1, y1, z1],
    size,
    hodograph,
    lambda,
    hbox: [hx0 - pad, hy0 - pad, hx1 + pad, hy1 + pad],
    scaleCaption: t(`${prefix}.scaleCaption`, { scale: scaleText(lambda) }),
    polynomial: curve.isPolynomial(0),
  };
}

/** The hodograph's origin O beside the curve: right of its box, level with its middle. */
export function originBeside(whole) {
  const { box, hbox, size } = whole;
  const ox = box[2] + HODOGRAPH_GAP * size - hbox[0];
  const oy = (box[1] + box[3]) / 2 - (hbox[1] + hbox[3]) / 2;
  const round = (v) => Number(v.toPrecision(4));
  return [round(ox), round(oy)];
}

/** The figure's box: the curve's and the hodograph's around O (`[ox, oy]`). */
export function planeBounds(whole, [ox, oy]) {
  const { box, hbox } = whole;
  return [
    Math.min(box[0], ox + hbox[0]),
    Math.min(box[1], oy + hbox[1]),
    Math.max(box[2], ox + hbox[2]),
    Math.max(box[3], oy + hbox[3]),
  ];
}
