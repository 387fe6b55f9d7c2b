/**
 * A vector attached to a point and edited by dragging its tip (an end derivative C′(t₀) = D₀ of
 * an interpolant, a tangent): the state holds the vector `[dx, dy]` in a field of its own, the
 * handle sits at anchor + vector (world units, full length), and a move writes vector = tip −
 * anchor, so dragging the anchor carries the arrow along unchanged.
 *
 *   handles: { field: "points", extra: [vectorTip({ field: "startDerivative", label: "…",
 *     when: (s) => s.useStartDerivative, anchor: (s) => s.points[0] })] }
 *   …in draw: vectorArrow(r, v, s.points[0], s.startDerivative, style);
 */
import { arrow } from "./draw.js";

/** Decimals kept in a dragged vector (the tip is rounded to the view; this only drops float dust). */
const VECTOR_DECIMALS = 6;

/** Writes anchor + vector (world [x, y]) into `out`; returns `out`. */
export function tipOf(anchor, vector, out) {
  out[0] = anchor[0] + vector[0];
  out[1] = anchor[1] + vector[1];
  return out;
}

/**
 * An `extra` handle of a declarative demo's `figure.handles` (demo.js) on the tip of the vector
 * `state[field]` drawn from `anchor(state)` (a point of the state); `label` a strings.js key,
 * `when(state)` whether it is shown.
 */
export function vectorTip({ field, label, when, anchor }) {
  const factor = 10 ** VECTOR_DECIMALS;
  return {
    field,
    label,
    when,
    at: (s, out) => tipOf(anchor(s), s[field], out),
    place(s, x, y) {
      const [ax, ay] = anchor(s);
      s[field][0] = Math.round((x - ax) * factor) / factor;
      s[field][1] = Math.round((y - ay) * factor) / factor;
    },
  };
}

const scratch = new Float64Array(2);

/** Draws the arrow anchor → anchor + vector (world points) with `style`. Allocates nothing. */
export function vectorArrow(r, v, anchor, vector, style) {
  tipOf(anchor, vector, scratch);
  arrow(r, v.sx(anchor[0]), v.sy(anchor[1]), v.sx(scratch[0]), v.sy(scratch[1]), style);
}
